//! What a run checks before it makes its folder: the whole config, every event against the
//! run's trials and the robot, and that the arm (as the URDF and each link event leave it)
//! reaches its reach space with the camera looking down.

use crate::experiment::setup::start_check::PrelearningFault;
use crate::experiment::setup::{build_simulator, reach_space};
use crate::experiment::{Config, ConfigErrorKind, Event, SimKind};
use crate::robot::{
    ArmModel, ContactRule, Controlled, ReachFitFailure, ReachSpace, RobotError, Simulator,
};
use crate::units::M_PER_CM;
use nalgebra::Point3;
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;

/// Reach-space points sampled to tell whether an arm can work there.
pub const REACH_SAMPLES: usize = 1000;
/// Fewer reachable samples than this share refuse the arm: trials would draw targets and
/// starts from a sliver of the reach space (or none) and the learner would learn nothing.
pub const MIN_REACHABLE_SHARE: f64 = 0.25;
/// The sampling's own seed, apart from the run's, so checking draws nothing from the run.
const REACH_SEED: u64 = 0x0e7e_4a2d;

/// Why a run cannot start.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum PreflightError {
    /// The config (with the command line's settings) breaks a rule.
    #[error(transparent)]
    Config(#[from] ConfigErrorKind),
    /// An event the robot cannot undergo (a link left ≤ 1 cm long).
    #[error("event {event}: {source}")]
    Event {
        /// The event.
        event: Event,
        /// Why the robot cannot undergo it.
        source: RobotError,
    },
    /// `reach_space auto` and no half annulus, of the study's shape or another, fits what
    /// the arm reaches.
    #[error("reach_space auto: no half annulus, of the study's shape or of others, fits inside what this arm reaches with the camera looking down above the floor: {0}")]
    NoReachSpace(ReachFitFailure),
    /// The lowest targets' bottom lies under the floor.
    #[error("floor_z {floor_cm} cm lies above the lowest targets' bottom ({bottom_cm:.2} cm: reach_space's lowest camera height less the camera's standoff and the object's radius): those targets would be under the floor")]
    TargetsUnderFloor {
        /// The lowest targets' bottom (cm).
        bottom_cm: f64,
        /// The floor (cm).
        floor_cm: f64,
    },
    /// Too many targets lie inside an obstacle.
    #[error(
        "obstacle: {inside} of {reached} sampled targets the arm reaches lie inside an obstacle (at most {:.0}% may)",
        (1.0 - MIN_REACHABLE_SHARE) * 100.0
    )]
    TargetsInObstacles {
        /// Targets inside an obstacle.
        inside: usize,
        /// Targets the arm reaches.
        reached: usize,
    },
    /// Too few of the pre-learning moves (made before trial 1 around the middle of the
    /// reach space) can be made.
    #[error("only {made} of the {moves} pre-learning moves can be made (at least half must be); move {number}: {fault} (obstacle, floor_z, camera_offset, camera_link)")]
    Prelearning {
        /// Moves that can be made.
        made: usize,
        /// Moves in all.
        moves: usize,
        /// The first move that cannot (1-based).
        number: usize,
        /// What is wrong with it.
        fault: PrelearningFault,
    },
    /// The camera cannot reach the pre-learning goal (the middle of the reach space)
    /// looking down: no pre-learning move can be made, and a learner that starts with no
    /// pattern answers zero moves.
    #[error("no pre-learning move can be made: the camera cannot reach the middle of the reach space ({:.1}, {:.1}, {:.1} cm) looking down, and a learner given no pattern answers zero moves: it would learn nothing (reach_space, learned_joints, camera_mount, camera_link)", .goal_cm[0], .goal_cm[1], .goal_cm[2])]
    NoPrelearningPose {
        /// The pre-learning goal: where the camera ends each pre-learning move (cm).
        goal_cm: [f64; 3],
    },
    /// The arm cannot reach (enough of) its reach space.
    #[error(
        "{reachable} of {sampled} sampled reach-space points are reachable by this arm with the camera looking down{} (at least {:.0}% are needed)",
        .after.map_or(String::new(), |e| format!(" after event {e}")),
        MIN_REACHABLE_SHARE * 100.0
    )]
    Unreachable {
        /// Points reached.
        reachable: usize,
        /// Points sampled.
        sampled: usize,
        /// The event that left the arm so, if one did.
        after: Option<Event>,
    },
}

/// Moves between two reached points of `reach`, and how many of them a contact (the floor,
/// an obstacle, another link) stopped: `moves` pairs of points drawn with a fixed seed, each
/// move made on the config's kinematic simulator from the first point's pose.
pub fn contact_stopped_moves(
    config: &Config,
    model: &ArmModel,
    reach: &ReachSpace,
    moves: usize,
) -> (usize, usize) {
    let mut sim = kinematic_simulator(config, model);
    let mut rng = ChaCha8Rng::seed_from_u64(REACH_SEED);
    let (mut made, mut stopped) = (0, 0);
    for _ in 0..moves {
        let (a, b) = (reach.sample(&mut rng), reach.sample(&mut rng));
        let (Ok(from), Ok(to)) = (
            model.solve_camera_position(&a),
            model.solve_camera_position(&b),
        ) else {
            continue;
        };
        if sim.place(&from).is_err() {
            continue;
        }
        made += 1;
        stopped += usize::from(sim.execute(&(to - from)).stopped_by_contact);
    }
    (made, stopped)
}

/// The config's simulator made kinematic (the dynamic one shares its contact rules), moving
/// `model`: what the checks before a run try moves and poses on.
pub(in crate::experiment) fn kinematic_simulator(
    config: &Config,
    model: &ArmModel,
) -> Box<dyn Simulator> {
    let kinematic = Config {
        sim: SimKind::Kinematic,
        ..config.clone()
    };
    build_simulator(&kinematic, model.clone())
}

/// The reach-space points (of `samples` drawn with a fixed seed) at which `model` puts its
/// camera with every joint inside its limits, elbow up, looking down, with those angles.
pub(in crate::experiment) fn solved_targets<'a>(
    model: &'a ArmModel,
    reach: &'a ReachSpace,
    samples: usize,
) -> impl Iterator<Item = (Point3<f64>, Controlled)> + 'a {
    let mut rng = ChaCha8Rng::seed_from_u64(REACH_SEED);
    (0..samples).filter_map(move |_| {
        let point = reach.sample(&mut rng);
        model
            .solve_camera_position(&point)
            .ok()
            .map(|theta| (point, theta))
    })
}

/// Reach-space points (of `samples` drawn with a fixed seed) at which `model` puts its
/// camera with every joint inside its limits, elbow up, looking down.
pub fn reachable_points(model: &ArmModel, reach: &ReachSpace, samples: usize) -> usize {
    solved_targets(model, reach, samples).count()
}

/// Reach-space points (of `samples` drawn with a fixed seed, as [`reachable_points`]
/// draws them) that `model` reaches looking down, and how many of those poses bring a link
/// within [`CONTACT_MARGIN`](crate::robot::CONTACT_MARGIN) of the config's floor or of
/// another link.
pub fn target_poses_in_contact(
    config: &Config,
    model: &ArmModel,
    reach: &ReachSpace,
    samples: usize,
) -> (usize, usize) {
    let rule = ContactRule::new(model, config.floor_z * M_PER_CM);
    let (mut reached, mut touching) = (0, 0);
    for (_, theta) in solved_targets(model, reach, samples) {
        reached += 1;
        touching += usize::from(rule.touch(model, &model.pose_of(&theta)).is_some());
    }
    (reached, touching)
}

/// Checks `config`, `events` (sorted by trial) and the arm's reach before a run starts, and
/// returns the run's reach space (given, or fitted to the arm: `model` then keeps to the
/// branch of its solutions the space was fitted on). The run's start is checked once the
/// entries sized to that space are (`check_start`).
pub fn preflight(
    config: &Config,
    model: &mut ArmModel,
    events: &[Event],
) -> Result<ReachSpace, PreflightError> {
    config.check()?;
    if let Some(late) = events.iter().find(|e| e.trial() > config.trials) {
        return Err(ConfigErrorKind::EventAfterLastTrial {
            name: format!("event {late}"),
            trial: late.trial(),
            trials: config.trials,
        }
        .into());
    }
    let reach = reach_space(config, model).map_err(PreflightError::NoReachSpace)?;
    check_reach(model, &reach, None)?;
    let mut changed = model.clone();
    for event in events {
        if let Event::Elongate { link, cm, .. } = *event {
            changed
                .stretch_link(link, cm * M_PER_CM)
                .map_err(|source| PreflightError::Event {
                    event: *event,
                    source,
                })?;
            check_reach(&changed, &reach, Some(*event))?;
        }
    }
    Ok(reach)
}

fn check_reach(
    model: &ArmModel,
    reach: &ReachSpace,
    after: Option<Event>,
) -> Result<(), PreflightError> {
    let reachable = reachable_points(model, reach, REACH_SAMPLES);
    if (reachable as f64) < MIN_REACHABLE_SHARE * REACH_SAMPLES as f64 {
        return Err(PreflightError::Unreachable {
            reachable,
            sampled: REACH_SAMPLES,
            after,
        });
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_oscar6_reaches_every_sampled_point() {
        assert_eq!(
            reachable_points(&ArmModel::oscar6(), &ReachSpace::OSCAR6, 200),
            200
        );
    }

    #[test]
    fn a_link_stretched_out_of_reach_is_refused_at_start() {
        let config = Config::default_config();
        let far = Event::Elongate {
            trial: 10,
            link: 1,
            cm: 1e9,
        };
        let err = preflight(&config, &mut ArmModel::oscar6(), &[far]).unwrap_err();
        assert_eq!(
            err,
            PreflightError::Unreachable {
                reachable: 0,
                sampled: REACH_SAMPLES,
                after: Some(far)
            }
        );
        assert!(err.to_string().starts_with("0 of 1000 sampled"), "{err}");
        let gone = Event::Elongate {
            trial: 10,
            link: 2,
            cm: -60.0,
        };
        let err = preflight(&config, &mut ArmModel::oscar6(), &[gone]).unwrap_err();
        assert!(matches!(
            err,
            PreflightError::Event {
                source: RobotError::LinkTooShort { link: 2, .. },
                ..
            }
        ));
    }

    #[test]
    fn an_event_after_the_last_trial_is_refused() {
        let mut config = Config::default_config();
        config.trials = 1000;
        let late = Event::Rotate {
            trial: 5000,
            degrees: 30.0,
        };
        let err = preflight(&config, &mut ArmModel::oscar6(), &[late]).unwrap_err();
        assert!(matches!(
            err,
            PreflightError::Config(ConfigErrorKind::EventAfterLastTrial {
                trial: 5000,
                trials: 1000,
                ..
            })
        ));
    }
}
