//! Another mount for a camera refused as the camera link's z axis points it: the link's
//! other axes tried in turn, and the first along which the arm passes every check made
//! before a run and most of a short run's first trials succeed — what the refusal then
//! proposes.

use crate::experiment::run::trial_driver::TrialDriver;
use crate::experiment::{
    CameraMount, Config, Event, PreflightError, RunError, RunSetup, Source, Sources,
};
use crate::robot::description::{DescriptionError, DescriptionErrorKind as Kind};
use crate::robot::ReachSpace;
use std::path::Path;

/// Trials of the short run a mount is tried with.
const TRIED_TRIALS: usize = 200;
/// The turns tried (roll, pitch, yaw in degrees, as `camera_mount` gives them) and the
/// axis of the camera link each turns the optical axis onto.
const TURNS: [([f64; 3], &str); 5] = [
    ([180.0, 0.0, 0.0], "-z"),
    ([0.0, 90.0, 0.0], "x"),
    ([0.0, -90.0, 0.0], "-x"),
    ([90.0, 0.0, 0.0], "-y"),
    ([-90.0, 0.0, 0.0], "y"),
];

/// A camera mount along another axis of the camera link with which an arm refused along
/// the link's z axis passes every check made before a run, and fails at most half of a
/// short run's first trials.
#[derive(Debug, Clone, PartialEq)]
pub struct OtherMount {
    /// The mount: the config's offset, turned.
    pub mount: CameraMount,
    /// The axis of the camera link the camera looks along (`-z`, `x`, `-x`, `-y`, `y`).
    pub axis: &'static str,
    /// The reach space the arm then works in.
    pub space: ReachSpace,
    /// How many of the first `TRIED_TRIALS` (200) trials of a run failed.
    pub failed: usize,
}

impl std::fmt::Display for OtherMount {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let [x, y, z] = self.mount.offset_m;
        let [roll, pitch, yaw] = self.mount.rpy_deg;
        let cm = |v: f64| v * 100.0;
        write!(
            f,
            "a camera looking along the link's {} axis works: with camera_mount \
             {x},{y},{z},{roll},{pitch},{yaw} the arm fits a reach space r {:.1}..{:.1} cm, \
             z {:.1}..{:.1} cm, passes every check before a run and fails {} of its first {} \
             trials (set it if the camera is mounted so)",
            self.axis,
            cm(self.space.r_min),
            cm(self.space.r_max),
            cm(self.space.z_min),
            cm(self.space.z_max),
            self.failed,
            TRIED_TRIALS
        )
    }
}

/// The mount a refusal proposes, when it is about where the camera looks (`looks`: see
/// [`refused_where_it_looks`], [`refuses_where_it_looks`]), the arm is a URDF's (`urdf`,
/// else the config's) and `camera_mount` was left at its default: the first other axis
/// that works. `None` otherwise, and when no other axis does.
pub fn proposed_mount(
    config: &Config,
    urdf: Option<&Path>,
    events: &[Event],
    sources: &Sources,
    looks: bool,
) -> Option<OtherMount> {
    let own_arm = urdf.or(config.urdf.path()).is_some();
    let default_mount = config.source_of("camera_mount", sources) == Source::Default;
    if own_arm && default_mount && looks {
        other_mount(config, urdf, events, sources)
    } else {
        None
    }
}

/// The first of the camera link's other axes (-z, x, -x, -y, y, the config's offset kept)
/// along which the arm of `urdf` with `config` passes every check made before a run with
/// `events` and at most half of `TRIED_TRIALS` (200) first trials fail; `None` when none does.
fn other_mount(
    config: &Config,
    urdf: Option<&Path>,
    events: &[Event],
    sources: &Sources,
) -> Option<OtherMount> {
    TURNS.iter().find_map(|&(rpy_deg, axis)| {
        let mut tried = config.clone();
        tried.camera_mount = CameraMount {
            offset_m: config.camera_mount.offset_m,
            rpy_deg,
        };
        let setup = RunSetup::checked(tried, urdf, events.to_vec(), sources).ok()?;
        let failed = failed_first_trials(&setup)?;
        (2 * failed <= TRIED_TRIALS).then_some(OtherMount {
            mount: setup.config.camera_mount,
            axis,
            space: setup.reach,
            failed,
        })
    })
}

/// How many of the first [`TRIED_TRIALS`] trials of `setup` fail (events left out);
/// `None` when its learner cannot be built or a trial stops the run.
fn failed_first_trials(setup: &RunSetup) -> Option<usize> {
    let mut driver =
        TrialDriver::start(setup.trial_loop(), setup.learner(None).ok()?, Vec::new()).ok()?;
    let mut failed = 0;
    for trial in 1..=TRIED_TRIALS {
        let outcome = driver.next(trial, &mut |_, _| {}).ok()?;
        failed += usize::from(outcome.failure.is_some());
    }
    Some(failed)
}

/// True when `refusal` is about where the camera looks: no wrist pose turns it down, it
/// looks back into the arm, no reach space fits what it reaches looking down, too little
/// of the space is reached, or the pre-learning moves cannot be made.
pub fn refused_where_it_looks(refusal: &RunError) -> bool {
    match refusal {
        RunError::Urdf(error) => refuses_where_it_looks(error),
        RunError::ArmEntry { source, .. } => refuses_where_it_looks(source),
        RunError::Preflight(error) => matches!(
            error,
            PreflightError::NoReachSpace(_)
                | PreflightError::Unreachable { .. }
                | PreflightError::Prelearning { .. }
        ),
        _ => false,
    }
}

/// True when `error` refuses the camera for where it looks: no wrist pose turns it down,
/// or it looks back into the arm.
pub fn refuses_where_it_looks(error: &DescriptionError) -> bool {
    matches!(
        error.kind,
        Kind::CannotLookDown { .. } | Kind::CameraFacesArm { .. }
    )
}
