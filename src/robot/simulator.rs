//! The simulator interface: what the trial loop asks of any simulated OSCAR-6, kinematic
//! or dynamic.

use super::model::{ArmModel, Controlled};
use super::{Joints, Obstacle, RobotError, SpeedFault, WorldView, DEFAULT_FLOOR_Z};
use nalgebra::Isometry3;

/// How commanded moves are executed.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MoveSettings {
    /// Top joint speed (rad/s) of the lead joint.
    pub speed: f64,
    /// Joint acceleration (rad/s²) of the lead joint.
    pub accel: f64,
    /// Height of the floor (m, world frame): a move stops where a link or the camera
    /// would go below it; default [`DEFAULT_FLOOR_Z`], `-inf` for none.
    pub floor_z: f64,
}

impl MoveSettings {
    /// Settings from the config's `robot_speed` (°/s) and `robot_accel` (°/s²), with the
    /// default floor.
    pub fn from_degrees(speed_deg: f64, accel_deg: f64) -> MoveSettings {
        MoveSettings {
            speed: speed_deg.to_radians(),
            accel: accel_deg.to_radians(),
            floor_z: DEFAULT_FLOOR_Z,
        }
    }

    /// These settings with the floor at `floor_z` (m).
    pub fn with_floor(self, floor_z: f64) -> MoveSettings {
        MoveSettings { floor_z, ..self }
    }
}

impl Default for MoveSettings {
    /// The shipped configs' moves: 90°/s top speed, 180°/s² acceleration, the default
    /// floor.
    fn default() -> Self {
        MoveSettings::from_degrees(90.0, 180.0)
    }
}

/// What happened during a commanded move.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MoveReport {
    /// The commanded change of θ1..θ3 (rad).
    pub commanded: Controlled,
    /// The change the joint sensors read after the move (rad).
    pub executed: Controlled,
    /// The 0-based joint whose limit stopped the move early, if one did.
    pub stopped_by_limit: Option<usize>,
    /// True when the move stopped early because a link or the camera touched the floor,
    /// an obstacle or another link.
    pub stopped_by_contact: bool,
    /// Simulated duration of the move (s), settling included.
    pub duration: f64,
    /// False when a dynamic move timed out before the arm settled.
    pub settled: bool,
}

/// What a simulator has done so far (the kinematic one takes no physics steps).
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct SimWork {
    /// Moves executed.
    pub moves: u64,
    /// Physics steps taken (moves, placing, settling).
    pub physics_steps: u64,
    /// Simulated time (s) of the moves, settling included.
    pub simulated_seconds: f64,
    /// Moves, placings and link changes after which the arm had not settled in time.
    pub settle_timeouts: u64,
    /// Moves stopped by a contact (the floor, an obstacle or another link).
    pub contact_stops: u64,
    /// Physics steps after which a joint turned faster than its URDF velocity limit.
    pub speed_faults: u64,
    /// The joint furthest beyond its velocity limit in any of them.
    pub worst_speed_fault: Option<SpeedFault>,
}

/// A simulated OSCAR-6 with a camera in its end-effector.
pub trait Simulator: std::fmt::Debug {
    /// The robot as it is now (with any stretched link or turned camera).
    fn model(&self) -> &ArmModel;

    /// Puts the arm at a controlled pose at once (untimed, as between trials); θ5 keeps the
    /// camera vertical. Fails when the pose is outside the joint limits.
    fn place(&mut self, theta: &Controlled) -> Result<(), RobotError>;

    /// Moves θ1..θ3 by `delta` (rad) along a straight line in joint space under the
    /// trapezoidal profile, stopping at the first joint limit met. Never fails: a
    /// non-finite command is not executed.
    fn execute(&mut self, delta: &Controlled) -> MoveReport;

    /// The joint sensors: all six angles (rad).
    fn joints(&self) -> Joints;

    /// The camera frame's pose in the world.
    fn camera_pose(&self) -> Isometry3<f64>;

    /// Stretches (positive) or shortens link 1, 2 or 3 by `delta_m` metres.
    fn stretch_link(&mut self, link: usize, delta_m: f64) -> Result<(), RobotError>;

    /// Turns the camera about its optical axis by `angle` (rad).
    fn rotate_camera(&mut self, angle: f64);

    /// What the simulator has done so far.
    fn work(&self) -> SimWork;

    /// The simulator's clock tick (s): the physics step of a simulator that moves in
    /// ticks (the dynamic one), in which continuous servoing and a camera's frame times
    /// are counted; `None` for one without a clock (the kinematic one: its moves take no
    /// steps).
    fn tick_seconds(&self) -> Option<f64> {
        None
    }

    /// Continuous servoing: from now on the servos' set-point heads for θ1..θ3 = `goal`
    /// (rad) from where it is, keeping its velocity, under the moves' speed and
    /// acceleration limits and without settling first; the goal is cut where a straight
    /// move from the set-point would meet a joint limit or a contact. A simulator without
    /// a clock ignores it.
    fn servo_toward(&mut self, _goal: &Controlled) {}

    /// One clock tick of continuous servoing (the arm held still once its set-point is at
    /// the goal); true when a contact stopped the arm, which is then held where it is.
    /// A simulator without a clock does nothing.
    fn servo_tick(&mut self) -> bool {
        false
    }

    /// The world around the arm as it is now, as the camera sees it: the floor, the
    /// obstacles and the arm's bodies (but link 6 and the camera) where they are.
    fn world(&self) -> WorldView<'_>;

    /// The obstacles standing in the world: [`world`](Self::world)'s, without placing the
    /// arm's bodies.
    fn obstacles(&self) -> &[Obstacle];

    /// Starts (`true`) or stops keeping the joint angles of every physics tick, for a
    /// recording of the run; a simulator without physics ticks keeps none.
    fn keep_ticks(&mut self, _keep: bool) {}

    /// Moves the joint angles of the ticks kept since the last call into `sink`, oldest
    /// first (one per `dt`).
    fn drain_ticks(&mut self, _sink: &mut Vec<Joints>) {}

    /// Starts (`true`) or stops keeping the poses along each move (only the last move's),
    /// for the frames a camera takes while the arm moves.
    fn keep_move_poses(&mut self, _keep: bool) {}

    /// Every joint's angle `t` seconds after the last move (or pre-learning move) began —
    /// the kinematic simulator along the move's trapezoidal profile, the dynamic one at
    /// its physics tick then — the pose it ended at from its end on; `None` when move
    /// poses are not kept or no move was made since.
    fn move_pose_at(&self, _t: f64) -> Option<Joints> {
        None
    }
}
