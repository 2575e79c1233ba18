//! The one place a run is put together: a config, a URDF and the events become the arm
//! (read and checked once), its reach space (fitted once), the simulator, the camera, the
//! learner and the trial loop. `run`, `show`, the study's cells, the Python `Testbed` and
//! the benches all build their runs here.

use crate::camera::Camera;
use crate::control::TrialLoop;
use crate::experiment::setup::preflight::preflight;
use crate::experiment::setup::start_check::check_start;
use crate::experiment::setup::{
    arm_entry, build_camera, build_learner, build_simulator, fitted_boundaries, load_arm,
    proposed_mount, refused_where_it_looks, size_readings_to_arm, size_standoff_to_arm,
    trial_settings,
};
use crate::experiment::{
    Config, Event, PreflightError, ReachSetting, RunError, Source, Sources, UrdfFile,
};
use crate::learn::{LearnError, Learner};
use crate::robot::{ArmModel, ReachSpace, Simulator};
use std::path::Path;

/// The learner boundaries of the learned shoulder and elbow, fitted to an arm together.
const BOUNDARIES: [&str; 4] = [
    "boundary_0_low",
    "boundary_0_high",
    "boundary_1_low",
    "boundary_1_high",
];

/// `reach_space auto` where the config left the reach space at its default (the
/// OSCAR-6's): what a URDF other than the shipped one gets.
pub fn fit_reach_space_to_arm(config: &mut Config, sources: &mut Sources) {
    if config.source_of("reach_space", sources) == Source::Default {
        config.reach_space = ReachSetting::Auto;
        sources.record("reach_space", Source::Fitted);
    }
}

/// The boundaries of θ2 and θ3 fitted to `model` over `reach` ([`fitted_boundaries`]) where
/// the config left all four at their defaults (the OSCAR-6's), the config checked again.
fn fit_boundaries_to_arm(
    config: &mut Config,
    sources: &mut Sources,
    model: &ArmModel,
    reach: &ReachSpace,
) -> Result<(), PreflightError> {
    let at_default = |name: &&str| config.source_of(name, sources) == Source::Default;
    if !BOUNDARIES.iter().all(at_default) {
        return Ok(());
    }
    let Some([(low2, high2), (low3, high3)]) = fitted_boundaries(model, reach) else {
        return Ok(());
    };
    (config.boundary_0_low, config.boundary_0_high) = (low2, high2);
    (config.boundary_1_low, config.boundary_1_high) = (low3, high3);
    for name in BOUNDARIES {
        sources.record(name, Source::Fitted);
    }
    Ok(config.check()?)
}

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
    /// Where each value of `config` came from, the entries fitted to the arm included.
    pub sources: Sources,
}

impl RunSetup {
    /// Reads the arm of `urdf` (else the config's `urdf`; the shipped OSCAR-6 without
    /// either; `urdf` becomes the config's, from `--urdf`) as the config's arm
    /// entries pick it out, and checks the config, `events` (every event of the run, in
    /// trial order: see [`Event::of_run`]) and the arm's reach before anything is built; an
    /// arm entry the URDF contradicts is reported where its value came from (`file:line`,
    /// `--set`, …, by `sources`). On a URDF other than the shipped OSCAR-6, the entries
    /// left at their defaults that describe the OSCAR-6 are fitted to the arm instead:
    /// `reach_space` (to `auto`), the boundaries of θ2 and θ3 ([`fitted_boundaries`]), the
    /// `standoff` over a fitted space
    /// ([`sized_standoff_cm`](crate::experiment::setup::sized_standoff_cm)) and the boundaries of cz
    /// ([`size_readings_to_arm`]). The run's start is checked with them.
    pub fn new(
        config: Config,
        urdf: Option<&Path>,
        events: Vec<Event>,
        sources: &Sources,
    ) -> Result<RunSetup, RunError> {
        RunSetup::checked(config.clone(), urdf, events.clone(), sources).map_err(|refusal| {
            let looks = refused_where_it_looks(&refusal);
            match proposed_mount(&config, urdf, &events, sources, looks) {
                Some(Ok(other)) => RunError::OtherMount {
                    refusal: Box::new(refusal),
                    other: Box::new(other),
                },
                Some(Err(search)) => RunError::NoOtherMount {
                    refusal: Box::new(refusal),
                    search,
                },
                None => refusal,
            }
        })
    }

    /// [`new`](RunSetup::new) without looking for another camera mount when the camera is
    /// refused.
    pub(super) fn checked(
        mut config: Config,
        urdf: Option<&Path>,
        events: Vec<Event>,
        sources: &Sources,
    ) -> Result<RunSetup, RunError> {
        let mut sources = sources.clone();
        if let Some(file) = urdf {
            config.urdf = UrdfFile(Some(file.to_path_buf()));
            sources.record("urdf", Source::Flag("--urdf"));
        }
        let urdf = config.urdf.0.clone();
        let urdf = urdf.as_deref();
        let mut arm = load_arm(&config, urdf).map_err(|source| match arm_entry(&source) {
            Some(entry) => RunError::ArmEntry {
                at: config.source_of(entry, &sources).to_string(),
                entry,
                source: Box::new(source),
            },
            None => RunError::Urdf(source),
        })?;
        if urdf.is_some() {
            fit_reach_space_to_arm(&mut config, &mut sources);
        }
        let reach = preflight(&config, &mut arm.model, &events)?;
        if urdf.is_some() {
            fit_boundaries_to_arm(&mut config, &mut sources, &arm.model, &reach)?;
            size_standoff_to_arm(&mut config, &mut sources, &reach)?;
            size_readings_to_arm(&mut config, &mut sources, &reach)?;
        }
        check_start(&config, &arm.model, &reach)?;
        Ok(RunSetup {
            config,
            model: arm.model,
            reach,
            events,
            warnings: arm.warnings,
            sources,
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
