//! The kinematic simulator: forward kinematics straight from the URDF, no dynamics. A move
//! is instant in wall time; its simulated duration follows the trapezoidal profile.

use super::motion::{last_holding, limit_stop_fraction, TrapezoidProfile};
use super::pace::{
    paced_profile, pieces, turn_rates, COARSE_MARGIN, COARSE_PIECES, SAMPLING_SLACK,
};
use super::wrist_gains::WristGains;
use crate::robot::contact::clearance::ArmGeometry;
use crate::robot::contact::collision::{body_elements, MoveStart};
use crate::robot::contact::floor::FloorRule;
use crate::robot::contact::world::{Obstacle, WorldView, SEEN_BODIES};
use crate::robot::dynamic::compound;
use crate::robot::Joints;
use crate::robot::RobotError;
use crate::robot::{ArmModel, Controlled, Frames};
use crate::robot::{MoveReport, MoveSettings, SimWork, Simulator};
use nalgebra::{Isometry3, Vector3};
use rapier3d_f64::parry::shape::SharedShape;

/// An arm moved by forward kinematics alone.
#[derive(Debug, Clone)]
pub struct KinematicSim {
    model: ArmModel,
    settings: MoveSettings,
    /// The arm as it is now: its angles, pose and link frames, where the next move starts.
    here: MoveStart,
    /// A lower bound (m) on the distance between any two bodies that may touch, with the
    /// arm as it is now; 0 when none is known.
    nearest: f64,
    /// Each link's collision elements and how far the arm reaches beyond each joint.
    floor: FloorRule,
    /// The bodies a camera sees (the base and every joint's body but the last) as parry
    /// shapes, for [`WorldView`].
    seen_shapes: [Option<SharedShape>; SEEN_BODIES],
    /// The obstacle boxes in the world.
    obstacles: Vec<Obstacle>,
    /// The bodies for the self-collision and obstacle rule.
    geometry: ArmGeometry,
    /// How the wrist's joints turn with the learned ones.
    gains: WristGains,
    work: SimWork,
    /// The last move's profile in time.
    profile: TrapezoidProfile,
    /// The last move, when the poses along moves are kept (for frames taken during them).
    last_move: Option<LastMove>,
    /// Whether the poses along moves are kept.
    keep_moves: bool,
}

/// A move as made, to give the poses along it.
#[derive(Debug, Clone, Copy)]
struct LastMove {
    /// The learned angles and every joint where it began.
    from: Controlled,
    near: Joints,
    /// The move made (rad) and its profile in time.
    executed: Controlled,
    profile: TrapezoidProfile,
}

impl KinematicSim {
    /// A simulator of `model`, resting at the pose closest to zero inside the limits.
    pub fn new(model: ArmModel, settings: MoveSettings) -> KinematicSim {
        let theta = model.controlled_of(&model.rest());
        let here = MoveStart::at(&model, model.pose_of(&theta));
        let mut sim = KinematicSim {
            model,
            settings,
            here,
            nearest: 0.0,
            floor: FloorRule::default(),
            seen_shapes: Default::default(),
            obstacles: Vec::new(),
            geometry: ArmGeometry::default(),
            gains: WristGains::default(),
            work: SimWork::default(),
            profile: TrapezoidProfile::new(0.0, settings.speed, settings.accel),
            last_move: None,
            keep_moves: false,
        };
        sim.refresh_collision();
        sim
    }

    /// This simulator with `obstacles` standing in its world.
    pub fn with_obstacles(mut self, obstacles: Vec<Obstacle>) -> KinematicSim {
        self.obstacles = obstacles;
        self
    }

    /// Takes the collision elements from the model as it is now.
    fn refresh_collision(&mut self) {
        self.floor = FloorRule::new(&self.model);
        self.geometry = ArmGeometry::new(&self.model);
        self.gains = WristGains::new(&self.model);
        let seen = self.model.dof();
        self.seen_shapes = std::array::from_fn(|k| {
            let base;
            let elements = match k {
                _ if k >= seen => return None,
                0 => {
                    base = body_elements(&self.model, 0);
                    &base
                }
                _ => &self.floor.bodies[k - 1],
            };
            (!elements.is_empty()).then(|| compound(elements))
        });
    }

    /// Puts the arm at `theta` (inside the limits).
    fn set_pose(&mut self, theta: Controlled) {
        let pose = self.model.pose_near(&theta, &self.here.pose.joints);
        self.here = MoveStart::at(&self.model, pose);
        self.nearest = 0.0;
    }

    fn limits(&self) -> (Vector3<f64>, Vector3<f64>) {
        let joints = self.model.joints();
        let learned = self.model.learned();
        (
            Vector3::from_fn(|i, _| joints[learned[i]].lower),
            Vector3::from_fn(|i, _| joints[learned[i]].upper),
        )
    }

    /// The profile of a move along `executed` from the arm as it is now: `robot_speed`,
    /// slowed where a joint of the chain, learned or following the wrist's solution, would
    /// turn faster than its URDF velocity limit (pace.rs), the wrist sampled along the line
    /// as the dynamic simulator's set-points follow it (held where it has no solution).
    /// Where the wrist follows the learned joints linearly, the move's exact turns from
    /// the start to `end` (every joint there), grown by what sampling can add
    /// ([`SAMPLING_SLACK`]), may show that no joint comes near its limit: then it runs at
    /// `robot_speed` unsampled. Otherwise a long move is first sampled in
    /// [`COARSE_PIECES`]; where even its rates grown by [`COARSE_MARGIN`] keep every joint
    /// within its limit, it runs at `robot_speed` without the fine sampling.
    fn paced(&self, executed: &Controlled, end: &Joints) -> TrapezoidProfile {
        let distance = executed.amax();
        let unpaced = TrapezoidProfile::new(distance, self.settings.speed, self.settings.accel);
        let limits = || self.model.joints().iter().map(|joint| joint.velocity);
        let profile = |rates: &Joints| {
            paced_profile(
                distance,
                self.settings.speed,
                self.settings.accel,
                rates,
                limits(),
            )
        };
        let start = &self.here.pose.joints;
        if let Some(turns) = self.gains.linear_turns(executed, start, end) {
            if profile(&turns.map(|turn| turn + SAMPLING_SLACK)) == unpaced {
                return unpaced;
            }
        }
        let fine = pieces(distance);
        if fine > COARSE_PIECES {
            let coarse = self.turn_rates_along(executed, COARSE_PIECES) * COARSE_MARGIN;
            if profile(&coarse) == unpaced {
                return unpaced;
            }
        }
        profile(&self.turn_rates_along(executed, fine))
    }

    /// Each joint's fastest turn per whole move along `executed` from the arm as it is now,
    /// sampled in `n` pieces (pace.rs's `turn_rates`).
    fn turn_rates_along(&self, executed: &Controlled, n: usize) -> Joints {
        let start = self.here.pose.joints;
        let mut near = start;
        let learned = self.model.learned();
        turn_rates(&start, n, |s| {
            let pose = self
                .model
                .pose_near(&(self.here.theta + executed * s), &near);
            if pose.wrist_found {
                near = pose.joints;
                return near;
            }
            let held = |j: usize| match learned.contains(&j) {
                true => pose.joints[j],
                false => f64::NAN,
            };
            Joints::from_fn(start.len(), held)
        })
    }

    /// The profile of the last move (the one the dynamic simulator's set-points follow).
    pub(crate) fn last_profile(&self) -> TrapezoidProfile {
        self.profile
    }

    /// The last fraction of the way along `delta` at which the wrist still has a solution
    /// inside its limits, assuming it has at `0` and not at `limit`.
    fn wrist_stop(&self, delta: &Controlled, limit: f64) -> f64 {
        last_holding(0.0, limit, |middle| {
            let pose = self
                .model
                .pose_near(&(self.here.theta + delta * middle), &self.here.pose.joints);
            self.model.wrist_fits(&pose)
        })
    }
}

impl Simulator for KinematicSim {
    fn model(&self) -> &ArmModel {
        &self.model
    }

    fn place(&mut self, theta: &Controlled) -> Result<(), RobotError> {
        // From rest, as the inverse kinematics solves it (moves follow on from here).
        let pose = self.model.pose_of(theta);
        let joints = self.model.check_pose(&pose)?;
        if let Some((link, obstacle)) =
            self.geometry
                .inside_obstacle(&self.model, &joints, &self.obstacles)
        {
            return Err(RobotError::InsideObstacle { link, obstacle });
        }
        self.here = MoveStart::at(&self.model, pose);
        self.nearest = 0.0;
        Ok(())
    }

    fn execute(&mut self, delta: &Controlled) -> MoveReport {
        let mut report = MoveReport {
            commanded: *delta,
            executed: Controlled::zeros(),
            stopped_by_limit: None,
            stopped_by_contact: false,
            duration: 0.0,
            settled: true,
        };
        if !delta.iter().all(|v| v.is_finite()) {
            return report;
        }
        let (lower, upper) = self.limits();
        let theta = self.here.theta;
        let mut fraction = limit_stop_fraction(&theta, delta, &lower, &upper);
        if fraction < 1.0 {
            report.stopped_by_limit = (0..3)
                .find(|&i| {
                    let end = theta[i] + delta[i] * fraction;
                    (end - lower[i]).abs() < 1e-12 || (end - upper[i]).abs() < 1e-12
                })
                .map(|i| self.model.learned()[i]);
        }
        let end = theta + delta * fraction;
        let mut end_pose = self.model.pose_near(&end, &self.here.pose.joints);
        if !self.model.wrist_fits(&end_pose) {
            report.stopped_by_limit = Some(self.model.wrist_joint_at_fault(&end_pose));
            fraction = self.wrist_stop(delta, fraction);
        }
        let sweep = self.gains.sweep(&self.model, &self.here, delta, fraction);
        let floor = self.floor.stop(
            &self.model,
            &self.here,
            &sweep,
            fraction,
            self.settings.floor_z,
        );
        let touch = self.geometry.contact_stop(
            &self.model,
            &self.here,
            &sweep,
            floor.min(fraction),
            &self.obstacles,
            &mut self.nearest,
        );
        if touch < fraction {
            fraction = touch;
            report.stopped_by_limit = None;
            report.stopped_by_contact = true;
            self.work.contact_stops += 1;
        }
        let after = (theta + delta * fraction).sup(&lower).inf(&upper);
        // (Bit for bit: a zero's sign could change the pose's last bits.)
        if after
            .iter()
            .zip(end.iter())
            .any(|(a, b)| a.to_bits() != b.to_bits())
        {
            end_pose = self.model.pose_near(&after, &self.here.pose.joints);
        }
        let near = self.here.pose.joints;
        let executed = after - theta;
        let profile = self.paced(&executed, &end_pose.joints);
        self.here = MoveStart::at(&self.model, end_pose);
        let turns = self.gains.executed_turns(&sweep, &executed, fraction);
        self.nearest = (self.nearest - self.geometry.closing(&turns)).max(0.0);
        report.executed = executed;
        self.profile = profile;
        report.duration = profile.duration();
        if self.keep_moves {
            self.last_move = Some(LastMove {
                from: theta,
                near,
                executed,
                profile,
            });
        }
        self.work.moves += 1;
        self.work.simulated_seconds += report.duration;
        report
    }

    fn joints(&self) -> Joints {
        self.here.pose.joints
    }

    fn camera_pose(&self) -> Isometry3<f64> {
        self.here.pose.camera
    }

    fn stretch_link(&mut self, link: usize, delta_m: f64) -> Result<(), RobotError> {
        self.model.stretch_link(link, delta_m)?;
        self.set_pose(self.here.theta);
        self.refresh_collision();
        Ok(())
    }

    fn rotate_camera(&mut self, angle: f64) {
        if angle.is_finite() {
            self.model.rotate_camera(angle);
            self.set_pose(self.here.theta);
            self.refresh_collision();
        }
    }

    fn work(&self) -> SimWork {
        self.work
    }

    fn world(&self) -> WorldView<'_> {
        self.world_placed(&self.here.pose.frames)
    }

    fn obstacles(&self) -> &[Obstacle] {
        &self.obstacles
    }

    fn keep_move_poses(&mut self, keep: bool) {
        self.keep_moves = keep;
        self.last_move = None;
    }

    fn move_pose_at(&self, t: f64) -> Option<Joints> {
        let last = self.last_move?;
        let theta = last.from + last.executed * last.profile.fraction_at(t);
        Some(self.model.pose_near(&theta, &last.near).joints)
    }
}

impl KinematicSim {
    /// The world as the camera sees it (see [`Simulator::world`]) with the arm at pose `q`.
    pub fn world_at(&self, q: &Joints) -> WorldView<'_> {
        self.world_placed(&self.model.link_frames(q))
    }

    /// The world as the camera sees it with the links placed at `frames`.
    fn world_placed(&self, frames: &Frames) -> WorldView<'_> {
        let poses = std::array::from_fn(|k| match k {
            0 => Isometry3::identity(),
            _ => frames.iter().nth(k - 1).copied().unwrap_or_default(),
        });
        WorldView {
            floor_z: self.settings.floor_z,
            obstacles: &self.obstacles,
            bodies: WorldView::place_bodies(&self.seen_shapes, &poses),
        }
    }
}
