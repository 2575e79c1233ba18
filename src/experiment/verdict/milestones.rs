//! Milestones of a run's 4-step distances: the trial at which their running mean first
//! reached a level, and how many trials after an event it took to come back near the level
//! it had before the event.

use crate::experiment::plot::Series;
use std::io;
use std::path::Path;

/// Trials in the running mean that decides a recovery.
pub const RECOVERY_WINDOW: usize = 50;
/// A run has recovered when its running mean is at most this many times its level before
/// the event.
pub const RECOVERY_FACTOR: f64 = 1.5;
/// Trials before an event whose mean is the level it is compared with.
pub const LEVEL_BEFORE_EVENT: usize = 500;

/// The 4-step distance (mm) of each trial of a run, from its `4step` file: trial t at
/// index t − 1, NaN for a trial that took no 4th step.
#[derive(Debug, Clone, PartialEq)]
pub struct FourStepTrace {
    by_trial: Vec<f64>,
}

impl FourStepTrace {
    /// The trace of the points (trial, distance) of a `4step` series.
    pub fn from_series(series: &Series) -> FourStepTrace {
        let trials = series.points.iter().map(|&(t, _)| t as usize).max();
        let mut by_trial = vec![f64::NAN; trials.unwrap_or(0)];
        for &(trial, distance) in &series.points {
            if trial >= 1.0 {
                by_trial[trial as usize - 1] = distance;
            }
        }
        FourStepTrace { by_trial }
    }

    /// The trace of the run in `folder` (its `4step` file; none: an empty trace).
    pub fn read(folder: &Path) -> io::Result<FourStepTrace> {
        Series::read(&folder.join("4step")).map(|s| FourStepTrace::from_series(&s))
    }

    /// The trials the trace covers.
    pub fn trials(&self) -> usize {
        self.by_trial.len()
    }

    /// The mean over trials `first..=last` of those that took a 4th step (`None`: none
    /// did, or the range is outside the trace).
    pub fn mean(&self, first: usize, last: usize) -> Option<f64> {
        let slice = self
            .by_trial
            .get(first.max(1) - 1..last.min(self.trials()))?;
        let (sum, n) = slice
            .iter()
            .filter(|d| d.is_finite())
            .fold((0.0, 0usize), |(sum, n), d| (sum + d, n + 1));
        (n > 0).then(|| sum / n as f64)
    }

    /// The first trial from which the mean over the last `window` trials is at most
    /// `level` (the soonest is trial `window`).
    pub fn first_within(&self, level: f64, window: usize) -> Option<usize> {
        self.first_from(window.max(1), level, window)
    }

    /// The level before the event at trial `event`: the mean over the
    /// [`LEVEL_BEFORE_EVENT`] trials before it.
    pub fn level_before(&self, event: usize) -> Option<f64> {
        let last = event.checked_sub(1)?;
        self.mean(last.saturating_sub(LEVEL_BEFORE_EVENT - 1), last)
    }

    /// Trials after the event at trial `event` until the mean over the last
    /// [`RECOVERY_WINDOW`] trials is within [`RECOVERY_FACTOR`] × the level before it
    /// (the soonest is [`RECOVERY_WINDOW`]; `None`: not by the trace's last trial).
    pub fn recovered_after(&self, event: usize) -> Option<usize> {
        let before = self.level_before(event)?;
        let from = event - 1 + RECOVERY_WINDOW;
        self.first_from(from, RECOVERY_FACTOR * before, RECOVERY_WINDOW)
            .map(|t| t + 1 - event)
    }

    /// The first trial from `from` on at which the mean over the last `window` trials is
    /// at most `level`.
    fn first_from(&self, from: usize, level: f64, window: usize) -> Option<usize> {
        (from..=self.trials()).find(|&t| {
            self.mean(t + 1 - window.min(t), t)
                .is_some_and(|mean| mean <= level)
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn trace(distances: &[f64]) -> FourStepTrace {
        let points = distances
            .iter()
            .enumerate()
            .map(|(i, &d)| ((i + 1) as f64, d))
            .collect();
        FourStepTrace::from_series(&Series {
            points,
            minutes: Vec::new(),
        })
    }

    #[test]
    fn a_running_mean_reaches_a_level_once_its_window_is_full_and_low_enough() {
        let mut d = vec![2.0; 10];
        d.extend([0.5; 10]);
        let t = trace(&d);
        // Over trials 9..=12 the mean is (2·2 + 2·0.5)/4 = 1.25; over 11..=14 it is 0.5.
        assert_eq!(t.first_within(1.25, 4), Some(12));
        assert_eq!(t.first_within(0.5, 4), Some(14));
        assert_eq!(t.first_within(0.4, 4), None);
    }

    #[test]
    fn recovery_counts_the_trials_from_the_event_to_a_full_window_within_the_factor() {
        let event = LEVEL_BEFORE_EVENT + 1;
        let mut d = vec![1.0; LEVEL_BEFORE_EVENT];
        d.extend([50.0; 10]);
        d.extend([1.0; 200]);
        let t = trace(&d);
        assert_eq!(t.level_before(event), Some(1.0));
        // The window must leave out all ten bad trials, except one at most:
        // (49 + 50) / 50 = 1.98 > 1.5, so all ten: trials event+10 ..= event+59.
        assert_eq!(t.recovered_after(event), Some(60));
        let never = trace(&[vec![1.0; LEVEL_BEFORE_EVENT], vec![2.0; 100]].concat());
        assert_eq!(never.recovered_after(event), None);
    }

    #[test]
    fn trials_without_a_fourth_step_are_left_out_of_the_means() {
        let t = trace(&[1.0, f64::NAN, 3.0]);
        assert_eq!(t.mean(1, 3), Some(2.0));
        assert_eq!(t.mean(2, 2), None);
        assert_eq!(t.mean(4, 9), None);
    }
}
