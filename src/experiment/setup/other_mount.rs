//! Another mount for a camera refused as the camera link's z axis points it: the link's
//! other axes tried in turn, then, along those from which the arm hid the object at the
//! pre-learning starts, the camera moved out of the arm; the first mount with which the arm
//! passes every check made before a run, most of a short run's first trials succeed and
//! the arm moves in them is what the refusal then proposes.

use crate::camera::NotSeen;
use crate::experiment::run::trial_driver::TrialDriver;
use crate::experiment::setup::mounts_tried::{NoOtherMount, Unfit};
use crate::experiment::setup::start_check::PrelearningFault;
use crate::experiment::setup::{arm_settings, load_arm};
use crate::experiment::{
    CameraMount, Config, Event, PreflightError, RunError, RunSetup, Source, Sources, STILL_DEG,
};
use crate::robot::description::{DescriptionError, DescriptionErrorKind as Kind};
use crate::robot::{ArmModel, ReachSpace};
use nalgebra::{Isometry3, Vector3};
use std::path::Path;

/// Trials of the short run a mount is tried with.
pub(super) const TRIED_TRIALS: usize = 200;
/// The turns tried (roll, pitch, yaw in degrees, as `camera_mount` gives them) and the
/// axis of the camera link each turns the optical axis onto.
const TURNS: [([f64; 3], &str); 5] = [
    ([180.0, 0.0, 0.0], "-z"),
    ([0.0, 90.0, 0.0], "x"),
    ([0.0, -90.0, 0.0], "-x"),
    ([90.0, 0.0, 0.0], "-y"),
    ([-90.0, 0.0, 0.0], "y"),
];
/// How far out of the arm (m) a camera is moved along a turn from which the arm hid the
/// object.
const OUT_OF_ARM_M: f64 = 0.05;
/// A joint closer than this (m) to the camera link's origin is not where the arm comes
/// from (a wrist roll whose axis passes through the link's origin).
const APART_M: f64 = 0.01;
/// The camera link's axes: a unit vector and its name.
const AXES: [([f64; 3], &str); 6] = [
    ([1.0, 0.0, 0.0], "x"),
    ([-1.0, 0.0, 0.0], "-x"),
    ([0.0, 1.0, 0.0], "y"),
    ([0.0, -1.0, 0.0], "-y"),
    ([0.0, 0.0, 1.0], "z"),
    ([0.0, 0.0, -1.0], "-z"),
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
    /// The axis of the camera link along which the camera was moved out of the arm, by
    /// `OUT_OF_ARM_M` (5 cm); `None` when it keeps the config's offset.
    pub out: Option<&'static str>,
    /// The reach space the arm then works in.
    pub space: ReachSpace,
    /// How many of the first `TRIED_TRIALS` (200) trials of a run failed.
    pub failed: usize,
}

impl OtherMount {
    fn new(
        mount: CameraMount,
        axis: &'static str,
        out: Option<&'static str>,
        space: ReachSpace,
        failed: usize,
    ) -> OtherMount {
        OtherMount {
            mount,
            axis,
            out,
            space,
            failed,
        }
    }
}

impl std::fmt::Display for OtherMount {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let [x, y, z] = self.mount.offset_m;
        let [roll, pitch, yaw] = self.mount.rpy_deg;
        let cm = |v: f64| v * 100.0;
        let out = self.out.map_or(String::new(), |axis| {
            format!(
                " and moved {:.0} cm out of the arm along its {axis} axis",
                cm(OUT_OF_ARM_M)
            )
        });
        write!(
            f,
            "a camera looking along the link's {} axis{out} works: with camera_mount \
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
/// else the config's) and `camera_mount` was left at its default: the first other mount
/// that works, or what each one tried met. `None` when no other mount is looked for.
pub fn proposed_mount(
    config: &Config,
    urdf: Option<&Path>,
    events: &[Event],
    sources: &Sources,
    looks: bool,
) -> Option<Result<OtherMount, NoOtherMount>> {
    let own_arm = urdf.or(config.urdf.path()).is_some();
    let default_mount = config.source_of("camera_mount", sources) == Source::Default;
    (own_arm && default_mount && looks).then(|| other_mount(config, urdf, events, sources))
}

/// The first of the camera link's other axes (-z, x, -x, -y, y, the config's offset kept)
/// along which the arm of `urdf` with `config` passes every check made before a run with
/// `events` and at most half of `TRIED_TRIALS` (200) first trials fail; else the first of
/// those along which the arm hid the object at the pre-learning starts that does so with
/// the camera moved `OUT_OF_ARM_M` (5 cm) out of the arm ([`out_of_arm`]); else why each
/// mount tried did not do.
fn other_mount(
    config: &Config,
    urdf: Option<&Path>,
    events: &[Event],
    sources: &Sources,
) -> Result<OtherMount, NoOtherMount> {
    let mut search = NoOtherMount::default();
    let mut hidden = Vec::new();
    for &(rpy_deg, axis) in &TURNS {
        let mount = CameraMount {
            offset_m: config.camera_mount.offset_m,
            rpy_deg,
        };
        match tried(config, urdf, events, sources, mount) {
            Ok((space, failed)) => return Ok(OtherMount::new(mount, axis, None, space, failed)),
            Err(why) => {
                if matches!(why, Unfit::Refused(ref refusal) if hides_the_object(refusal)) {
                    hidden.push((mount, axis));
                }
                search.tried.push((axis.to_string(), why.to_string()));
            }
        }
    }
    for (mount, axis) in hidden {
        let Some((offset_m, out)) = moved_out(config, urdf, &mount) else {
            continue;
        };
        let moved = CameraMount { offset_m, ..mount };
        match tried(config, urdf, events, sources, moved) {
            Ok((space, failed)) => {
                return Ok(OtherMount::new(moved, axis, Some(out), space, failed))
            }
            Err(why) => search.tried.push((
                format!(
                    "{axis}, moved {:.0} cm out along {out}",
                    OUT_OF_ARM_M * 100.0
                ),
                why.to_string(),
            )),
        }
    }
    search.joints = joints(config, urdf);
    Err(search)
}

/// The joints the arm of `urdf` with `config` learns and the other joints of its chain
/// (URDF names), as the arm is read with the config's mount or, where that cannot be read,
/// with the first of [`TURNS`] that can; both empty when none can.
fn joints(config: &Config, urdf: Option<&Path>) -> (Vec<String>, Vec<String>) {
    let mounts = std::iter::once(config.camera_mount.rpy_deg).chain(TURNS.map(|(rpy, _)| rpy));
    let model = mounts.into_iter().find_map(|rpy_deg| {
        let mut turned = config.clone();
        turned.camera_mount.rpy_deg = rpy_deg;
        load_arm(&turned, urdf).ok()
    });
    let Some(model) = model.map(|arm| arm.model) else {
        return (Vec::new(), Vec::new());
    };
    let learned = model.learned();
    let name = |j: usize| model.joints()[j].name.clone();
    (
        learned.iter().map(|&j| name(j)).collect(),
        (0..model.dof())
            .filter(|j| !learned.contains(j))
            .map(name)
            .collect(),
    )
}

/// The arm of `urdf` with `config` and the camera mounted at `mount`, once its checks pass,
/// at most half of its first `TRIED_TRIALS` trials fail and the arm moves in one of them at
/// least: its reach space and how many failed.
fn tried(
    config: &Config,
    urdf: Option<&Path>,
    events: &[Event],
    sources: &Sources,
    mount: CameraMount,
) -> Result<(ReachSpace, usize), Unfit> {
    let mut tried = config.clone();
    tried.camera_mount = mount;
    let setup = RunSetup::checked(tried, urdf, events.to_vec(), sources).map_err(Unfit::Refused)?;
    match first_trials(&setup) {
        Some((failed, _)) if 2 * failed > TRIED_TRIALS => Err(Unfit::Failed(Some(failed))),
        Some((_, 0)) => Err(Unfit::Still),
        Some((failed, _)) => Ok((setup.reach, failed)),
        None => Err(Unfit::Failed(None)),
    }
}

/// True when `refusal` is the arm hiding the object from the camera at the pre-learning
/// starts.
fn hides_the_object(refusal: &RunError) -> bool {
    matches!(
        refusal,
        RunError::Preflight(PreflightError::Prelearning {
            fault: PrelearningFault::NotSeen(NotSeen::Hidden),
            ..
        })
    )
}

/// `mount`'s offset moved `OUT_OF_ARM_M` out of the arm of `urdf` with `config`, along the
/// camera link's axis [`out_of_arm`] names, and that axis' name; `None` when the arm cannot
/// be read with that mount or no joint of its chain lies apart from the camera link.
fn moved_out(
    config: &Config,
    urdf: Option<&Path>,
    mount: &CameraMount,
) -> Option<([f64; 3], &'static str)> {
    let mut turned = config.clone();
    turned.camera_mount = *mount;
    let model = load_arm(&turned, urdf).ok()?.model;
    let (unit, axis) = out_of_arm(&model, &arm_settings(&turned).mount())?;
    let offset = Vector3::from(mount.offset_m) + Vector3::from(unit) * OUT_OF_ARM_M;
    Some((offset.into(), axis))
}

/// The axis of the camera link (unit vector in its frame, and name) nearest the direction
/// out of the arm at rest: from the last joint of `model`'s chain that lies over `APART_M`
/// (1 cm) from the link's origin, to that origin. `camera_in_link` is the camera's pose in
/// the link's frame (offset and turn). `None` when every joint lies at the link's origin.
fn out_of_arm(
    model: &ArmModel,
    camera_in_link: &Isometry3<f64>,
) -> Option<([f64; 3], &'static str)> {
    let rest = model.rest();
    let link = model.camera_pose(&rest) * camera_in_link.inverse();
    let frames = model.link_frames(&rest);
    let origin = link.translation.vector;
    let from = (0..model.dof())
        .rev()
        .map(|k| frames[k].translation.vector)
        .find(|joint| (joint - origin).norm() > APART_M)?;
    Some(nearest_axis(&(link.rotation.inverse() * (origin - from))))
}

/// The axis of a frame (unit vector and name: `x`, `-x`, `y`, `-y`, `z`, `-z`) nearest the
/// direction `v` (in that frame).
fn nearest_axis(v: &Vector3<f64>) -> ([f64; 3], &'static str) {
    AXES.into_iter()
        .max_by(|(a, _), (b, _)| {
            Vector3::from(*a)
                .dot(v)
                .total_cmp(&Vector3::from(*b).dot(v))
        })
        .expect("six axes")
}

/// How many of the first [`TRIED_TRIALS`] trials of `setup` fail, and in how many the arm
/// moves from its start (events left out); `None` when its learner cannot be built or a
/// trial stops the run.
fn first_trials(setup: &RunSetup) -> Option<(usize, usize)> {
    let mut driver =
        TrialDriver::start(setup.trial_loop(), setup.learner(None).ok()?, Vec::new()).ok()?;
    let (mut failed, mut moved) = (0, 0);
    for trial in 1..=TRIED_TRIALS {
        let outcome = driver.next(trial, &mut |_, _| {}).ok()?;
        failed += usize::from(outcome.failure.is_some());
        moved += usize::from(outcome.moved_deg >= STILL_DEG);
    }
    Some((failed, moved))
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
                | PreflightError::NoPrelearningPose { .. }
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_nearest_axis_is_the_one_a_direction_leans_to_most() {
        assert_eq!(nearest_axis(&Vector3::new(0.2, -0.1, -0.9)).1, "-z");
        assert_eq!(nearest_axis(&Vector3::new(-0.6, 0.5, 0.1)).1, "-x");
        assert_eq!(
            nearest_axis(&Vector3::new(0.0, 3.0, -2.9)),
            ([0.0, 1.0, 0.0], "y")
        );
    }

    /// The OSCAR-6's camera link lies past its wrist along its z axis, the camera looking
    /// out of the hand.
    #[test]
    fn out_of_the_arm_points_from_the_wrist_to_the_camera_link() {
        let oscar6 = ArmModel::oscar6();
        let unturned = Isometry3::identity();
        assert_eq!(
            out_of_arm(&oscar6, &unturned).map(|(_, axis)| axis),
            Some("z")
        );
    }
}
