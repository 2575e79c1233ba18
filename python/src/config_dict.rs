//! A run's config as Python sees it in a learner's `setup(config)`: a dict of every entry
//! by name, typed as Python values.

use eyehand::experiment::{declarations, Config, REPEATED_ENTRY_NAMES};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList, PyString, PyTuple};
use pyo3::IntoPyObjectExt;

/// `config` as a dict from entry name to value: an integer entry as `int`, a real one as
/// `float`, one of several numbers (`x,y,z`, …) as a tuple of them, a repeated entry
/// (`obstacle`) as a list of its values, anything else (choices, names, files) as `str`.
pub fn config_dict<'py>(py: Python<'py>, config: &Config) -> PyResult<Bound<'py, PyDict>> {
    let declared = declarations();
    let kind_of = |name: &str| {
        declared
            .iter()
            .find(|d| d.name == name)
            .map_or("", |d| d.kind)
    };
    let dict = PyDict::new(py);
    for name in REPEATED_ENTRY_NAMES {
        dict.set_item(name, PyList::empty(py))?;
    }
    for (name, text) in config.entries() {
        let value = typed_value(py, kind_of(name), &text)?;
        match dict.get_item(name)? {
            Some(list) if REPEATED_ENTRY_NAMES.contains(&name) => {
                list.cast::<PyList>()?.append(value)?
            }
            _ => dict.set_item(name, value)?,
        }
    }
    Ok(dict)
}

/// An entry's `text` as the Python value its `kind` says: `int` and `float` for the numeric
/// kinds, a tuple of floats for a list kind (`x,y,z`, …) whose items are all numbers, else
/// the text.
fn typed_value<'py>(py: Python<'py>, kind: &str, text: &str) -> PyResult<Bound<'py, PyAny>> {
    let as_text = || PyString::new(py, text).into_any();
    Ok(match kind {
        "integer" => text
            .parse::<i128>()
            .map_or_else(|_| Ok(as_text()), |v| v.into_bound_py_any(py))?,
        "real" => text
            .parse::<f64>()
            .map_or_else(|_| Ok(as_text()), |v| v.into_bound_py_any(py))?,
        list if list.contains(',') => {
            let numbers: Result<Vec<f64>, _> =
                text.split(',').map(|p| p.trim().parse::<f64>()).collect();
            match numbers {
                Ok(numbers) => PyTuple::new(py, numbers)?.into_any(),
                Err(_) => as_text(),
            }
        }
        _ => as_text(),
    })
}
