//! `eyehand._eyehand.run`: a whole run (every trial, event and data file) of a built-in
//! learner or a Python learner, with the GIL released while Rust works.

use crate::convert::{load_config, run_error, set_entry, value_error};
use crate::learner::{ErrorSlot, PyLearner};
use eyehand::experiment::{run, run_learner, Event, RunOptions, RunResult};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::PyDict;
use std::path::PathBuf;

/// Runs a run and returns (its folder, summary.json's text). `learner` is a Python object
/// with `propose` and `learn`; without it the config's (or `method`'s) built-in learner
/// runs. Keyword entries override the config's, as `--set` does.
#[pyfunction(name = "run")]
#[pyo3(signature = (learner = None, *, method = None, trials = None, config = None, data = PathBuf::from("data"), seed = None, sim = None, camera = None, urdf = None, events = Vec::new(), plot = false, **entries))]
#[allow(clippy::too_many_arguments)]
pub fn run_py(
    py: Python<'_>,
    learner: Option<&Bound<'_, PyAny>>,
    method: Option<&str>,
    trials: Option<usize>,
    config: Option<PathBuf>,
    data: PathBuf,
    seed: Option<u64>,
    sim: Option<&str>,
    camera: Option<&str>,
    urdf: Option<PathBuf>,
    events: Vec<String>,
    plot: bool,
    entries: Option<&Bound<'_, PyDict>>,
) -> PyResult<(String, String)> {
    let (mut config, config_name) = load_config(config.as_deref(), entries)?;
    let overrides = [
        ("method", method.map(str::to_string)),
        ("sim", sim.map(str::to_string)),
        ("camera", camera.map(str::to_string)),
        ("seed", seed.map(|s| s.to_string())),
        ("trials", trials.map(|t| t.to_string())),
    ];
    for (name, value) in overrides {
        if let Some(value) = value {
            set_entry(&mut config, name, &value)?;
        }
    }
    if learner.is_some() && method.is_some() {
        return Err(PyValueError::new_err(
            "give a learner or a method, not both",
        ));
    }
    let events = events
        .iter()
        .map(|e| e.parse::<Event>().map_err(value_error))
        .collect::<PyResult<Vec<_>>>()?;
    let options = RunOptions {
        config_name,
        urdf,
        events,
        plot,
        ..RunOptions::new(config, data)
    };
    let result = match learner {
        None => py.detach(|| run(&options)).map_err(run_error)?,
        Some(object) => run_python_learner(py, object, &options)?,
    };
    let summary = serde_json::to_string(&result.summary).map_err(value_error)?;
    Ok((result.folder.display().to_string(), summary))
}

/// A run with a Python learner; its exception, if it raised one, is raised again.
fn run_python_learner(
    py: Python<'_>,
    object: &Bound<'_, PyAny>,
    options: &RunOptions,
) -> PyResult<RunResult> {
    let slot = ErrorSlot::default();
    let learner = PyLearner::new(object, slot.clone())?;
    let outcome = py.detach(|| run_learner(options, Box::new(learner)));
    if let Some(error) = slot.lock().ok().and_then(|mut s| s.take()) {
        return Err(error);
    }
    outcome.map_err(run_error)
}

/// An event's text (`rotate:TRIAL:DEG`, `elongate:TRIAL:LINK:CM`) as (kind, trial, link,
/// amount): ("rotate", trial, 0, degrees) or ("elongate", trial, link, cm); a malformed
/// one is a `ValueError` with the command line's message.
#[pyfunction]
pub fn parse_event(text: &str) -> PyResult<(&'static str, usize, usize, f64)> {
    Ok(match text.parse::<Event>().map_err(value_error)? {
        Event::Rotate { trial, degrees } => ("rotate", trial, 0, degrees),
        Event::Elongate { trial, link, cm } => ("elongate", trial, link, cm),
    })
}
