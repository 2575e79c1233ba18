//! The Python extension `eyehand._eyehand`: the testbed, the built-in learners and runs,
//! on the same engine as the `eyehand` command line.

mod arm;
mod config_dict;
mod convert;
mod learner;
mod named;
mod patterns;
mod pool;
mod run;
mod testbed;
mod vec_testbed;
mod view;

use pyo3::prelude::*;

/// The module `eyehand._eyehand`.
#[pymodule]
fn _eyehand(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<testbed::Testbed>()?;
    m.add_class::<vec_testbed::VecTestbed>()?;
    m.add_class::<learner::BuiltinLearner>()?;
    m.add_class::<named::NamedQuery>()?;
    m.add_class::<named::Patterns>()?;
    m.add("INPUTS", named::INPUTS.to_vec())?;
    m.add("INPUT_UNITS", named::INPUT_UNITS.to_vec())?;
    m.add("TARGETS", named::TARGETS.to_vec())?;
    m.add_function(wrap_pyfunction!(run::run_py, m)?)?;
    m.add_function(wrap_pyfunction!(run::parse_event, m)?)?;
    m.add_function(wrap_pyfunction!(patterns::patterns, m)?)?;
    m.add("ENTRY_NAMES", eyehand::experiment::ENTRY_NAMES.to_vec())?;
    Ok(())
}
