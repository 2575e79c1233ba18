//! A whole trial run through: begun, stepped with the learner's moves until it is over,
//! then learned, with an observer told of every step.

use super::outcome::{Failure, TrialOutcome};
use super::TrialLoop;
use crate::control::feedback::{TrialEnd, TrialObserver};
use crate::learn::{LearnError, Learner};
use nalgebra::Vector3;

impl TrialLoop {
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
}
