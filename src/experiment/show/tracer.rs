//! Watching a replayed run: the simulator and the camera wrapped so that every look the
//! trial loop takes (the pose, the object, the reading) and every move (its duration and,
//! on the dynamic simulator, its physics ticks) is written down. The wrappers pass every
//! call through unchanged, so the replay does exactly what the run did.

use crate::camera::{Camera, CameraModel, NotSeen, Scene};
use crate::robot::{
    ArmModel, Controlled, Joints, MoveReport, Obstacle, RobotError, SimWork, Simulator, WorldView,
};
use nalgebra::{Isometry3, Point3, Vector3};
use std::cell::RefCell;
use std::rc::Rc;

/// One look of the camera.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Look {
    /// All six joint angles when the camera looked (rad).
    pub joints: Joints,
    /// The camera frame in the world.
    pub camera_pose: Isometry3<f64>,
    /// The object's centre (world, m).
    pub object: Point3<f64>,
    /// The reading, or why the object was not seen.
    pub reading: Result<Vector3<f64>, NotSeen>,
    /// Simulated time of the moves since the last placing (s).
    pub sim_time: f64,
}

/// What has been seen since the log was last cleared.
#[derive(Debug, Default)]
pub(super) struct WatchLog {
    /// The camera's looks, in order.
    pub(super) looks: Vec<Look>,
    /// Joint angles of every physics tick since the last placing, with their simulated
    /// time (s); empty on the kinematic simulator.
    pub ticks: Vec<(f64, Joints)>,
    joints: Joints,
    sim_time: f64,
    tick_buffer: Vec<Joints>,
}

impl WatchLog {
    /// Forgets everything seen so far (every placing starts afresh: the last placing of a
    /// trial puts the arm at its start pose).
    pub(super) fn clear(&mut self) {
        self.looks.clear();
        self.ticks.clear();
        self.sim_time = 0.0;
    }
}

/// The log both wrappers write to.
pub(super) type SharedLog = Rc<RefCell<WatchLog>>;

/// A simulator that notes its joints after every placing and move.
#[derive(Debug)]
pub(super) struct WatchedSim {
    inner: Box<dyn Simulator>,
    log: SharedLog,
}

impl WatchedSim {
    /// Wraps `inner`, writing to `log`.
    pub(super) fn new(inner: Box<dyn Simulator>, log: SharedLog) -> WatchedSim {
        log.borrow_mut().joints = inner.joints();
        WatchedSim { inner, log }
    }

    fn note_joints(&mut self) {
        self.log.borrow_mut().joints = self.inner.joints();
    }
}

impl Simulator for WatchedSim {
    fn model(&self) -> &ArmModel {
        self.inner.model()
    }

    fn place(&mut self, theta: &Controlled) -> Result<(), RobotError> {
        let placed = self.inner.place(theta);
        let mut log = self.log.borrow_mut();
        self.inner.drain_ticks(&mut log.tick_buffer);
        log.tick_buffer.clear();
        log.clear();
        log.joints = self.inner.joints();
        placed
    }

    fn execute(&mut self, delta: &Controlled) -> MoveReport {
        let report = self.inner.execute(delta);
        let mut log = self.log.borrow_mut();
        let mut ticks = std::mem::take(&mut log.tick_buffer);
        self.inner.drain_ticks(&mut ticks);
        let dt = report.duration / ticks.len().max(1) as f64;
        let start = log.sim_time;
        for (k, joints) in ticks.drain(..).enumerate() {
            log.ticks.push((start + (k + 1) as f64 * dt, joints));
        }
        log.tick_buffer = ticks;
        log.sim_time += report.duration;
        drop(log);
        self.note_joints();
        report
    }

    fn joints(&self) -> Joints {
        self.inner.joints()
    }

    fn camera_pose(&self) -> Isometry3<f64> {
        self.inner.camera_pose()
    }

    fn stretch_link(&mut self, link: usize, delta_m: f64) -> Result<(), RobotError> {
        let stretched = self.inner.stretch_link(link, delta_m);
        self.inner
            .drain_ticks(&mut self.log.borrow_mut().tick_buffer);
        self.log.borrow_mut().tick_buffer.clear();
        self.note_joints();
        stretched
    }

    fn rotate_camera(&mut self, angle: f64) {
        self.inner.rotate_camera(angle);
        self.note_joints();
    }

    fn work(&self) -> SimWork {
        self.inner.work()
    }

    fn world(&self) -> WorldView<'_> {
        self.inner.world()
    }

    fn obstacles(&self) -> &[Obstacle] {
        self.inner.obstacles()
    }

    fn keep_ticks(&mut self, keep: bool) {
        self.inner.keep_ticks(keep);
    }

    fn tick_seconds(&self) -> Option<f64> {
        self.inner.tick_seconds()
    }

    fn servo_toward(&mut self, goal: &Controlled) {
        self.inner.servo_toward(goal);
    }

    fn servo_tick(&mut self) -> bool {
        let stopped = self.inner.servo_tick();
        let dt = self.inner.tick_seconds().unwrap_or(0.0);
        let mut log = self.log.borrow_mut();
        let mut ticks = std::mem::take(&mut log.tick_buffer);
        self.inner.drain_ticks(&mut ticks);
        log.sim_time += dt;
        let time = log.sim_time;
        log.ticks
            .extend(ticks.drain(..).map(|joints| (time, joints)));
        log.tick_buffer = ticks;
        drop(log);
        self.note_joints();
        stopped
    }
}

/// A camera that notes every look it takes.
#[derive(Debug)]
pub(super) struct WatchedCamera {
    inner: Box<dyn Camera>,
    log: SharedLog,
}

impl WatchedCamera {
    /// Wraps `inner`, writing to `log`.
    pub(super) fn new(inner: Box<dyn Camera>, log: SharedLog) -> WatchedCamera {
        WatchedCamera { inner, log }
    }
}

impl Camera for WatchedCamera {
    fn read_local(&self, p: &Vector3<f64>) -> Result<Vector3<f64>, NotSeen> {
        self.inner.read_local(p)
    }

    fn model(&self) -> &CameraModel {
        self.inner.model()
    }

    fn read_in(
        &self,
        camera_pose: &Isometry3<f64>,
        object: &Point3<f64>,
        scene: &dyn Scene,
    ) -> Result<Vector3<f64>, NotSeen> {
        let reading = self.inner.read_in(camera_pose, object, scene);
        let mut log = self.log.borrow_mut();
        let (joints, sim_time) = (log.joints, log.sim_time);
        log.looks.push(Look {
            joints,
            camera_pose: *camera_pose,
            object: *object,
            reading,
            sim_time,
        });
        reading
    }
}
