//! Crossing the boundary: vectors and observations to and from NumPy, a config from a
//! file and keyword entries, and the library's errors as Python exceptions.

use eyehand::experiment::{Config, RunError, DEFAULT_CONFIG_NAME};
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

/// The config file named (or the shipped default) and the name it is reported under,
/// with `entries` (name = value) set on top; a bad file or entry is a `ValueError`.
pub fn load_config(
    file: Option<&Path>,
    entries: Option<&Bound<'_, PyDict>>,
) -> PyResult<(Config, String)> {
    let (mut config, name) = match file {
        Some(path) => (
            Config::from_file(path).map_err(value_error)?,
            path.display().to_string(),
        ),
        None => (Config::default_config(), DEFAULT_CONFIG_NAME.to_string()),
    };
    for (key, value) in entries.into_iter().flatten() {
        let key: String = key.extract()?;
        let text = value.str()?.to_string();
        config
            .set(&key, &text)
            .map_err(|e| PyValueError::new_err(format!("{key}={text}: {e}")))?;
    }
    Ok((config, name))
}

/// Sets one entry given as text (the `sim`, `camera`, `seed` arguments).
pub fn set_entry(config: &mut Config, name: &str, value: &str) -> PyResult<()> {
    config
        .set(name, value)
        .map_err(|e| PyValueError::new_err(format!("{name}={value}: {e}")))
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
