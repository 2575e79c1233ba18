//! The named inputs of a learner that asks for them (`eyehand_api = 2`): `eyehand.Query`,
//! one query with its fields by name, and `eyehand.Patterns`, a trial's learning patterns,
//! both with the five inputs in the order of the config's boundaries 0–4.

use crate::convert::{path_array, path_from};
use eyehand::learn::{adjusted_pattern, pose_pairs, Observation, Query};
use nalgebra::Vector3;
use numpy::{PyArray1, PyArray2, PyArrayMethods};
use pyo3::prelude::*;

/// The five inputs' names, in the order of `Query.inputs`, `Patterns.inputs` and the
/// config's `boundary_0` … `boundary_4`.
pub const INPUTS: [&str; 5] = ["theta2_deg", "theta3_deg", "cx", "cy", "cz"];

/// The five inputs' units, in the order of [`INPUTS`].
pub const INPUT_UNITS: [&str; 5] = ["°", "°", "px", "px", "area measure"];

/// The three targets' names (a move), in the order of `Patterns.targets` and `propose`'s
/// answer.
pub const TARGETS: [&str; 3] = ["dtheta1_deg", "dtheta2_deg", "dtheta3_deg"];

/// A query by name: `Query(theta2_deg, theta3_deg, cx, cy, cz)` — the shoulder and elbow
/// angles (°), the object's image offsets (px) and its area measure. `inputs` is the
/// (5,) array in the order of `eyehand.INPUTS`, which is the order of the config's
/// boundaries 0–4.
#[pyclass(frozen, module = "eyehand", name = "Query")]
#[derive(Debug, Clone, Copy)]
pub struct NamedQuery {
    query: Query,
}

impl NamedQuery {
    /// The named form of `query`.
    pub fn of(query: &Query) -> NamedQuery {
        NamedQuery { query: *query }
    }
}

#[pymethods]
impl NamedQuery {
    #[new]
    fn new(theta2_deg: f64, theta3_deg: f64, cx: f64, cy: f64, cz: f64) -> NamedQuery {
        NamedQuery {
            query: Query {
                c: Vector3::new(cx, cy, cz),
                theta2_deg,
                theta3_deg,
            },
        }
    }

    /// Shoulder angle θ2 (°).
    #[getter]
    fn theta2_deg(&self) -> f64 {
        self.query.theta2_deg
    }

    /// Elbow angle θ3 (°).
    #[getter]
    fn theta3_deg(&self) -> f64 {
        self.query.theta3_deg
    }

    /// The object's horizontal image offset (px).
    #[getter]
    fn cx(&self) -> f64 {
        self.query.c.x
    }

    /// The object's vertical image offset (px).
    #[getter]
    fn cy(&self) -> f64 {
        self.query.c.y
    }

    /// The object's area measure (0 at the standoff, larger when nearer).
    #[getter]
    fn cz(&self) -> f64 {
        self.query.c.z
    }

    /// The five inputs (θ2, θ3, cx, cy, cz) as a (5,) array.
    #[getter]
    fn inputs<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        PyArray1::from_slice(py, self.query.five_inputs().as_slice())
    }

    fn __repr__(&self) -> String {
        let q = &self.query;
        format!(
            "eyehand.Query(theta2_deg={}, theta3_deg={}, cx={}, cy={}, cz={})",
            q.theta2_deg, q.theta3_deg, q.c.x, q.c.y, q.c.z
        )
    }
}

/// A trial's adjusted learning patterns (those lin5 learns from), by name:
/// `Patterns(path, minimal_joint_move=None, config=None)`. `inputs` is (m, 5) in the order
/// of `eyehand.INPUTS` (θ2 °, θ3 °, cx px, cy px, cz: the pose a move starts from and the
/// reading it removes), `targets` (m, 3) the moves (Δθ1, Δθ2, Δθ3 in °, `eyehand.TARGETS`),
/// `path` the trial's (n, 6) poses they come from. A pose pair is a pattern when some joint
/// moved at least `minimal_joint_move` degrees (default: `config`'s, a dict as `setup`
/// gets it or a config file; without either the entry's declared default).
#[pyclass(frozen, module = "eyehand", name = "Patterns")]
#[derive(Debug)]
pub struct Patterns {
    count: usize,
    inputs: Py<PyArray2<f64>>,
    targets: Py<PyArray2<f64>>,
    path: Py<PyArray2<f64>>,
}

impl Patterns {
    /// The patterns of `path`'s pose pairs that moved at least `minimal_joint_move` degrees.
    pub fn of(py: Python<'_>, path: &[Observation], minimal_joint_move: f64) -> PyResult<Self> {
        let (inputs, targets) = pattern_rows(path, minimal_joint_move);
        let count = targets.len() / TARGETS.len();
        Ok(Patterns {
            count,
            inputs: PyArray1::from_vec(py, inputs)
                .reshape([count, INPUTS.len()])?
                .unbind(),
            targets: PyArray1::from_vec(py, targets)
                .reshape([count, TARGETS.len()])?
                .unbind(),
            path: path_array(py, path)?.unbind(),
        })
    }
}

#[pymethods]
impl Patterns {
    #[new]
    #[pyo3(signature = (path, minimal_joint_move = None, config = None))]
    fn new(
        py: Python<'_>,
        path: &Bound<'_, PyAny>,
        minimal_joint_move: Option<f64>,
        config: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<Patterns> {
        let minimal_joint_move = crate::patterns::minimal_joint_move(minimal_joint_move, config)?;
        Patterns::of(py, &path_from(path)?, minimal_joint_move)
    }

    /// The inputs, (m, 5): θ2 (°), θ3 (°), cx (px), cy (px), cz.
    #[getter]
    fn inputs<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray2<f64>> {
        self.inputs.bind(py).clone()
    }

    /// The targets, (m, 3): Δθ1, Δθ2, Δθ3 (°).
    #[getter]
    fn targets<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray2<f64>> {
        self.targets.bind(py).clone()
    }

    /// The trial's poses, (n, 6): cx, cy, cz, θ1, θ2, θ3 a row.
    #[getter]
    fn path<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray2<f64>> {
        self.path.bind(py).clone()
    }

    /// The number of patterns.
    fn __len__(&self) -> usize {
        self.count
    }

    fn __repr__(&self) -> String {
        format!("eyehand.Patterns({} patterns)", self.count)
    }
}

/// The inputs (θ2, θ3, cx, cy, cz a row) and targets (Δθ1, Δθ2, Δθ3 a row), flat, of the
/// adjusted patterns of `path`'s pose pairs that moved at least `minimal_joint_move`.
pub fn pattern_rows(path: &[Observation], minimal_joint_move: f64) -> (Vec<f64>, Vec<f64>) {
    let mut inputs = Vec::new();
    let mut targets = Vec::new();
    for (from, to) in pose_pairs(path, minimal_joint_move) {
        let pattern = adjusted_pattern(from, to);
        inputs.extend(pattern.input.iter());
        targets.extend(pattern.target.iter());
    }
    (inputs, targets)
}
