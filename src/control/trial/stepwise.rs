//! A trial taken in pieces, as Python drives one move by move: begin it, take feedback
//! steps, finish it by learning its poses.

use super::outcome::Failure;
use super::TrialLoop;
use crate::control::feedback::{ActiveTrial, StepError, StepReport, TrialEnd};
use crate::learn::{LearnError, Learner, Observation};
use crate::units::MM_PER_M;
use nalgebra::Vector3;

impl TrialLoop {
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
    pub(super) fn keep_pose(&mut self, seen: Observation) {
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
}
