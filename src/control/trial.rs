//! One trial: draw a target and a start pose from which the object is seen, then feedback
//! steps `Δθ = N(c, θ2, θ3)` until the camera is within ε of the target (after at least
//! `min_feedback_steps` steps) or `feedback_steps` are used; the trial's poses are then
//! learned.

use super::clocked::FrameQueue;
use super::feedback::{ActiveTrial, StepError, StepReport, TrialEnd, TrialObserver};
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

/// Distances after steps 1..=this are written to the `1step`…`5step` files.
pub const MAX_RECORDED_STEPS: usize = 5;
/// Draws of a reachable target, or of a start from which it is seen, before giving up.
const MAX_DRAWS: usize = 10_000;

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

/// Why a trial could not be completed; counted, never fatal.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Failure {
    /// No reachable target was drawn.
    UnreachableTarget,
    /// No start pose from which the object is seen was drawn.
    NoStartSeen,
    /// The object left the image after a move.
    LostObject(NotSeen),
    /// The learner proposed a non-finite move.
    NonFiniteMove,
}

/// What a trial did (`Default`: nothing yet, no distance, no failure).
#[derive(Debug, Clone, Default, PartialEq)]
pub struct TrialOutcome {
    /// Distance to the target (mm) after each feedback step taken.
    pub distances_mm: Vec<f64>,
    /// Why the trial stopped early, if it did.
    pub failure: Option<Failure>,
    /// True when the camera came within ε of the target.
    pub reached: bool,
    /// Simulated seconds of the feedback steps: from the first frame's delivery to the
    /// last step's frame (moves, settling and waits for frames).
    pub seconds: f64,
    /// The largest change (degrees) of a controlled joint from the trial's start pose over
    /// the trial, in the simulator's true angles (no encoder noise): 0 for an arm that
    /// never left its start.
    pub moved_deg: f64,
    /// The largest joint move (degrees) the learner proposed in the trial.
    pub proposed_deg: f64,
    /// Distance to the target (mm) at the trial's start, before any move (`None` when no
    /// target or start was drawn).
    pub start_distance_mm: Option<f64>,
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

    /// Runs one trial with `learner` and lets it learn from the trial's poses; fails only
    /// when the learner cannot learn (its pattern storage failed). Built on
    /// [`begin_trial`](Self::begin_trial), [`step_trial`](Self::step_trial) and
    /// [`finish_trial`](Self::finish_trial).
    pub fn run_trial(&mut self, learner: &mut dyn Learner) -> Result<TrialOutcome, LearnError> {
        self.run_trial_reporting(learner, &mut |_, _| {})
    }

    /// [`run_trial`](Self::run_trial), calling `after_step` with the step's number and the
    /// trial's simulated seconds so far after every feedback step: a caller's progress
    /// report within a long trial.
    pub fn run_trial_reporting(
        &mut self,
        learner: &mut dyn Learner,
        after_step: &mut dyn FnMut(usize, f64),
    ) -> Result<TrialOutcome, LearnError> {
        let mut after_step = after_step;
        self.run_trial_observed(learner, &mut after_step)
    }

    /// [`run_trial`](Self::run_trial), telling `observer` of every feedback step and of
    /// the learning that follows them.
    pub fn run_trial_observed(
        &mut self,
        learner: &mut dyn Learner,
        observer: &mut dyn TrialObserver,
    ) -> Result<TrialOutcome, LearnError> {
        let mut outcome = TrialOutcome {
            distances_mm: Vec::with_capacity(self.settings.feedback_steps),
            ..TrialOutcome::default()
        };
        let mut here = match self.begin_trial() {
            Ok(start) => start,
            Err(failure) => {
                outcome.failure = Some(failure);
                return Ok(outcome);
            }
        };
        let start_deg = self.true_controlled_deg();
        outcome.start_distance_mm = self.distance_mm();
        for _ in 0..self.settings.feedback_steps {
            let delta_deg = learner.propose(&here.query());
            outcome.proposed_deg = outcome.proposed_deg.max(delta_deg.amax());
            let report = match self.step_trial(&delta_deg) {
                Ok(report) => report,
                Err(_) => {
                    outcome.failure = Some(Failure::NonFiniteMove);
                    break;
                }
            };
            outcome.seconds = report.seconds;
            observer.step_done(report.step, report.seconds);
            let moved = (self.true_controlled_deg() - start_deg).amax();
            outcome.moved_deg = outcome.moved_deg.max(moved);
            if report.reading.is_ok() {
                outcome.distances_mm.push(report.distance_mm);
                here = self.path[self.path.len() - 1];
            }
            if let Some(end) = report.end {
                outcome.failure = end.failure();
                outcome.reached = end == TrialEnd::Reached;
                break;
            }
            if crate::cancel::requested() {
                break; // a signal: the run stops after this trial, cut short here
            }
        }
        observer.learning();
        self.finish_trial(learner)?;
        Ok(outcome)
    }

    /// The controlled joint angles (degrees) the simulator's arm is at, without encoder
    /// noise.
    fn true_controlled_deg(&self) -> Vector3<f64> {
        let model = self.sim.model();
        model.controlled_of(&self.sim.joints()).map(f64::to_degrees)
    }

    /// Begins a trial: draws a reachable target and a start from which the object is seen,
    /// places the arm there and returns what it sees. Any trial going on is dropped
    /// unlearned.
    pub fn begin_trial(&mut self) -> Result<Observation, Failure> {
        self.active = None;
        self.path.clear();
        self.learning_path.clear();
        let object = self.draw_target()?;
        let start = self.draw_start(&object)?;
        self.keep_pose(start);
        if let Some(clock) = self.clock {
            self.start_clock(&clock, &object);
        }
        self.active = Some(ActiveTrial {
            object,
            goal: self.camera.model().goal_point(&object),
            steps: 0,
            seconds: 0.0,
            end: None,
        });
        Ok(start)
    }

    /// Takes one feedback step of the trial going on: executes `delta_deg` (Δθ1, Δθ2, Δθ3
    /// in degrees), reads the camera and measures the distance to the target. The trial is
    /// over once the camera is within ε (after `min_feedback_steps`), `feedback_steps`
    /// were taken, or the object is lost. Under a camera clock the step ends when the
    /// next frame arrives, and the distance is the camera's then; in continuous servoing
    /// `delta_deg` is relative to the pose of the last frame and a step is a frame.
    pub fn step_trial(&mut self, delta_deg: &Vector3<f64>) -> Result<StepReport, StepError> {
        let Some(trial) = self.active.filter(|t| t.end.is_none()) else {
            return Err(StepError::NoTrial);
        };
        if !delta_deg.iter().all(|v| v.is_finite()) {
            return Err(StepError::NonFiniteMove {
                delta_deg: *delta_deg,
            });
        }
        let delta = delta_deg.map(f64::to_radians);
        let (sight, seconds) = match self.clock {
            Some(clock) => {
                let sight = self.clocked_step(&clock, &delta, &trial.object);
                (sight, self.clock_seconds(&clock))
            }
            None => {
                let duration = self.sim.execute(&delta).duration;
                if let Some(frames) = self.settings.move_frames {
                    self.learn_frames_of_move(&frames, duration, &trial.object);
                }
                (self.look(&trial.object), trial.seconds + duration)
            }
        };
        let step = trial.steps + 1;
        let (theta_deg, reading) = match sight {
            Ok(seen) => {
                self.keep_pose(seen);
                (seen.theta_deg, Ok(seen.c))
            }
            Err((not_seen, exact)) => (exact, Err(not_seen)),
        };
        let distance = (self.sim.camera_pose().translation.vector - trial.goal.coords).norm();
        let end = match reading {
            Err(not_seen) => Some(TrialEnd::Lost(not_seen)),
            Ok(_)
                if step >= self.settings.min_feedback_steps
                    && distance <= self.settings.epsilon =>
            {
                Some(TrialEnd::Reached)
            }
            Ok(_) if step >= self.settings.feedback_steps => Some(TrialEnd::StepsUsed),
            Ok(_) => None,
        };
        self.active = Some(ActiveTrial {
            steps: step,
            seconds,
            end,
            ..trial
        });
        Ok(StepReport {
            step,
            theta_deg,
            reading,
            distance_mm: distance * MM_PER_M,
            seconds,
            end,
        })
    }

    /// Adds a pose at which a move ended (or the start) to the trial's path, and to the
    /// learning path when frames during moves are learned too.
    fn keep_pose(&mut self, seen: Observation) {
        self.path.push(seen);
        if self.settings.move_frames.is_some() {
            self.learning_path.push(seen);
        }
    }

    /// Finishes the trial begun last, over or not: `learner` learns from its poses (and the
    /// frames learned during its moves, when they are). Does nothing when no trial was
    /// begun since the last finish (or the draw failed).
    pub fn finish_trial(&mut self, learner: &mut dyn Learner) -> Result<(), LearnError> {
        match self.active.take() {
            Some(_) if self.settings.move_frames.is_some() => learner.learn(&self.learning_path),
            Some(_) => learner.learn(&self.path),
            None => Ok(()),
        }
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

    /// The object's centre for a target drawn uniformly in the reach space, reachable by
    /// the robot as it is now and not inside an obstacle.
    fn draw_target(&mut self) -> Result<Point3<f64>, Failure> {
        let model = *self.camera.model();
        for _ in 0..MAX_DRAWS {
            let goal = self.reach.sample(&mut self.rng);
            let object = model.object_at_goal(&goal);
            let inside = |o: &crate::robot::Obstacle| o.overlaps_ball(&object, model.object_radius);
            if self.sim.model().solve_camera_position(&goal).is_ok()
                && !self.sim.obstacles().iter().any(inside)
            {
                return Ok(object);
            }
        }
        Err(Failure::UnreachableTarget)
    }

    /// Places the arm at a start drawn uniformly in the reach space from which the object
    /// is seen, and observes it there.
    fn draw_start(&mut self, object: &Point3<f64>) -> Result<Observation, Failure> {
        for _ in 0..MAX_DRAWS {
            let at = self.reach.sample(&mut self.rng);
            // Most draws do not see the object: skip their inverse kinematics.
            if !self.camera.model().may_see_from_above(&at, object) {
                continue;
            }
            let Ok(theta) = self.sim.model().solve_camera_position(&at) else {
                continue;
            };
            if self.sim.place(&theta).is_ok() {
                if let Ok(seen) = self.observe(object) {
                    return Ok(seen);
                }
            }
        }
        Err(Failure::NoStartSeen)
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
