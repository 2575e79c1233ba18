//! What a run's start needs, checked before its folder is made: targets above the floor and
//! (enough of them) outside the obstacles, and pre-learning poses free of contact from which
//! the camera sees the object. A run that fails one of these would learn nothing.

use crate::camera::{Camera, NotSeen};
use crate::control::{prelearning_moves, PrelearnMove};
use crate::experiment::setup::build_camera;
use crate::experiment::setup::preflight::{kinematic_simulator, solved_targets};
use crate::experiment::{Config, PreflightError, MIN_REACHABLE_SHARE, REACH_SAMPLES};
use crate::robot::{ArmModel, ReachSpace, RobotError, Simulator};
use crate::units::M_PER_CM;
use nalgebra::Point3;

/// How far (m) the lowest target's bottom may lie under the floor: rounding only.
const FLOOR_TOLERANCE: f64 = 1e-9;
/// Pre-learning moves (of 8) that must be possible: with fewer the learner starts from
/// almost nothing, and a run refuses to start.
const MIN_PRELEARNING_MOVES: usize = 4;

/// What pre-learning found wrong.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum PrelearningFault {
    /// A start pose puts the arm in contact.
    #[error("its start pose is refused: {0}")]
    StartInContact(RobotError),
    /// A contact stops its move.
    #[error("its move is stopped by a contact (the floor, an obstacle or another link)")]
    MoveStopped,
    /// The camera does not see the object at its start.
    #[error("the camera does not see the object from its start ({0})")]
    NotSeen(NotSeen),
}

/// Checks the targets of `reach` against the floor and obstacles, and the pre-learning
/// moves, on the config's arm and camera (on the kinematic simulator: the same contact
/// rules as the dynamic one).
pub(in crate::experiment) fn check_start(
    config: &Config,
    model: &ArmModel,
    reach: &ReachSpace,
) -> Result<(), PreflightError> {
    let mut sim = kinematic_simulator(config, model);
    let camera = build_camera(config);
    check_targets_above_floor(config, camera.as_ref(), reach)?;
    check_targets_free(sim.as_ref(), camera.as_ref(), reach)?;
    check_prelearning(sim.as_mut(), camera.as_ref(), reach)
}

/// The lowest targets' bottom (the reach space's floor less the camera's standoff and the
/// object's radius) must not lie under the floor.
fn check_targets_above_floor(
    config: &Config,
    camera: &dyn Camera,
    reach: &ReachSpace,
) -> Result<(), PreflightError> {
    let bottom = reach.z_min - camera.model().object_bottom_below();
    let floor = config.floor_z * M_PER_CM;
    if bottom + FLOOR_TOLERANCE < floor {
        return Err(PreflightError::TargetsUnderFloor {
            bottom_cm: bottom / M_PER_CM,
            floor_cm: config.floor_z,
        });
    }
    Ok(())
}

/// Enough of the reach-space targets the arm reaches must lie outside every obstacle.
fn check_targets_free(
    sim: &dyn Simulator,
    camera: &dyn Camera,
    reach: &ReachSpace,
) -> Result<(), PreflightError> {
    if sim.obstacles().is_empty() {
        return Ok(());
    }
    let radius = camera.model().object_radius;
    let (mut reached, mut inside) = (0, 0);
    for (goal, _) in solved_targets(sim.model(), reach, REACH_SAMPLES) {
        reached += 1;
        let object = camera.model().object_at_goal(&goal);
        inside += usize::from(
            sim.obstacles()
                .iter()
                .any(|o| o.overlaps_ball(&object, radius)),
        );
    }
    if ((reached - inside) as f64) < MIN_REACHABLE_SHARE * reached as f64 {
        return Err(PreflightError::TargetsInObstacles { inside, reached });
    }
    Ok(())
}

/// The camera must reach the pre-learning goal looking down, and at least
/// [`MIN_PRELEARNING_MOVES`] of the pre-learning moves must start free of contact, see the
/// object and not be stopped.
fn check_prelearning(
    sim: &mut dyn Simulator,
    camera: &dyn Camera,
    reach: &ReachSpace,
) -> Result<(), PreflightError> {
    let Some((object, moves)) = prelearning_moves(sim.model(), camera.model(), reach) else {
        let goal = reach.prelearning_goal() / M_PER_CM;
        return Err(PreflightError::NoPrelearningPose {
            goal_cm: goal.coords.into(),
        });
    };
    let mut first_fault = None;
    let mut made = 0;
    for (index, step) in moves.iter().enumerate() {
        match prelearning_fault(sim, camera, &object, step) {
            None => made += 1,
            Some(fault) => {
                first_fault.get_or_insert((index + 1, fault));
            }
        }
    }
    match first_fault {
        Some((number, fault)) if made < MIN_PRELEARNING_MOVES => Err(PreflightError::Prelearning {
            made,
            moves: moves.len(),
            number,
            fault,
        }),
        _ => Ok(()),
    }
}

/// What keeps the pre-learning move `step` from being made as it must, if anything.
fn prelearning_fault(
    sim: &mut dyn Simulator,
    camera: &dyn Camera,
    object: &Point3<f64>,
    step: &PrelearnMove,
) -> Option<PrelearningFault> {
    if let Err(e) = sim.place(&step.start) {
        return Some(PrelearningFault::StartInContact(e));
    }
    if let Err(e) = camera.read_in(&sim.camera_pose(), object, &sim.world()) {
        return Some(PrelearningFault::NotSeen(e));
    }
    sim.execute(&step.delta)
        .stopped_by_contact
        .then_some(PrelearningFault::MoveStopped)
}
