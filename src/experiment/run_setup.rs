//! The one place a run is put together: a config, a URDF and the events become the arm
//! (read and checked once), its reach space (fitted once), the simulator, the camera, the
//! learner and the trial loop. `run`, `show`, the study's cells, the Python `Testbed` and
//! the benches all build their runs here.

use super::preflight::preflight;
use super::setup::{
    arm_entry, build_camera, build_learner, build_simulator, load_arm, trial_settings,
};
use super::{Config, Event, RunError, Sources};
use crate::camera::Camera;
use crate::control::TrialLoop;
use crate::learn::{LearnError, Learner};
use crate::robot::{ArmModel, ReachSpace, Simulator};
use std::path::Path;

/// A run's parts, checked and fitted once: what every run-making command builds from.
#[derive(Debug, Clone)]
pub struct RunSetup {
    /// The run's settings.
    pub config: Config,
    /// The nominal arm, as its URDF and the config's arm entries give it.
    pub model: ArmModel,
    /// Where targets lie: given, or fitted to the arm.
    pub reach: ReachSpace,
    /// The config's events and the caller's, in trial order.
    pub events: Vec<Event>,
    /// What the URDF was missing and what stands in for it, one line each.
    pub warnings: Vec<String>,
}

impl RunSetup {
    /// Reads the arm of `urdf` (the shipped OSCAR-6 without one) as the config's arm
    /// entries pick it out, and checks the config, `events` (every event of the run, in
    /// trial order: see [`Event::of_run`]) and the arm's reach before anything is built; an
    /// arm entry the URDF contradicts is reported where its value came from (`file:line`,
    /// `--set`, …, by `sources`).
    pub fn new(
        config: Config,
        urdf: Option<&Path>,
        events: Vec<Event>,
        sources: &Sources,
    ) -> Result<RunSetup, RunError> {
        let arm = load_arm(&config, urdf).map_err(|source| match arm_entry(&source) {
            Some(entry) => RunError::ArmEntry {
                at: config.source_of(entry, sources).to_string(),
                entry,
                source: Box::new(source),
            },
            None => RunError::Urdf(source),
        })?;
        let reach = preflight(&config, &arm.model, &events)?;
        Ok(RunSetup {
            config,
            model: arm.model,
            reach,
            events,
            warnings: arm.warnings,
        })
    }

    /// The simulator the config names, moving the nominal arm.
    pub fn simulator(&self) -> Box<dyn Simulator> {
        build_simulator(&self.config, self.model.clone())
    }

    /// The camera the config names.
    pub fn camera(&self) -> Box<dyn Camera> {
        build_camera(&self.config)
    }

    /// The learner the config names; one that stores its patterns in a file
    /// (`use_pat_file` 0) puts it in `run_dir`.
    pub fn learner(&self, run_dir: Option<&Path>) -> Result<Box<dyn Learner>, LearnError> {
        build_learner(&self.config, &self.model, run_dir)
    }

    /// The trial loop over the config's simulator and camera.
    pub fn trial_loop(&self) -> TrialLoop {
        self.trial_loop_around(self.simulator(), self.camera())
    }

    /// The trial loop over `sim` and `camera` (the config's, wrapped by the caller), with
    /// the config's trial settings, seed and the reach space.
    pub fn trial_loop_around(&self, sim: Box<dyn Simulator>, camera: Box<dyn Camera>) -> TrialLoop {
        TrialLoop::new(sim, camera, trial_settings(&self.config), self.config.seed)
            .with_reach(self.reach)
    }
}
