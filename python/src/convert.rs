//! Crossing the boundary: vectors and observations to and from NumPy, a run's request
//! from a config file and keyword entries, and the library's errors as Python exceptions.

use eyehand::experiment::{RequestError, RunError, RunOptions, RunRequest};
use eyehand::learn::{Observation, Query};
use nalgebra::Vector3;
use numpy::{PyArray1, PyArray2, PyArrayMethods, PyReadonlyArray1};
use pyo3::exceptions::{PyOSError, PyRuntimeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::PyDict;
use std::path::Path;

/// Columns of a path row: the reading, then the controlled joint angles.
pub const PATH_COLUMNS: usize = 6;

/// Three finite or non-finite numbers from a NumPy array or any sequence of three numbers.
pub fn vector3(value: &Bound<'_, PyAny>, what: &str) -> PyResult<Vector3<f64>> {
    if let Ok(array) = value.extract::<PyReadonlyArray1<'_, f64>>() {
        if let Ok(&[a, b, c]) = array.as_slice() {
            return Ok(Vector3::new(a, b, c));
        }
    }
    let numbers: Vec<f64> = value
        .extract()
        .map_err(|_| PyValueError::new_err(format!("{what} must be three numbers")))?;
    match numbers[..] {
        [a, b, c] => Ok(Vector3::new(a, b, c)),
        _ => Err(PyValueError::new_err(format!(
            "{what} must be three numbers, not {}",
            numbers.len()
        ))),
    }
}

/// A query as the learners' input vector (cx, cy, cz, θ2, θ3).
pub fn query_array<'py>(py: Python<'py>, query: &Query) -> Bound<'py, PyArray1<f64>> {
    let c = query.c;
    PyArray1::from_slice(py, &[c.x, c.y, c.z, query.theta2_deg, query.theta3_deg])
}

/// The query (cx, cy, cz, θ2, θ3) given as five numbers.
pub fn query_from(value: &Bound<'_, PyAny>) -> PyResult<Query> {
    let numbers: Vec<f64> = match value.extract::<PyReadonlyArray1<'_, f64>>() {
        Ok(array) => array
            .to_vec()
            .map_err(|e| PyValueError::new_err(e.to_string()))?,
        Err(_) => value.extract()?,
    };
    let [cx, cy, cz, theta2_deg, theta3_deg] = numbers[..] else {
        return Err(PyValueError::new_err(format!(
            "a query is five numbers (cx, cy, cz, θ2, θ3), not {}",
            numbers.len()
        )));
    };
    Ok(Query {
        c: Vector3::new(cx, cy, cz),
        theta2_deg,
        theta3_deg,
    })
}

/// A trial's poses as an (n, 6) array: cx, cy, cz, θ1, θ2, θ3 a row.
pub fn path_array<'py>(
    py: Python<'py>,
    path: &[Observation],
) -> PyResult<Bound<'py, PyArray2<f64>>> {
    let flat: Vec<f64> = path
        .iter()
        .flat_map(|o| o.c.iter().chain(o.theta_deg.iter()).copied())
        .collect();
    PyArray1::from_vec(py, flat).reshape([path.len(), PATH_COLUMNS])
}

/// The poses of an (n, 6) array (cx, cy, cz, θ1, θ2, θ3 a row).
pub fn path_from(value: &Bound<'_, PyAny>) -> PyResult<Vec<Observation>> {
    let rows: Vec<Vec<f64>> = value.extract()?;
    rows.iter()
        .map(|row| match row[..] {
            [cx, cy, cz, t1, t2, t3] => Ok(Observation {
                theta_deg: Vector3::new(t1, t2, t3),
                c: Vector3::new(cx, cy, cz),
            }),
            _ => Err(PyValueError::new_err(format!(
                "a path row is six numbers (cx, cy, cz, θ1, θ2, θ3), not {}",
                row.len()
            ))),
        })
        .collect()
}

/// A run as Python asks for it: the config file named (or the shipped default), then the
/// keyword `entries` (name = value) and the `named` arguments given (`sim`, `method`, …,
/// as text), applied together as the command line's `--set`s are.
pub fn run_request(
    file: Option<&Path>,
    entries: Option<&Bound<'_, PyDict>>,
    named: &[(&str, Option<String>)],
) -> PyResult<RunRequest> {
    let mut sets = Vec::new();
    for (key, value) in entries.into_iter().flatten() {
        sets.push((key.extract::<String>()?, value.str()?.to_string()));
    }
    let given = named
        .iter()
        .filter_map(|(name, value)| Some((name.to_string(), value.clone()?)));
    sets.extend(given);
    Ok(RunRequest {
        config: file.map(Path::to_path_buf),
        sets,
        ..RunRequest::default()
    })
}

/// The options of the run `request` asks for, its config checked once with every entry
/// in: a bad file, entry or pair of entries is a `ValueError` naming the file and line or
/// the entry.
pub fn run_options(request: &RunRequest) -> PyResult<RunOptions> {
    request.options().map_err(|error| match error {
        RequestError::Set { shown, kind } => value_error(format!("{shown}: {kind}")),
        RequestError::Combined { config, kind } => {
            value_error(format!("{config} with the keyword entries: {kind}"))
        }
        other => value_error(other),
    })
}

/// Any error whose message is the whole story, as a `ValueError`.
pub fn value_error(error: impl std::fmt::Display) -> PyErr {
    PyValueError::new_err(error.to_string())
}

/// A failed run as the matching Python exception: bad input as `ValueError`, files as
/// `OSError`, anything else as `RuntimeError`.
pub fn run_error(error: RunError) -> PyErr {
    match error {
        RunError::Urdf(_) | RunError::Event { .. } | RunError::LearnerName(_) => value_error(error),
        RunError::Folder(_) | RunError::Io(_) => PyOSError::new_err(error.to_string()),
        _ => PyRuntimeError::new_err(error.to_string()),
    }
}
