//! `eyehand.patterns`: a trial's learning patterns as the built-in learners form them, for
//! learners written in Python, and which `minimal_joint_move` picks them.

use crate::convert::{path_from, value_error};
use crate::named::{pattern_rows, INPUTS, TARGETS};
use eyehand::experiment::Config;
use numpy::{PyArray1, PyArray2, PyArrayMethods};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::PyDict;
use std::path::PathBuf;

/// Inputs (m, 5) and targets (m, 3) of a path's adjusted (lin5) learning patterns: every
/// pose pair whose move reaches `minimal_joint_move` degrees in some joint (default:
/// `config`'s — the dict a learner's `setup` gets, or a config file — else the entry's
/// declared default). Inputs are in the query's order (cx, cy, cz, θ2, θ3), so a regressor
/// fitted on them answers queries; `eyehand.Patterns` gives them in the boundaries' order.
#[pyfunction]
#[pyo3(signature = (path, minimal_joint_move = None, config = None))]
#[allow(clippy::type_complexity)]
pub fn patterns<'py>(
    py: Python<'py>,
    path: &Bound<'py, PyAny>,
    minimal_joint_move: Option<f64>,
    config: Option<&Bound<'py, PyAny>>,
) -> PyResult<(Bound<'py, PyArray2<f64>>, Bound<'py, PyArray2<f64>>)> {
    let path = path_from(path)?;
    let (five, targets) =
        pattern_rows(&path, self::minimal_joint_move(minimal_joint_move, config)?);
    let inputs: Vec<f64> = five
        .chunks_exact(INPUTS.len())
        .flat_map(|x| [x[2], x[3], x[4], x[0], x[1]])
        .collect();
    let count = targets.len() / TARGETS.len();
    Ok((
        PyArray1::from_vec(py, inputs).reshape([count, INPUTS.len()])?,
        PyArray1::from_vec(py, targets).reshape([count, TARGETS.len()])?,
    ))
}

/// The `minimal_joint_move` given, else `config`'s (a dict of entries or a config file),
/// else the entry's declared default.
pub fn minimal_joint_move(given: Option<f64>, config: Option<&Bound<'_, PyAny>>) -> PyResult<f64> {
    if let Some(value) = given {
        return Ok(value);
    }
    let Some(config) = config else {
        return Ok(Config::default_config().minimal_joint_move);
    };
    if let Ok(entries) = config.cast::<PyDict>() {
        return match entries.get_item("minimal_joint_move")? {
            Some(value) => value.extract(),
            None => Err(PyValueError::new_err(
                "the config dict has no entry minimal_joint_move",
            )),
        };
    }
    let file: PathBuf = config.extract().map_err(|_| {
        PyValueError::new_err("config is a dict of entries (as setup gets it) or a config file")
    })?;
    Ok(Config::from_file(&file)
        .map_err(value_error)?
        .minimal_joint_move)
}
