//! Watching a nested learner's trials for a change of the mapping, and deciding when to
//! forget and when to cut (the `change_detection` merge strategy).
//!
//! What is watched: every pattern's error in the deepest node that answered it, measured
//! before the pattern is trained, relative to the size of the move — e = ‖o − t‖ / ‖t‖ —
//! on a log scale. Each trial gives one value, the mean of ln e over its patterns; the
//! [`ChangeDetector`] tests those values for a rise. Why these choices, from streams of the
//! real arm (lin5, seed 1): within a trial the patterns share their poses, so their errors
//! rise and fall together and a trial is the unit of evidence; over trials the values are
//! close to normal with a spread of about 0.5 that does not change as the tree grows,
//! while ln ‖o − t‖ itself spreads wider with the size of the moves. After a 30° camera turn
//! the relative values rise by 3 spreads, after link 2 ±10 cm by 1.4–1.5 (absolute errors:
//! 2.2 and 1.1). Link 1 ±10 cm only lifts the arm; the mapping from pose and reading to
//! move stays the same and there is nothing to detect. A trial that yields no pattern at
//! all (its first move lost the object) has no error to book, but is itself the strongest
//! evidence: it counts as a failure ([`ChangeDetector::observe_failure`]). After a 90°
//! turn most trials end so, and the turn is found within 3–5 trials instead of 8–29.
//!
//! What follows an alarm: the change is dated to the first trial of the rise, and the
//! learner forgets every pattern numbered before that trial began; `change_grace` trials
//! later it cuts what is still starved. See the tree's recovery.

use super::{ChangeDetector, ChangeSettings};

/// Relative errors below this count as this (an exact answer).
const MIN_RELATIVE_ERROR: f64 = 1e-6;

/// What the learner is to do before a trial.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum WatchStep {
    /// Nothing.
    Nothing,
    /// The mapping changed at `estimated_trial`: forget every pattern numbered below
    /// `cutoff` (the first pattern of that trial).
    Forget {
        /// The trial at which the mapping is estimated to have changed.
        estimated_trial: usize,
        /// The number of the first pattern trained in that trial.
        cutoff: u64,
    },
    /// The grace period after the last change is over: cut what is still starved.
    CutStarved,
}

/// The detector on a learner's per-trial errors, and the dates it needs.
#[derive(Debug, Clone)]
pub(crate) struct ChangeWatch {
    detector: ChangeDetector,
    /// The trial being learned, and the ln e of its patterns so far.
    trial: usize,
    sum: f64,
    count: usize,
    /// Whether the trial yielded no pattern at all.
    failed: bool,
    /// The number of the first pattern of each trial, by trial.
    starts: Vec<u64>,
    grace: usize,
    /// The trial before which starved subtrees are cut, once a change was found.
    cut_at: Option<usize>,
}

impl ChangeWatch {
    /// A watch set up by `settings`.
    pub(crate) fn new(settings: &ChangeSettings) -> Self {
        ChangeWatch {
            detector: ChangeDetector::new(settings.detector),
            trial: 0,
            sum: 0.0,
            count: 0,
            failed: false,
            starts: vec![0],
            grace: settings.grace,
            cut_at: None,
        }
    }

    /// Books a pattern of the current trial whose target move was `target_norm` degrees and
    /// whose answering node missed it by `error` degrees (`None`: no node answered).
    pub(crate) fn pattern(&mut self, error: Option<f64>, target_norm: f64) {
        let Some(error) = error else {
            return;
        };
        let relative = (error / target_norm).max(MIN_RELATIVE_ERROR).ln();
        if relative.is_finite() {
            self.sum += relative;
            self.count += 1;
        }
    }

    /// Books that the current trial yielded no pattern: its moves lost the object before
    /// a second pose was seen.
    pub(crate) fn no_pattern(&mut self) {
        self.failed = true;
    }

    /// Closes the trial learned so far; `trial` comes next, its first pattern will be
    /// number `next_seq`. Says what the learner must do before it.
    pub(crate) fn start_trial(&mut self, trial: usize, next_seq: u64) -> WatchStep {
        let at = self.trial as u64;
        let alarm = if self.count > 0 {
            self.detector.observe(at, self.sum / self.count as f64)
        } else if self.failed {
            self.detector.observe_failure(at)
        } else {
            None
        };
        (self.sum, self.count, self.failed) = (0.0, 0, false);
        // Trials skipped (never started) begin where the next one does.
        if self.starts.len() <= trial {
            self.starts.resize(trial + 1, next_seq);
        }
        self.trial = trial;
        if let Some(alarm) = alarm {
            let estimated_trial = alarm.changed_at as usize;
            self.cut_at = Some(trial + self.grace);
            return WatchStep::Forget {
                estimated_trial,
                cutoff: self
                    .starts
                    .get(estimated_trial)
                    .copied()
                    .unwrap_or(next_seq),
            };
        }
        if self.cut_at.is_some_and(|at| trial >= at) {
            self.cut_at = None;
            return WatchStep::CutStarved;
        }
        WatchStep::Nothing
    }

    /// The starved subtrees were not cut before `trial` (they still did better than their
    /// ancestors): the question comes up again a grace period later.
    pub(crate) fn postpone_cut(&mut self, trial: usize) {
        self.cut_at = Some(trial + self.grace);
    }

    /// The learner threw everything away (a root merge): what was seen says nothing about
    /// what comes.
    pub(crate) fn restart(&mut self) {
        self.detector.restart();
        (self.sum, self.count, self.failed) = (0.0, 0, false);
        self.cut_at = None;
    }
}
