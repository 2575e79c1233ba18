//! The dynamic simulator behind the [`Simulator`] trait. A kinematic simulator of the same
//! model plans every move (where a joint limit stops it, the wrist angle, link and camera
//! changes); the multibody then follows the plan tick by tick and settles.
//!
//! How it moves, and why (the measured figures are in docs/DYNAMIC.md, printed by
//! `cargo bench --bench dynamic`; they drift, so none are copied here):
//! - A move's trapezoidal profile (`robot_speed`, `robot_accel`) is sampled every `dt`
//!   along the straight joint-space line; each tick sends every servo the set-point, its
//!   speed and its acceleration (velocity and acceleration feed-forward), the wrist joints
//!   from the model's wrist solution (θ5 on the OSCAR-6, θ4 = θ6 = 0). After
//!   the profile the arm steps until every joint is within `settle_position_tol` of its
//!   set-point and slower than `settle_speed_tol`, or `settle_timeout` passes (reported in
//!   the move's [`MoveReport`] and counted, not fatal).
//! - Two engines (`engine`). `rk4` (the default: it follows MuJoCo closest): the servos'
//!   law (servo_law.rs) is per joint a spring and damper toward the set-point taken at
//!   the tick's end (stable at the stiff default gains), the set-point's acceleration fed
//!   forward, made torques through the arm's mass matrix (so one gain pair suits a 25 kg
//!   column and a 0.8 kg flange), plus the whole bias of the equations of motion at the
//!   set-point (weight, Coriolis and centrifugal torques, the joints' damping), which
//!   carries the arm as a model-based industrial controller does; all bounded by the
//!   joints' URDF efforts and held over the tick. Each tick integrates the arm's
//!   joint-space equations (joint_space.rs) by one classical fourth-order Runge–Kutta step
//!   (integrator.rs); Rapier places the bodies and looks for contacts. The joints' dry
//!   friction is fed forward by the servos in the direction they turn each joint and
//!   solved with the joints' equations over the tick (dry_friction.rs). While a link
//!   is near something, Rapier steps the tick itself under the same torques, its contact
//!   and friction constraints acting (first order, in 1 ms sub-ticks with at least 4
//!   `solver_iterations`, Rapier's contacts found anew at every step). `rapier` (motors.rs): Rapier's multibody integrator
//!   steps every tick (`rapier_substeps` steps of it), each joint driven by a Rapier joint
//!   motor toward the set-point with the same gains, the set-point's inverse dynamics fed
//!   forward as joint torques; Rapier's joint limits and contacts act.
//!   Either way set-points are clamped to the limits (a command past a limit stops at it,
//!   exactly where the kinematic simulator stops), and a joint turning faster than its
//!   URDF velocity limit is counted as a fault (faults.rs).
//! - Defaults: `dt` 5 ms (200 Hz), stiffness 400,000/s² and damping 1265/s (a critically
//!   damped 100 Hz servo). With the joints' damping the URDF's (zero, not Rapier's default
//!   0.1 N·m·s/rad), the 100 Hz servo with acceleration feed-forward settles within a few
//!   ticks of a move's profile.
//! - f64 (rapier3d-f64): the camera must match the kinematic model to 0.05 mm over a
//!   1.2 m arm. A probe of Rapier 0.36 (shared/notes) found f32's rounding a visible part
//!   of that budget and f32 unstable with stiff motors, for a step only slightly dearer in
//!   f64: f64 keeps the servo error, not rounding, as the only gap, and identical inputs
//!   give bit-identical runs.
//! - The world: a floor at `floor_z` and contacts between links that are neither
//!   neighbours nor touching at the zero pose (`contacts.rs`). The plan already stops a
//!   move where a link or the camera would go below the floor (the kinematic rule); a
//!   contact deeper than 0.5 mm during a move, or one that holds the arm back from its
//!   set-point (a link within 1 mm of something, a joint 0.1° behind), stops it where the
//!   arm is, reported and
//!   counted. Each body has one massless compound collider of its URDF shapes, which
//!   follows a stretched link; the camera sees a body's collision meshes as their own
//!   triangles (built with the arm), the contacts as their hulls. The camera link is merged into the last body; turning the
//!   camera turns the model's mount, not its collider.

use super::body_parts::body_parts;
use super::builder::{joint_frame, Arm};
use super::colliders::contact_compound;
use super::convert::{to_isometry, to_pose};
use super::faults::SpeedFault;
use super::inertia::Inertial;
use super::seen::compound;
use super::settings::DynamicSettings;
use crate::robot::{
    ArmModel, Controlled, Joints, KinematicSim, MoveReport, Obstacle, RobotError, SetPointTracker,
    SimWork, Simulator, WorldView,
};
use nalgebra::Isometry3;
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::Arc;

/// What a dynamic simulator has done so far; shared, so it stays readable after the
/// simulator is handed to a trial loop.
#[derive(Debug, Default)]
pub struct SimCounters {
    pub(super) steps: AtomicU64,
    pub(super) moves: AtomicU64,
    pub(super) settle_timeouts: AtomicU64,
    pub(super) contact_stops: AtomicU64,
    pub(super) settle_steps: AtomicU64,
    pub(super) speed_faults: AtomicU64,
}

impl SimCounters {
    /// Physics steps taken (moves, placing and settling).
    pub fn steps(&self) -> u64 {
        self.steps.load(Ordering::Relaxed)
    }

    /// Moves executed.
    pub fn moves(&self) -> u64 {
        self.moves.load(Ordering::Relaxed)
    }

    /// Moves, placings and link changes after which the arm had not settled in time.
    pub fn settle_timeouts(&self) -> u64 {
        self.settle_timeouts.load(Ordering::Relaxed)
    }

    /// Physics steps spent settling (after profiles, placings and link changes).
    pub fn settle_steps(&self) -> u64 {
        self.settle_steps.load(Ordering::Relaxed)
    }

    /// Moves a contact stopped (the floor, in the plan or in the physics, or another link).
    pub fn contact_stops(&self) -> u64 {
        self.contact_stops.load(Ordering::Relaxed)
    }

    /// Physics steps after which a joint turned faster than its URDF velocity limit.
    pub fn speed_faults(&self) -> u64 {
        self.speed_faults.load(Ordering::Relaxed)
    }

    pub(super) fn count(counter: &AtomicU64) {
        counter.fetch_add(1, Ordering::Relaxed);
    }
}

/// An arm (the OSCAR-6, or any chain of revolute joints) as a Rapier multibody with
/// gravity, joint limits and position servos, stepped by the settings' engine.
#[derive(Debug)]
pub struct DynamicSim {
    /// The set-point: the kinematic simulator's pose is where the servos are sent.
    pub(super) plan: KinematicSim,
    pub(super) arm: Arm,
    pub(super) settings: DynamicSettings,
    pub(super) counters: Arc<SimCounters>,
    /// The joints after every tick since the last drain, when a recording asks for them.
    pub(super) kept_ticks: Option<Vec<Joints>>,
    /// The joints after every tick of the last move, when the poses along moves are kept.
    pub(super) move_ticks: Option<Vec<Joints>>,
    /// The set-point of continuous servoing, while it goes on.
    pub(super) tracker: Option<SetPointTracker>,
    /// The joint furthest beyond its URDF velocity limit after any tick so far.
    pub(super) worst_speed_fault: Option<SpeedFault>,
}

impl DynamicSim {
    /// A simulator of `model`, resting at the pose closest to zero inside the limits (as
    /// the kinematic simulator does). Settings that make no sense (not finite, not
    /// positive) are replaced by their defaults.
    pub fn new(model: ArmModel, settings: DynamicSettings) -> DynamicSim {
        let settings = settings.sanitized();
        let arm = Arm::build(&model, &settings);
        let mut sim = DynamicSim {
            plan: KinematicSim::new(model, settings.moves),
            arm,
            settings,
            counters: Arc::default(),
            kept_ticks: None,
            move_ticks: None,
            tracker: None,
            worst_speed_fault: None,
        };
        let start = sim.plan.joints();
        sim.arm.teleport(&start);
        sim.settle();
        sim
    }

    /// This simulator with `obstacles` standing in its world: solid for the arm (a move
    /// into one stops at contact) and seen by the camera.
    pub fn with_obstacles(mut self, obstacles: Vec<Obstacle>) -> DynamicSim {
        self.arm.add_obstacles(&obstacles);
        self.plan = self.plan.with_obstacles(obstacles);
        self
    }

    /// The simulator's work so far.
    pub fn counters(&self) -> Arc<SimCounters> {
        Arc::clone(&self.counters)
    }

    /// The joint torques (N·m) the gravity feed-forward gives at pose `q`: what holds the
    /// arm's weight there, from the links' mass properties as simulated.
    pub fn holding_torques(&self, q: &Joints) -> Joints {
        self.arm.weight_torques(self.plan.model(), q)
    }

    /// The settings in use.
    pub fn settings(&self) -> &DynamicSettings {
        &self.settings
    }
}

impl Simulator for DynamicSim {
    fn model(&self) -> &ArmModel {
        self.plan.model()
    }

    fn place(&mut self, theta: &Controlled) -> Result<(), RobotError> {
        let q = self.model().check_limits(theta)?;
        self.arm.check_holds(self.model(), &q)?;
        self.end_servoing();
        self.plan.place(theta)?;
        let q = self.plan.joints();
        self.arm.teleport(&q);
        self.settle();
        Ok(())
    }

    fn execute(&mut self, delta: &Controlled) -> MoveReport {
        self.end_servoing();
        if let Some(ticks) = &mut self.move_ticks {
            ticks.clear();
        }
        let start = self.plan.joints();
        let before = self.arm.joints();
        let mut report = self.plan.execute(delta);
        if !delta.iter().all(|v| v.is_finite()) {
            return report;
        }
        SimCounters::count(&self.counters.moves);
        let (steps, touched) = self.follow(&start, &report.executed);
        if touched {
            // Stopped where the contact found the arm: the plan follows.
            let reached = self.model().controlled_of(&self.arm.joints());
            if self.plan.place(&reached).is_ok() {
                report.stopped_by_contact = true;
                report.stopped_by_limit = None;
            }
        }
        if report.stopped_by_contact {
            SimCounters::count(&self.counters.contact_stops);
        }
        let (settled, settle_steps) = self.settle();
        report.settled = settled;
        report.duration = (steps + settle_steps) as f64 * self.settings.dt;
        report.executed = self.model().controlled_of(&(self.arm.joints() - before));
        report
    }

    fn joints(&self) -> Joints {
        self.arm.joints()
    }

    fn camera_pose(&self) -> Isometry3<f64> {
        self.arm.link_pose(self.arm.dof).map_or_else(
            || self.model().camera_pose(&self.joints()),
            |flange| flange * self.model().camera_mount(),
        )
    }

    fn stretch_link(&mut self, link: usize, delta_m: f64) -> Result<(), RobotError> {
        self.end_servoing();
        self.plan.stretch_link(link, delta_m)?;
        let model = self.plan.model();
        let joint = &model.joints()[link];
        let frame = to_pose(&joint_frame(&joint.origin, &joint.axis));
        let (inertial, elements) = body_parts(model, link);
        self.arm.set_joint_frame(link, frame);
        self.arm.set_inertial(link, inertial);
        if let Some(collider) =
            self.arm.colliders[link].and_then(|handle| self.arm.world.colliders.get_mut(handle))
        {
            collider.set_shape(contact_compound(&elements));
        }
        self.arm.seen[link] = (!elements.is_empty()).then(|| compound(&elements));
        self.arm.refresh_reaches(model);
        self.arm.refresh_bodies();
        self.settle();
        Ok(())
    }

    fn rotate_camera(&mut self, angle: f64) {
        self.plan.rotate_camera(angle);
    }

    fn work(&self) -> SimWork {
        let c = &self.counters;
        SimWork {
            moves: c.moves(),
            physics_steps: c.steps(),
            simulated_seconds: c.steps() as f64 * self.settings.dt,
            settle_timeouts: c.settle_timeouts(),
            contact_stops: c.contact_stops(),
            speed_faults: c.speed_faults(),
            worst_speed_fault: self.worst_speed_fault,
        }
    }

    fn tick_seconds(&self) -> Option<f64> {
        Some(self.settings.dt)
    }

    fn servo_toward(&mut self, goal: &Controlled) {
        self.aim(goal);
    }

    fn servo_tick(&mut self) -> bool {
        self.servo_step()
    }

    fn world(&self) -> WorldView<'_> {
        let plan = self.plan.world();
        let colliders = &self.arm.world.colliders;
        WorldView {
            bodies: std::array::from_fn(|k: usize| {
                if k >= self.arm.dof {
                    return None; // the last body carries the camera, behind its lens
                }
                let collider = colliders.get(self.arm.colliders[k]?)?;
                Some((*collider.position(), self.arm.seen[k].as_ref()?))
            }),
            ..plan
        }
    }

    fn obstacles(&self) -> &[Obstacle] {
        self.plan.obstacles()
    }

    fn keep_ticks(&mut self, keep: bool) {
        self.kept_ticks = keep.then(Vec::new);
    }

    fn drain_ticks(&mut self, sink: &mut Vec<Joints>) {
        if let Some(ticks) = &mut self.kept_ticks {
            sink.append(ticks);
        }
    }

    fn keep_move_poses(&mut self, keep: bool) {
        self.move_ticks = keep.then(Vec::new);
    }

    fn move_pose_at(&self, t: f64) -> Option<Joints> {
        let ticks = self.move_ticks.as_ref()?;
        let tick = (t / self.settings.dt).round() as usize;
        ticks
            .get(tick.saturating_sub(1))
            .or_else(|| ticks.last())
            .copied()
    }
}

impl Arm {
    /// The pose of body `k` (1 for joint 1's) in the world, as simulated.
    fn link_pose(&self, k: usize) -> Option<Isometry3<f64>> {
        let body = self.world.bodies.get(*self.bodies.get(k)?)?;
        Some(to_isometry(body.position()))
    }

    /// Gives body `k` (1 for joint 1's) new mass properties, for the gravity feed-forward
    /// too.
    fn set_inertial(&mut self, k: usize, inertial: Inertial) {
        self.inertials[k - 1] = inertial;
        if let Some(body) = self.world.bodies.get_mut(self.bodies[k]) {
            body.set_additional_mass_properties(inertial.mass_properties(), true);
        }
    }

    /// Sets the frame of joint `i` (0-based) in its parent link.
    fn set_joint_frame(&mut self, i: usize, frame: rapier3d_f64::math::Pose) {
        let id = self.link_ids[i];
        if let Some(link) = self
            .world
            .multibody_joints
            .get_multibody_mut(self.multibody)
            .and_then(|mb| mb.link_mut(id))
        {
            link.joint.data.set_local_frame1(frame);
        }
    }
}
