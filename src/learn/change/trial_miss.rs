//! The per-trial value the change watch of a single-model learner is given
//! ([`WatchedLearner`](super::WatchedLearner)): the log of a trial's summed miss relative to
//! its summed move, and what an alarm tells the learner.
//!
//! The nested learners book each pattern's relative miss; a single smooth model answers
//! every pattern with an absolute error floor, so a trial's many small late moves miss by
//! about their own size whatever the robot does and would drown the rise a change causes
//! in the large moves (see the `lwpr` module's notes). Summing first weighs each pattern
//! by its move.

use super::{ChangeSettings, ChangeWatch, WatchStep};
use crate::learn::ModelEvent;

/// A change watch fed one value per trial, with the events it raised.
#[derive(Debug, Clone)]
pub(crate) struct TrialMiss {
    watch: ChangeWatch,
    /// The trial's summed miss (degrees; `None` once a pattern had no answer) and move.
    missed: Option<f64>,
    moved: f64,
    events: Vec<ModelEvent>,
}

impl TrialMiss {
    /// A watch set up by `settings` (only its detector counts).
    pub(crate) fn new(settings: &ChangeSettings) -> TrialMiss {
        TrialMiss {
            watch: ChangeWatch::new(settings),
            missed: Some(0.0),
            moved: 0.0,
            events: Vec::new(),
        }
    }

    /// Books a pattern of the trial: the model missed its target of `target_norm` degrees
    /// by `miss` degrees before learning it (`None`: the model had no answer there).
    pub(crate) fn book(&mut self, miss: Option<f64>, target_norm: f64) {
        self.missed = self.missed.zip(miss).map(|(sum, miss)| sum + miss);
        self.moved += target_norm;
    }

    /// Closes the trial booked so far: its value goes to the watch if it moved at all.
    pub(crate) fn close_trial(&mut self) {
        if self.moved > 0.0 {
            self.watch.pattern(self.missed, self.moved);
        }
        (self.missed, self.moved) = (Some(0.0), 0.0);
    }

    /// Trial `trial` comes next, its first pattern number `next_seq`. On an alarm the
    /// change is logged and the trial it is dated to returned.
    pub(crate) fn start_trial(&mut self, trial: usize, next_seq: u64) -> Option<usize> {
        match self.watch.start_trial(trial, next_seq) {
            WatchStep::Forget {
                estimated_trial, ..
            } => {
                self.events.push(ModelEvent::Change { estimated_trial });
                Some(estimated_trial)
            }
            WatchStep::Nothing | WatchStep::CutStarved => None,
        }
    }

    /// Moves the changes detected since the last call into `sink`.
    pub(crate) fn drain_events(&mut self, sink: &mut Vec<ModelEvent>) {
        sink.append(&mut self.events);
    }
}
