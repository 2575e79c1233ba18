//! `eyehand.patterns`: a trial's learning patterns as the built-in learners form them, for
//! learners written in Python.

use crate::convert::path_from;
use crate::named::{pattern_rows, INPUTS, TARGETS};
use eyehand::experiment::Config;
use numpy::{PyArray1, PyArray2, PyArrayMethods};
use pyo3::prelude::*;

/// Inputs (m, 5) and targets (m, 3) of a path's adjusted (lin5) learning patterns: every
/// pose pair whose move reaches `minimal_joint_move` degrees in some joint (default: the
/// config entry's declared default, as a run's). Inputs are in the query's order (cx, cy,
/// cz, θ2, θ3), so a regressor fitted on them answers queries; `eyehand.Patterns` gives
/// them in the boundaries' order.
#[pyfunction]
#[pyo3(signature = (path, minimal_joint_move = None))]
#[allow(clippy::type_complexity)]
pub fn patterns<'py>(
    py: Python<'py>,
    path: &Bound<'py, PyAny>,
    minimal_joint_move: Option<f64>,
) -> PyResult<(Bound<'py, PyArray2<f64>>, Bound<'py, PyArray2<f64>>)> {
    let path = path_from(path)?;
    let minimal_joint_move =
        minimal_joint_move.unwrap_or(Config::default_config().minimal_joint_move);
    let (five, targets) = pattern_rows(&path, minimal_joint_move);
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
