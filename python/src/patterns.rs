//! `eyehand.patterns`: a trial's learning patterns as the built-in learners form them, for
//! learners written in Python.

use crate::convert::path_from;
use eyehand::experiment::Config;
use eyehand::learn::{adjusted_pattern, pose_pairs};
use numpy::{PyArray1, PyArray2, PyArrayMethods};
use pyo3::prelude::*;

/// Inputs (m, 5) and targets (m, 3) of a path's adjusted (lin5) learning patterns: every
/// pose pair whose move reaches `minimal_joint_move` degrees in some joint (default: the
/// config entry's declared default, as a run's). Inputs are in the query's order (cx, cy,
/// cz, θ2, θ3), so a regressor fitted on them answers queries.
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
    let mut inputs = Vec::new();
    let mut targets = Vec::new();
    for (from, to) in pose_pairs(&path, minimal_joint_move) {
        let pattern = adjusted_pattern(from, to);
        let x = pattern.input;
        inputs.extend_from_slice(&[x[2], x[3], x[4], x[0], x[1]]);
        targets.extend(pattern.target.iter());
    }
    let count = targets.len() / 3;
    Ok((
        PyArray1::from_vec(py, inputs).reshape([count, 5])?,
        PyArray1::from_vec(py, targets).reshape([count, 3])?,
    ))
}
