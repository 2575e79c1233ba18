//! One trial: draw a target and a start pose from which the object is seen, then feedback
//! steps `Δθ = N(c, θ2, θ3)` until the camera is within ε of the target (after at least
//! `min_feedback_steps` steps) or `feedback_steps` are used; the trial's poses are then
//! learned. This file holds the loop itself and what it observes; `stepwise.rs` takes a
//! trial in pieces, `whole_trial.rs` runs one through, `draws.rs` draws its target and
//! start, `outcome.rs` says what it did.

mod draws;
mod outcome;
mod stepwise;
mod whole_trial;

pub use outcome::{Failure, TrialOutcome, MAX_RECORDED_STEPS};

use super::clocked::FrameQueue;
use super::feedback::{ActiveTrial, TrialEnd};
use super::move_frames::MoveFrames;
use super::sensors::{NoisySensors, SensorNoise};
use super::timing::{CameraTiming, FrameClock};
use crate::camera::{Camera, NotSeen};
use crate::learn::Observation;
use crate::learn::{LearnError, Learner};
use crate::robot::{ReachSpace, Simulator};
use crate::units::MM_PER_M;
use nalgebra::{Point3, Vector3};
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;

/// The control loop's settings.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TrialSettings {
    /// At most this many feedback steps.
    pub feedback_steps: usize,
    /// At least this many feedback steps before reaching ε ends the trial.
    pub min_feedback_steps: usize,
    /// ε: distance to the target (m) at which the trial may stop.
    pub epsilon: f64,
    /// The noise of the camera's and the encoders' reports.
    pub noise: SensorNoise,
    /// When the camera delivers frames, and whether the arm settles between them.
    pub timing: CameraTiming,
    /// The frames taken during moves that are learned too (`None`: only the poses at
    /// which moves ended, the study's; see [`MoveFrames`]).
    pub move_frames: Option<MoveFrames>,
}

/// What a frame shows: the pose and reading as the sensors report them, or why the object
/// is not seen with the joint angles (θ1..θ3, degrees) as they were.
pub(super) type Sight = Result<Observation, (NotSeen, Vector3<f64>)>;

/// The control loop over a simulator and camera, with the run's random generator.
#[derive(Debug)]
pub struct TrialLoop {
    pub(super) sim: Box<dyn Simulator>,
    pub(super) camera: Box<dyn Camera>,
    reach: ReachSpace,
    settings: TrialSettings,
    rng: ChaCha8Rng,
    pub(super) sensors: NoisySensors,
    pub(super) path: Vec<Observation>,
    /// The path with the frames learned during moves between its poses, when they are
    /// (`settings.move_frames`).
    pub(super) learning_path: Vec<Observation>,
    active: Option<ActiveTrial>,
    /// The camera's clock; `None` for the study's timing or a simulator without a clock.
    clock: Option<FrameClock>,
    pub(super) frames: FrameQueue,
}

impl TrialLoop {
    /// A loop whose every random draw comes from `seed` (the sensor noise from a stream of
    /// its own). On a simulator without a clock frames are taken as each move ends,
    /// whatever `settings.timing` asks.
    pub fn new(
        sim: Box<dyn Simulator>,
        camera: Box<dyn Camera>,
        settings: TrialSettings,
        seed: u64,
    ) -> TrialLoop {
        let clock = FrameClock::new(&settings.timing, sim.tick_seconds());
        let mut sim = sim;
        sim.keep_move_poses(settings.move_frames.is_some());
        TrialLoop {
            sim,
            camera,
            reach: ReachSpace::OSCAR6,
            settings,
            rng: ChaCha8Rng::seed_from_u64(seed),
            sensors: NoisySensors::new(settings.noise, seed),
            path: Vec::with_capacity(settings.feedback_steps + 1),
            learning_path: Vec::new(),
            active: None,
            clock,
            frames: FrameQueue::default(),
        }
    }

    /// This loop with targets drawn from `reach` (the study's space by default).
    pub fn with_reach(mut self, reach: ReachSpace) -> TrialLoop {
        self.reach = reach;
        self
    }

    /// The reach space targets are drawn from.
    pub fn reach(&self) -> &ReachSpace {
        &self.reach
    }

    /// Restarts the random generator from `seed`, as a new loop would start it.
    pub fn reseed(&mut self, seed: u64) {
        self.rng = ChaCha8Rng::seed_from_u64(seed);
    }

    /// The simulator, for events that change the robot.
    pub fn sim_mut(&mut self) -> &mut dyn Simulator {
        self.sim.as_mut()
    }

    /// The simulator.
    pub fn sim(&self) -> &dyn Simulator {
        self.sim.as_ref()
    }

    /// The camera.
    pub fn camera(&self) -> &dyn Camera {
        self.camera.as_ref()
    }

    /// The poses of the current (or last) trial in the order they were seen: the start and
    /// the pose after every step at which the object was seen.
    pub fn path(&self) -> &[Observation] {
        &self.path
    }

    /// Feedback steps taken in the trial going on and why it is over, if it is; `None`
    /// when no trial is going on.
    pub fn trial_state(&self) -> Option<(usize, Option<TrialEnd>)> {
        self.active.map(|t| (t.steps, t.end))
    }

    /// The distance (mm) from the camera to the target of the trial going on, as it is now.
    pub fn distance_mm(&self) -> Option<f64> {
        let goal = self.active?.goal;
        Some((self.sim.camera_pose().translation.vector - goal.coords).norm() * MM_PER_M)
    }

    /// The goal point of the trial going on (world, m): where the camera is to be, a
    /// standoff above the object; `None` when no trial was begun.
    pub fn goal(&self) -> Option<Point3<f64>> {
        self.active.map(|t| t.goal)
    }

    /// The object's centre of the trial going on (world, m); `None` when no trial was
    /// begun.
    pub fn object(&self) -> Option<Point3<f64>> {
        self.active.map(|t| t.object)
    }

    /// The control loop's settings.
    pub fn settings(&self) -> &TrialSettings {
        &self.settings
    }

    /// What the sensors and camera report at the current pose (with their noise), or why
    /// the object is not seen.
    pub fn observe(&mut self, object: &Point3<f64>) -> Result<Observation, NotSeen> {
        let c = self
            .camera
            .read_in(&self.sim.camera_pose(), object, &self.sim.world())?;
        let q = self.sim.joints();
        let exact = Observation {
            theta_deg: self.sim.model().controlled_of(&q).map(f64::to_degrees),
            c,
        };
        Ok(self.sensors.report(exact, self.camera.model()))
    }

    /// What the sensors and camera report at the current pose, or why the object is not
    /// seen with the exact joint angles.
    pub(super) fn look(&mut self, object: &Point3<f64>) -> Sight {
        self.observe(object).map_err(|not_seen| {
            let q = self.sim.joints();
            let exact = self.sim.model().controlled_of(&q).map(f64::to_degrees);
            (not_seen, exact)
        })
    }

    /// Pre-learning: the fixed moves of [`prelearning_moves`](super::prelearning_moves), each
    /// executed by the simulator and learned like a trial.
    /// Drops any trial going on unlearned.
    pub fn prelearn(&mut self, learner: &mut dyn Learner) -> Result<(), LearnError> {
        self.active = None;
        let Some((object, moves)) =
            super::prelearning_moves(self.sim.model(), self.camera.model(), &self.reach)
        else {
            return Ok(());
        };
        for step in moves {
            if self.sim.place(&step.start).is_err() {
                continue;
            }
            let Ok(before) = self.observe(&object) else {
                continue;
            };
            self.sim.execute(&step.delta);
            let Ok(after) = self.observe(&object) else {
                continue;
            };
            learner.learn(&[before, after])?;
        }
        Ok(())
    }
}
