//! Learners across the boundary: a Python object with `propose` and `learn` as a Rust
//! [`Learner`], and the built-in learners as the Python class `eyehand.Learner`.

use crate::config_dict::config_dict;
use crate::convert::{
    path_array, path_from, query_array, query_from, run_options, run_request, value_error, vector3,
};
use crate::named::{NamedQuery, Patterns};
use eyehand::experiment::{Config, RunRequest, StopRequest};
use eyehand::learn::{LearnError, Learner, LearnerStats, Observation, Query};
use nalgebra::Vector3;
use numpy::PyArray1;
use pyo3::exceptions::{PyKeyboardInterrupt, PyValueError};
use pyo3::prelude::*;
use pyo3::types::PyDict;
use std::path::PathBuf;
use std::sync::{Arc, Mutex};

/// The first error a Python learner raised, kept for the caller to raise again.
pub type ErrorSlot = Arc<Mutex<Option<PyErr>>>;

/// The signal a stop from Python is filed under: SIGINT, as Ctrl-C.
pub const SIGINT: i32 = 2;

/// A Python object with `propose(query) -> (3,)` and `learn(path)`, driven by the Rust
/// trial loop. The first exception (or non-finite move) is kept in its slot; from then on
/// it proposes no move and its `learn` fails, which stops the run.
///
/// What its calls are given is its [`Api`]; a `size()` it defines is its `nodes` figure,
/// and a `setup(config)` it defines is called by [`PyLearner::configured`].
///
/// Given a run's stop request ([`PyLearner::stopping`]), it also lets Python's signal
/// handlers run before each call: Ctrl-C's `KeyboardInterrupt`, raised there or inside the
/// learner's own code, asks the run to stop after the current trial (the call it broke
/// proposes no move or learns nothing) and is kept in the interrupt slot, not as a failure.
#[derive(Debug)]
pub struct PyLearner {
    object: Py<PyAny>,
    name: String,
    api: Api,
    has_size: bool,
    minimal_joint_move: f64,
    error: ErrorSlot,
    stop: Option<(StopRequest, ErrorSlot)>,
}

/// What a Python learner's calls are given, by its `eyehand_api` attribute.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Api {
    /// No attribute, or `eyehand_api = 1`: `propose` gets the (5,) array (cx, cy, cz, θ2,
    /// θ3), `learn` the trial's (n, 6) path.
    Arrays,
    /// `eyehand_api = 2`: `propose` gets an `eyehand.Query`, `learn` an `eyehand.Patterns`.
    Named,
}

impl Api {
    /// The API `object` asks for; an `eyehand_api` other than 1 or 2 is a `ValueError`.
    fn of(object: &Bound<'_, PyAny>) -> PyResult<Api> {
        if !object.hasattr("eyehand_api")? {
            return Ok(Api::Arrays);
        }
        let asked = object.getattr("eyehand_api")?;
        match asked.extract::<i64>() {
            Ok(1) => Ok(Api::Arrays),
            Ok(2) => Ok(Api::Named),
            _ => Err(PyValueError::new_err(format!(
                "eyehand_api is 1 (arrays) or 2 (eyehand.Query and eyehand.Patterns), not {}",
                asked.repr()?
            ))),
        }
    }
}

impl PyLearner {
    /// Wraps `object`; its runs are filed under its `name` attribute, or its class name.
    /// Its patterns take the declared default `minimal_joint_move` until
    /// [`configured`](PyLearner::configured).
    pub fn new(object: &Bound<'_, PyAny>, error: ErrorSlot) -> PyResult<PyLearner> {
        let name = match object.getattr("name") {
            Ok(name) if name.is_instance_of::<pyo3::types::PyString>() => name.extract()?,
            _ => object.get_type().name()?.to_string(),
        };
        Ok(PyLearner {
            object: object.clone().unbind(),
            name,
            api: Api::of(object)?,
            has_size: object.hasattr("size")?,
            minimal_joint_move: Config::default_config().minimal_joint_move,
            error,
            stop: None,
        })
    }

    /// The learner set up for a run of `config` (the run's, resolved): its `setup(config)`
    /// called, if it has one, with the entries as a dict; its patterns formed with the
    /// config's `minimal_joint_move`.
    pub fn configured(self, py: Python<'_>, config: &Config) -> PyResult<PyLearner> {
        let object = self.object.bind(py);
        if object.hasattr("setup")? {
            object.call_method1("setup", (config_dict(py, config)?,))?;
        }
        Ok(PyLearner {
            minimal_joint_move: config.minimal_joint_move,
            ..self
        })
    }

    /// The learner that answers a signal by asking `stop` for a stop and keeping the
    /// exception in `interrupt`.
    pub fn stopping(self, stop: StopRequest, interrupt: ErrorSlot) -> PyLearner {
        PyLearner {
            stop: Some((stop, interrupt)),
            ..self
        }
    }

    /// Runs `call` after Python's signal handlers; an interrupt raised by either is
    /// answered by a stop request and `Ok(None)`.
    fn guarded<T>(
        &self,
        py: Python<'_>,
        call: impl FnOnce(Python<'_>) -> PyResult<T>,
    ) -> PyResult<Option<T>> {
        let Some((stop, interrupt)) = &self.stop else {
            return call(py).map(Some);
        };
        match py.check_signals().and_then(|()| call(py)) {
            Err(error) if error.is_instance_of::<PyKeyboardInterrupt>(py) => {
                stop.request(SIGINT);
                if let Ok(mut slot) = interrupt.lock() {
                    slot.get_or_insert(error);
                }
                Ok(None)
            }
            other => other.map(Some),
        }
    }

    fn failed(&self) -> bool {
        self.error.lock().map_or(true, |slot| slot.is_some())
    }

    fn keep(&self, error: PyErr) {
        if let Ok(mut slot) = self.error.lock() {
            slot.get_or_insert(error);
        }
    }

    /// What the learner's `size()` answers (0 without one, or once it has failed); an
    /// answer that is no count fails it.
    fn size(&self) -> usize {
        if !self.has_size || self.failed() {
            return 0;
        }
        Python::attach(|py| {
            let answer = self.object.bind(py).call_method0("size")?;
            answer.extract::<usize>().map_err(|_| {
                PyValueError::new_err(format!(
                    "learner `{}`'s size() must be a count (an int ≥ 0), not {}",
                    self.name,
                    answer
                        .repr()
                        .map_or_else(|_| "?".to_string(), |r| r.to_string())
                ))
            })
        })
        .unwrap_or_else(|error| {
            self.keep(error);
            0
        })
    }

    fn call_propose(&self, py: Python<'_>, query: &Query) -> PyResult<Vector3<f64>> {
        let object = self.object.bind(py);
        let answer = match self.api {
            Api::Arrays => object.call_method1("propose", (query_array(py, query),))?,
            Api::Named => object.call_method1("propose", (NamedQuery::of(query),))?,
        };
        let delta = vector3(&answer, "propose's answer")?;
        if !delta.iter().all(|v| v.is_finite()) {
            return Err(PyValueError::new_err(format!(
                "learner `{}` proposed a non-finite move ({}, {}, {}) for the query \
                 (cx {}, cy {}, cz {}, θ2 {}, θ3 {})",
                self.name,
                delta.x,
                delta.y,
                delta.z,
                query.c.x,
                query.c.y,
                query.c.z,
                query.theta2_deg,
                query.theta3_deg
            )));
        }
        Ok(delta)
    }
}

impl Learner for PyLearner {
    fn name(&self) -> &str {
        &self.name
    }

    fn propose(&mut self, query: &Query) -> Vector3<f64> {
        if self.failed() {
            return Vector3::repeat(f64::NAN);
        }
        Python::attach(
            |py| match self.guarded(py, |py| self.call_propose(py, query)) {
                Ok(Some(delta)) => delta,
                Ok(None) => Vector3::repeat(f64::NAN),
                Err(error) => {
                    self.keep(error);
                    Vector3::repeat(f64::NAN)
                }
            },
        )
    }

    fn learn(&mut self, path: &[Observation]) -> Result<(), LearnError> {
        if !self.failed() {
            let called = Python::attach(|py| {
                self.guarded(py, |py| {
                    let object = self.object.bind(py);
                    match self.api {
                        Api::Arrays => object.call_method1("learn", (path_array(py, path)?,)),
                        Api::Named => object.call_method1(
                            "learn",
                            (Patterns::of(py, path, self.minimal_joint_move)?,),
                        ),
                    }
                    .map(drop)
                })
            });
            if let Err(error) = called {
                self.keep(error);
            }
        }
        match self
            .error
            .lock()
            .ok()
            .and_then(|slot| slot.as_ref().map(|e| e.to_string()))
        {
            Some(reason) => Err(LearnError::Failed {
                learner: self.name.clone(),
                reason,
            }),
            None => Ok(()),
        }
    }

    fn stats(&self) -> LearnerStats {
        LearnerStats {
            nodes: self.size(),
            ..LearnerStats::default()
        }
    }
}

/// A built-in learner (any of `Method::ALL`, by name) with the settings of a config, built
/// as a run builds its learner (on an arm other than the OSCAR-6, its boundaries fitted to
/// that arm): `Learner(method="lin5", config=None, urdf=None, **entries)`.
#[pyclass(unsendable, module = "eyehand", name = "Learner")]
#[derive(Debug)]
pub struct BuiltinLearner {
    inner: Box<dyn Learner>,
}

impl BuiltinLearner {
    /// The learner, for the trial loop.
    pub fn inner_mut(&mut self) -> &mut dyn Learner {
        self.inner.as_mut()
    }
}

#[pymethods]
impl BuiltinLearner {
    #[new]
    #[pyo3(signature = (method = "lin5", config = None, urdf = None, **entries))]
    fn new(
        method: &str,
        config: Option<PathBuf>,
        urdf: Option<PathBuf>,
        entries: Option<&Bound<'_, PyDict>>,
    ) -> PyResult<BuiltinLearner> {
        let named = [("method", Some(method.to_string()))];
        let request = RunRequest {
            urdf,
            ..run_request(config.as_deref(), entries, &named)?
        };
        let setup = run_options(&request)?.setup().map_err(value_error)?;
        let inner = setup.learner(None).map_err(value_error)?;
        Ok(BuiltinLearner { inner })
    }

    /// The method's name.
    #[getter]
    fn name(&self) -> String {
        self.inner.name().to_string()
    }

    /// The move (Δθ1, Δθ2, Δθ3 in degrees) for a query (cx, cy, cz, θ2, θ3).
    fn propose<'py>(
        &mut self,
        py: Python<'py>,
        query: &Bound<'py, PyAny>,
    ) -> PyResult<Bound<'py, PyArray1<f64>>> {
        let delta = self.inner.propose(&query_from(query)?);
        Ok(PyArray1::from_slice(py, delta.as_slice()))
    }

    /// Learns from a trial's poses, an (n, 6) array of (cx, cy, cz, θ1, θ2, θ3).
    fn learn(&mut self, path: &Bound<'_, PyAny>) -> PyResult<()> {
        let path = path_from(path)?;
        self.inner
            .learn(&path)
            .map_err(|e| pyo3::exceptions::PyOSError::new_err(e.to_string()))
    }

    /// The learner's figures: nodes, bins and patterns.
    fn stats<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let LearnerStats {
            nodes,
            bins,
            patterns,
            ..
        } = self.inner.stats();
        let dict = PyDict::new(py);
        dict.set_item("nodes", nodes)?;
        dict.set_item("bins", bins)?;
        dict.set_item("patterns", patterns)?;
        Ok(dict)
    }

    fn __repr__(&self) -> String {
        format!("eyehand.Learner({:?})", self.inner.name())
    }
}
