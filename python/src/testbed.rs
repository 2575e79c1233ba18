//! `eyehand.Testbed`: the trial loop of a run, driven one feedback step at a time from
//! Python, on the simulator and camera a run's config names.

use crate::convert::{path_array, query_array, run_options, run_request, value_error, vector3};
use crate::learner::{BuiltinLearner, ErrorSlot, PyLearner};
use crate::view::EpisodeView;
use eyehand::control::{Failure, StepError, TrialEnd, TrialLoop};
use eyehand::experiment::{begin_learner_trial, start_learning, CameraKind, RunRequest, RunSetup};
use eyehand::learn::{LearnError, Learner};
use eyehand::robot::Controlled;
use eyehand::units::{MM_PER_M, M_PER_CM};
use numpy::{PyArray1, PyArray2, PyArray3, PyArrayMethods};
use pyo3::exceptions::{PyOSError, PyRuntimeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::PyDict;
use std::path::PathBuf;

/// The smallest and largest camera image (pixels a side).
const MIN_IMAGE: usize = 2;
const MAX_IMAGE: usize = 4096;

/// What a step returns: the reading (None when not seen), θ1..θ3, the distance (mm) and
/// whether the object is seen.
type StepTuple<'py> = (
    Option<Bound<'py, PyArray1<f64>>>,
    Bound<'py, PyArray1<f64>>,
    f64,
    bool,
);

/// The testbed: `Testbed(config=None, sim="kinematic", camera="projection", seed=1,
/// urdf=None, **entries)`. The config and the arm pass a run's checks before it is built.
#[pyclass(unsendable, module = "eyehand")]
#[derive(Debug)]
pub struct Testbed {
    trials: TrialLoop,
    view: EpisodeView,
    /// The number of the trial a learner begins next (1 until one has learned a trial).
    next_trial: usize,
}

#[pymethods]
impl Testbed {
    #[new]
    #[pyo3(signature = (config = None, sim = "kinematic", camera = "projection", seed = 1, urdf = None, **entries))]
    fn new(
        config: Option<PathBuf>,
        sim: &str,
        camera: &str,
        seed: u64,
        urdf: Option<PathBuf>,
        entries: Option<&Bound<'_, PyDict>>,
    ) -> PyResult<Testbed> {
        let setup = run_setup(config, sim, camera, seed, urdf, entries)?;
        let trials = setup.trial_loop();
        let resolution = match setup.config.camera {
            CameraKind::Raycast => setup.config.raycast_resolution,
            CameraKind::Projection => trials.camera().model().width.round() as usize,
        };
        Ok(Testbed {
            trials,
            view: EpisodeView::new(resolution),
            next_trial: 1,
        })
    }

    /// Begins a trial (target and start drawn as a run draws them) and returns the
    /// observation (cx, cy, cz, θ2, θ3). With `seed`, the draws restart from it.
    #[pyo3(signature = (seed = None))]
    fn reset<'py>(
        &mut self,
        py: Python<'py>,
        seed: Option<u64>,
    ) -> PyResult<Bound<'py, PyArray1<f64>>> {
        if let Some(seed) = seed {
            self.trials.reseed(seed);
        }
        match self.trials.begin_trial() {
            Ok(start) => {
                self.view.begin(&self.trials, start.c);
                Ok(query_array(py, &start.query()))
            }
            Err(failure) => Err(PyRuntimeError::new_err(failure_message(failure))),
        }
    }

    /// Executes a move (Δθ1, Δθ2, Δθ3 in degrees) and returns (reading or None, joint
    /// angles θ1..θ3 in degrees, distance to the target in mm, seen).
    fn step<'py>(
        &mut self,
        py: Python<'py>,
        delta_deg: &Bound<'py, PyAny>,
    ) -> PyResult<StepTuple<'py>> {
        let delta = vector3(delta_deg, "a move")?;
        let report = self.trials.step_trial(&delta).map_err(|e| match e {
            StepError::NoTrial => PyRuntimeError::new_err(e.to_string()),
            _ => PyValueError::new_err(e.to_string()),
        })?;
        self.view.keep(&self.trials, report.reading);
        let reading = report
            .reading
            .ok()
            .map(|c| PyArray1::from_slice(py, c.as_slice()));
        let seen = reading.is_some();
        let joints = PyArray1::from_slice(py, report.theta_deg.as_slice());
        Ok((reading, joints, report.distance_mm, seen))
    }

    /// The latest observation of the trial (cx, cy, cz, θ2, θ3): where the object was last
    /// seen; None before the first reset.
    #[getter]
    fn observation<'py>(&self, py: Python<'py>) -> Option<Bound<'py, PyArray1<f64>>> {
        let last = self.trials.path().last()?;
        Some(query_array(py, &last.query()))
    }

    /// The distance (mm) from the camera to the target as it is now; None when no trial
    /// was begun.
    #[getter]
    fn distance_mm(&self) -> Option<f64> {
        self.trials.distance_mm()
    }

    /// The episode drawn as `eyehand show` draws a trial: the arm's side and top views of
    /// every pose so far beside the camera's image at the last one, an (H, W, 3) uint8
    /// array; None before the first reset.
    fn render<'py>(&self, py: Python<'py>) -> PyResult<Option<Bound<'py, PyArray3<u8>>>> {
        let Some(frame) = self.view.frame(&self.trials) else {
            return Ok(None);
        };
        let frame = frame.map_err(PyRuntimeError::new_err)?;
        let shape = [frame.height as usize, frame.width as usize, 3];
        PyArray1::from_vec(py, frame.rgb).reshape(shape).map(Some)
    }

    /// The grey image (`resolution` × `resolution`, uint8) the ray-cast camera sees at the
    /// pose now: the floor, obstacles and arm, and the object where it is seen; None
    /// before the first reset.
    fn camera_image<'py>(
        &self,
        py: Python<'py>,
        resolution: usize,
    ) -> PyResult<Option<Bound<'py, PyArray2<u8>>>> {
        if !(MIN_IMAGE..=MAX_IMAGE).contains(&resolution) {
            return Err(PyValueError::new_err(format!(
                "an image resolution from {MIN_IMAGE} to {MAX_IMAGE} pixels, not {resolution}"
            )));
        }
        let Some(image) = self.view.camera_image(&self.trials, resolution) else {
            return Ok(None);
        };
        PyArray1::from_vec(py, image)
            .reshape([resolution, resolution])
            .map(Some)
    }

    /// The camera's position (world, mm) as it is now.
    #[getter]
    fn camera_mm<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        let camera = self.trials.sim().camera_pose().translation.vector * MM_PER_M;
        PyArray1::from_slice(py, camera.as_slice())
    }

    /// The goal point of the trial (world, mm): where the camera is to be, a standoff above
    /// the object; None when no trial was begun.
    #[getter]
    fn goal_mm<'py>(&self, py: Python<'py>) -> Option<Bound<'py, PyArray1<f64>>> {
        let goal = self.trials.goal()?.coords * MM_PER_M;
        Some(PyArray1::from_slice(py, goal.as_slice()))
    }

    /// The reading's bounds: (low, high) of cx, cy (pixels, the image's half size) and cz
    /// (above −100; no upper bound), a (3, 2) array.
    #[getter]
    fn reading_bounds<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray2<f64>>> {
        let camera = self.trials.camera().model();
        let (x, y) = (camera.width / 2.0, camera.height / 2.0);
        let flat = vec![-x, x, -y, y, -100.0, f64::INFINITY];
        PyArray1::from_vec(py, flat).reshape([3, 2])
    }

    /// Feedback steps taken in the trial going on (0 when none is).
    #[getter]
    fn steps(&self) -> usize {
        self.trials.trial_state().map_or(0, |(steps, _)| steps)
    }

    /// Why the trial is over: "reached", "steps_used", "lost", or None while it goes on.
    #[getter]
    fn end(&self) -> Option<&'static str> {
        let (_, end) = self.trials.trial_state()?;
        end.map(|end| match end {
            TrialEnd::Reached => "reached",
            TrialEnd::StepsUsed => "steps_used",
            TrialEnd::Lost(_) => "lost",
        })
    }

    /// True when no trial is going on or it is over.
    #[getter]
    fn done(&self) -> bool {
        self.trials
            .trial_state()
            .is_none_or(|(_, end)| end.is_some())
    }

    /// The trial's poses so far, an (n, 6) array of (cx, cy, cz, θ1, θ2, θ3).
    #[getter]
    fn path<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray2<f64>>> {
        path_array(py, self.trials.path())
    }

    /// Finishes the trial: `learner` (an `eyehand.Learner` or any object with `learn`)
    /// learns from its poses, as a run's learner does after each trial, and the next trial
    /// begins for it as a run begins it (a built-in learner told its number, pre-learning
    /// made again if it asks).
    fn learn(&mut self, learner: &Bound<'_, PyAny>) -> PyResult<()> {
        let (trials, next) = (&mut self.trials, self.next_trial + 1);
        with_learner(learner, |l| {
            trials.finish_trial(l)?;
            begin_learner_trial(trials, l, next)
        })?;
        self.next_trial = next;
        Ok(())
    }

    /// Pre-learning: `learner` started as a run starts its learner before the first
    /// trial (told trial 0 begins, then the 8 fixed moves made and learned), and the next
    /// trial begun for it. Ends any trial going on unlearned.
    fn prelearn(&mut self, learner: &Bound<'_, PyAny>) -> PyResult<()> {
        let (trials, next) = (&mut self.trials, self.next_trial);
        with_learner(learner, |l| {
            start_learning(trials, l)?;
            begin_learner_trial(trials, l, next)
        })
    }

    /// Stretches (positive) or shortens link 1, 2 or 3 by `cm`.
    fn stretch_link(&mut self, link: usize, cm: f64) -> PyResult<()> {
        self.trials
            .sim_mut()
            .stretch_link(link, cm * M_PER_CM)
            .map_err(value_error)
    }

    /// Turns the camera about its optical axis by `degrees`.
    fn rotate_camera(&mut self, degrees: f64) -> PyResult<()> {
        if !degrees.is_finite() {
            return Err(PyValueError::new_err(format!(
                "a camera turn of {degrees} degrees"
            )));
        }
        self.trials.sim_mut().rotate_camera(degrees.to_radians());
        Ok(())
    }

    /// Forward kinematics of the robot as it is now, as `eyehand fk --json` gives it:
    /// {"camera_cm": (3,), "joints_deg": (every joint,)} for θ1..θ3 in degrees.
    fn fk<'py>(&self, py: Python<'py>, joints: &Bound<'py, PyAny>) -> PyResult<Bound<'py, PyDict>> {
        let theta = vector3(joints, "joints")?;
        if !theta.iter().all(|v| v.is_finite()) {
            return Err(PyValueError::new_err("joint angles must be finite"));
        }
        let model = self.trials.sim().model();
        let q = model.full_pose(&Controlled::from(theta.map(f64::to_radians)));
        let camera = model.camera_position(&q).coords / M_PER_CM;
        let dict = PyDict::new(py);
        dict.set_item("camera_cm", PyArray1::from_slice(py, camera.as_slice()))?;
        let joints_deg: Vec<f64> = q.iter().map(|v| v.to_degrees()).collect();
        dict.set_item("joints_deg", PyArray1::from_vec(py, joints_deg))?;
        Ok(dict)
    }

    /// The limits (low, high) of θ1, θ2, θ3 in degrees, a (3, 2) array.
    #[getter]
    fn joint_limits_deg<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray2<f64>>> {
        let model = self.trials.sim().model();
        let flat: Vec<f64> = model
            .learned()
            .iter()
            .map(|&i| &model.joints()[i])
            .flat_map(|j| [j.lower.to_degrees(), j.upper.to_degrees()])
            .collect();
        PyArray1::from_vec(py, flat).reshape([3, 2])
    }

    /// At most this many feedback steps a trial.
    #[getter]
    fn feedback_steps(&self) -> usize {
        self.trials.settings().feedback_steps
    }

    /// At least this many feedback steps before reaching ε ends a trial.
    #[getter]
    fn min_feedback_steps(&self) -> usize {
        self.trials.settings().min_feedback_steps
    }

    /// ε in mm.
    #[getter]
    fn epsilon_mm(&self) -> f64 {
        self.trials.settings().epsilon * MM_PER_M
    }
}

/// The testbed's setup: the config file (or the default) with `entries`, `sim` and
/// `camera` set together and checked once, the `seed`, and the arm of `urdf`, checked as a
/// run checks them.
pub fn run_setup(
    config: Option<PathBuf>,
    sim: &str,
    camera: &str,
    seed: u64,
    urdf: Option<PathBuf>,
    entries: Option<&Bound<'_, PyDict>>,
) -> PyResult<RunSetup> {
    let named = [
        ("sim", Some(sim.to_string())),
        ("camera", Some(camera.to_string())),
    ];
    let request = RunRequest {
        seed: Some(seed),
        urdf,
        ..run_request(config.as_deref(), entries, &named)?
    };
    run_options(&request)?.setup().map_err(value_error)
}

/// Runs `body` with `learner` as a Rust learner: a built-in `eyehand.Learner` directly,
/// any other object through its `propose` and `learn`; its exception is raised again.
fn with_learner(
    learner: &Bound<'_, PyAny>,
    body: impl FnOnce(&mut dyn Learner) -> Result<(), LearnError>,
) -> PyResult<()> {
    if let Ok(builtin) = learner.cast::<BuiltinLearner>() {
        let mut builtin = builtin.try_borrow_mut()?;
        return body(builtin.inner_mut()).map_err(|e| PyOSError::new_err(e.to_string()));
    }
    let slot = ErrorSlot::default();
    let mut wrapped = PyLearner::new(learner, slot.clone())?;
    let result = body(&mut wrapped);
    if let Some(error) = slot.lock().ok().and_then(|mut s| s.take()) {
        return Err(error);
    }
    result.map_err(|e| PyOSError::new_err(e.to_string()))
}

/// Why a trial could not begin, in words.
fn failure_message(failure: Failure) -> String {
    match failure {
        Failure::UnreachableTarget => "no reachable target was drawn".into(),
        Failure::NoStartSeen => "no start pose from which the object is seen was drawn".into(),
        other => format!("the trial could not begin: {other:?}"),
    }
}
