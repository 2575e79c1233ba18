//! `eyehand._eyehand.run`: a whole run (every trial, event and data file) of a built-in
//! learner or a Python learner, with the GIL released while Rust works. Ctrl-C stops the run
//! after its current trial, as it does on the command line: the folder keeps a summary
//! marked interrupted, and `KeyboardInterrupt` is raised once the run has written it.

use crate::convert::{run_error, run_options, run_request, value_error};
use crate::learner::{ErrorSlot, PyLearner, SIGINT};
use eyehand::experiment::{
    run, run_learner_set_up, Event, RunError, RunOptions, RunRequest, RunResult,
};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::PyDict;
use std::path::PathBuf;
use std::sync::mpsc::{self, RecvTimeoutError};
use std::sync::Mutex;
use std::time::Duration;

/// How often the waiting thread lets Python run its signal handlers.
const SIGNAL_POLL: Duration = Duration::from_millis(50);

/// Runs a run and returns (its folder, summary.json's text, the summary as `eyehand run`
/// prints it). `learner` is a Python object
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
) -> PyResult<(String, String, String)> {
    let named = [
        ("method", method.map(str::to_string)),
        ("sim", sim.map(str::to_string)),
        ("camera", camera.map(str::to_string)),
        ("seed", seed.map(|s| s.to_string())),
        ("trials", trials.map(|t| t.to_string())),
    ];
    let request = run_request(config.as_deref(), entries, &named)?;
    if learner.is_some() && method.is_some() {
        return Err(PyValueError::new_err(
            "give a learner or a method, not both",
        ));
    }
    let events = events
        .iter()
        .map(|e| e.parse::<Event>().map_err(value_error))
        .collect::<PyResult<Vec<_>>>()?;
    let request = RunRequest {
        urdf,
        data,
        events,
        plot,
        ..request
    };
    let options = run_options(&request)?;
    let result = match learner {
        None => run_interruptible(py, &options)?.map_err(run_error)?,
        Some(object) => run_python_learner(py, object, &options)?,
    };
    let summary = serde_json::to_string(&result.summary).map_err(value_error)?;
    Ok((
        result.folder.display().to_string(),
        summary,
        result.summary.one_screen(),
    ))
}

/// A run with a Python learner, on this thread (a learner may hold objects that must
/// stay on it), set up with the run's resolved config before anything is written: its
/// exception, if it raised one, is raised again; Ctrl-C, met by the learner's calls, stops
/// the run after its trial and is raised once the run is written.
fn run_python_learner(
    py: Python<'_>,
    object: &Bound<'_, PyAny>,
    options: &RunOptions,
) -> PyResult<RunResult> {
    let (failure, interrupt) = (ErrorSlot::default(), ErrorSlot::default());
    let setup = py.detach(|| options.warned_setup()).map_err(run_error)?;
    let learner = PyLearner::new(object, failure.clone())?
        .configured(py, &setup.config)?
        .stopping(options.stop.clone(), interrupt.clone());
    let outcome = py.detach(|| run_learner_set_up(options, setup, Box::new(learner)));
    for slot in [failure, interrupt] {
        if let Some(error) = slot.lock().ok().and_then(|mut s| s.take()) {
            return Err(error);
        }
    }
    outcome.map_err(run_error)
}

/// Runs a built-in learner's run on a thread of its own while this one, without the GIL,
/// wakes every [`SIGNAL_POLL`] to let Python's signal handlers run. When one raises
/// (Ctrl-C's `KeyboardInterrupt`), the run is asked to stop after its current trial; once
/// it has finished writing, that exception is returned in place of the run's result.
fn run_interruptible(
    py: Python<'_>,
    options: &RunOptions,
) -> PyResult<Result<RunResult, RunError>> {
    let stop = options.stop.clone();
    std::thread::scope(|scope| {
        let (done, finished) = mpsc::channel();
        // Behind a lock so that the wait can leave this thread's GIL behind.
        let finished = Mutex::new(finished);
        let worker = scope.spawn(move || {
            let result = run(options);
            // The waiting thread may have left already; nothing to tell then.
            let _ = done.send(());
            result
        });
        let mut raised = None;
        let wait = || {
            finished
                .lock()
                .map_or(Err(RecvTimeoutError::Disconnected), |finished| {
                    finished.recv_timeout(SIGNAL_POLL)
                })
        };
        while py.detach(wait) == Err(RecvTimeoutError::Timeout) {
            if raised.is_none() {
                if let Err(error) = py.check_signals() {
                    stop.request(SIGINT);
                    raised = Some(error);
                }
            }
        }
        let result = py
            .detach(|| worker.join())
            .map_err(|_| pyo3::exceptions::PyRuntimeError::new_err("the run's thread panicked"))?;
        match raised {
            Some(error) => Err(error),
            None => Ok(result),
        }
    })
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
