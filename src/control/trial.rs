//! One trial: draw a target and a start pose from which the object is seen, then feedback
//! steps `Δθ = N(c, θ2, θ3)` until the camera is within ε of the target (after at least
//! `min_feedback_steps` steps) or `feedback_steps` are used; the trial's poses are then
//! learned.

use super::sensors::{NoisySensors, SensorNoise};
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
    /// A pose pair is a learning pattern only if a joint moved this much (degrees).
    pub minimal_joint_move_deg: f64,
    /// The noise of the camera's and the encoders' reports.
    pub noise: SensorNoise,
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

/// What a trial did.
#[derive(Debug, Clone, PartialEq)]
pub struct TrialOutcome {
    /// Distance to the target (mm) after each feedback step taken.
    pub distances_mm: Vec<f64>,
    /// Why the trial stopped early, if it did.
    pub failure: Option<Failure>,
}

/// The control loop over a simulator and camera, with the run's random generator.
#[derive(Debug)]
pub struct TrialLoop {
    sim: Box<dyn Simulator>,
    camera: Box<dyn Camera>,
    reach: ReachSpace,
    settings: TrialSettings,
    rng: ChaCha8Rng,
    sensors: NoisySensors,
    path: Vec<Observation>,
}

impl TrialLoop {
    /// A loop whose every random draw comes from `seed` (the sensor noise from a stream of
    /// its own).
    pub fn new(
        sim: Box<dyn Simulator>,
        camera: Box<dyn Camera>,
        settings: TrialSettings,
        seed: u64,
    ) -> TrialLoop {
        TrialLoop {
            sim,
            camera,
            reach: ReachSpace::OSCAR6,
            settings,
            rng: ChaCha8Rng::seed_from_u64(seed),
            sensors: NoisySensors::new(settings.noise, seed),
            path: Vec::with_capacity(settings.feedback_steps + 1),
        }
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
    /// when the learner cannot learn (its pattern storage failed).
    pub fn run_trial(&mut self, learner: &mut dyn Learner) -> Result<TrialOutcome, LearnError> {
        let mut outcome = TrialOutcome {
            distances_mm: Vec::with_capacity(self.settings.feedback_steps),
            failure: None,
        };
        let object = match self.draw_target() {
            Ok(object) => object,
            Err(failure) => {
                outcome.failure = Some(failure);
                return Ok(outcome);
            }
        };
        self.path.clear();
        match self.draw_start(&object) {
            Ok(start) => self.path.push(start),
            Err(failure) => {
                outcome.failure = Some(failure);
                return Ok(outcome);
            }
        }
        let goal = self.camera.model().goal_point(&object);
        for step in 1..=self.settings.feedback_steps {
            let here = self.path[self.path.len() - 1];
            let delta_deg = learner.propose(&here.query());
            if !delta_deg.iter().all(|v| v.is_finite()) {
                outcome.failure = Some(Failure::NonFiniteMove);
                break;
            }
            self.sim.execute(&delta_deg.map(f64::to_radians));
            match self.observe(&object) {
                Ok(seen) => self.path.push(seen),
                Err(not_seen) => {
                    outcome.failure = Some(Failure::LostObject(not_seen));
                    break;
                }
            }
            let distance = (self.sim.camera_pose().translation.vector - goal.coords).norm();
            outcome.distances_mm.push(distance * MM_PER_M);
            if step >= self.settings.min_feedback_steps && distance <= self.settings.epsilon {
                break;
            }
        }
        learner.learn(&self.path)?;
        Ok(outcome)
    }

    /// What the sensors and camera report at the current pose (with their noise), or why
    /// the object is not seen.
    pub fn observe(&mut self, object: &Point3<f64>) -> Result<Observation, NotSeen> {
        let c = self.camera.read(&self.sim.camera_pose(), object)?;
        let q = self.sim.joints();
        let exact = Observation {
            theta_deg: Vector3::new(q[0], q[1], q[2]).map(f64::to_degrees),
            c,
        };
        Ok(self.sensors.report(exact, self.camera.model()))
    }

    /// The object's centre for a target drawn uniformly in the reach space and reachable by
    /// the robot as it is now.
    fn draw_target(&mut self) -> Result<Point3<f64>, Failure> {
        let standoff = self.camera.model().standoff;
        for _ in 0..MAX_DRAWS {
            let goal = self.reach.sample(&mut self.rng);
            if self.sim.model().solve_camera_position(&goal).is_ok() {
                return Ok(goal - Vector3::z() * standoff);
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
    pub fn prelearn(&mut self, learner: &mut dyn Learner) -> Result<(), LearnError> {
        let Some((object, moves)) = super::prelearning_moves(self.sim.model(), self.camera.model())
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
