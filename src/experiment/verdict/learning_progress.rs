//! Whether a run's last trials show learning against its first: trials that end no closer
//! to their targets than a fair share of where they started, or that lose the object about
//! as often as the first trials did, learned nothing (judged once the window holds
//! [`JUDGED_WINDOW`] trials).

use super::step_figures::StepFigures;
use crate::control::{Failure, TrialOutcome};
use crate::experiment::config::shown;
use crate::experiment::{declarations, Config, Scope};

/// Trials the window must hold before its distances and failures are judged.
pub(super) const JUDGED_WINDOW: usize = 10;
/// A window whose trials end, on average, at this share of their start distance or farther
/// came no closer to its targets.
pub(super) const NO_CLOSER: f64 = 2.0 / 3.0;
/// The share of a window's trials lost by the learner's moves from which failures count.
pub(super) const MANY_LOST: f64 = 0.5;
/// Failures stay near the first trials' rate while the window's share is at least this
/// share of it.
pub(super) const NEAR_FIRST: f64 = 0.75;

/// One trial as the judgement sees it.
#[derive(Debug, Clone, Copy)]
struct Mark {
    /// Distance (mm) at the start; NaN for a trial that never began.
    start_mm: f64,
    /// Distance (mm) after its last step seen (its start distance when it saw none).
    end_mm: f64,
    /// The learner's moves lost the object (or were not finite).
    lost: bool,
}

/// How a window judged learned nothing: what it shows, in words.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Stalled {
    /// Its trials ended no closer than [`NO_CLOSER`] of their start distance.
    NoCloser,
    /// Its trials were lost about as often as the first ones.
    LostAsOften,
}

/// The distances and losses of a run's first and last trials.
#[derive(Debug, Clone, Default)]
pub(super) struct Progress {
    /// The window of the whole run ([`StepFigures::window_for`]): the ring's length and
    /// the number of first trials whose losses are counted.
    capacity: usize,
    /// The last `capacity` trials, trial t in slot (t − 1) mod `capacity`.
    ring: Vec<Mark>,
    /// Losses among the first `capacity` trials.
    first_lost: usize,
    /// The last trial taken in.
    last: usize,
}

impl Progress {
    /// The progress of a run of `trials` trials.
    pub(super) fn new(trials: usize) -> Progress {
        let capacity = StepFigures::window_for(trials);
        let none = Mark {
            start_mm: f64::NAN,
            end_mm: f64::NAN,
            lost: false,
        };
        Progress {
            capacity,
            ring: vec![none; capacity],
            first_lost: 0,
            last: 0,
        }
    }

    /// Takes in trial `trial`'s outcome (trials in order, from 1).
    pub(super) fn trial_done(&mut self, trial: usize, outcome: &TrialOutcome) {
        if self.capacity == 0 {
            return;
        }
        let lost = matches!(
            outcome.failure,
            Some(Failure::LostObject(_) | Failure::NonFiniteMove)
        );
        if lost && trial <= self.capacity {
            self.first_lost += 1;
        }
        let start_mm = outcome.start_distance_mm.unwrap_or(f64::NAN);
        let end_mm = outcome.distances_mm.last().copied().unwrap_or(start_mm);
        self.ring[(trial.max(1) - 1) % self.capacity] = Mark {
            start_mm,
            end_mm,
            lost,
        };
        self.last = trial;
    }

    /// The last `window` trials taken in (at most the ring's).
    fn window(&self, window: usize) -> impl Iterator<Item = &Mark> + '_ {
        let window = window.min(self.capacity).min(self.last);
        (self.last + 1 - window..=self.last).map(|t| &self.ring[(t - 1) % self.capacity])
    }

    /// How the last `window` trials learned nothing, in words; `None` when they show
    /// learning or are too few to judge.
    pub(super) fn stalled(&self, window: usize) -> Option<(Stalled, String)> {
        let window = window.min(self.capacity).min(self.last);
        if window < JUDGED_WINDOW {
            return None;
        }
        self.no_closer(window)
            .or_else(|| self.lost_as_often(window))
    }

    fn no_closer(&self, window: usize) -> Option<(Stalled, String)> {
        let begun: Vec<&Mark> = self
            .window(window)
            .filter(|m| m.start_mm.is_finite())
            .collect();
        if begun.len() < JUDGED_WINDOW {
            return None;
        }
        let n = begun.len() as f64;
        let start = begun.iter().map(|m| m.start_mm).sum::<f64>() / n;
        let end = begun.iter().map(|m| m.end_mm).sum::<f64>() / n;
        (end >= NO_CLOSER * start).then(|| {
            (
                Stalled::NoCloser,
                format!(
                    "the last {} trials ended {end:.0} mm from their targets on average, {:.0} % of the {start:.0} mm they started at",
                    begun.len(),
                    100.0 * end / start.max(f64::MIN_POSITIVE)
                ),
            )
        })
    }

    fn lost_as_often(&self, window: usize) -> Option<(Stalled, String)> {
        if self.last + 1 - window <= self.capacity {
            return None; // the window reaches into the first trials
        }
        let lost = self.window(window).filter(|m| m.lost).count();
        let share = lost as f64 / window as f64;
        let first_share = self.first_lost as f64 / self.capacity as f64;
        (share >= MANY_LOST && share >= NEAR_FIRST * first_share).then(|| {
            (
                Stalled::LostAsOften,
                format!(
                    "the learner's moves lost the object in {lost} of the last {window} trials ({:.0} %), against {} of the first {} ({:.0} %)",
                    100.0 * share,
                    self.first_lost,
                    self.capacity,
                    100.0 * first_share
                ),
            )
        })
    }
}

/// The entries of `config`'s learner set away from their defaults (`name value (default
/// d)`), or its default settings named when none is; `learner` is the learner's name, which
/// a learner built outside the config may not share.
pub(in crate::experiment) fn learner_entries(config: &Config, learner: &str) -> String {
    if learner != config.method.to_string() {
        return format!("the {learner} learner's own settings");
    }
    let values = config.entries();
    let changed: Vec<String> = declarations()
        .into_iter()
        .filter(|d| matches!(d.scope, Scope::Methods(ms) if ms.contains(&config.method)))
        .filter_map(|d| {
            let default = d.default?;
            let (_, value) = values.iter().find(|(name, _)| *name == d.name)?;
            (*value != default)
                .then(|| format!("{} {} (default {})", d.name, shown(value), shown(&default)))
        })
        .collect();
    if changed.is_empty() {
        format!(
            "the {} learner at its default settings; the run's other entries (feedback_steps, noise, events) may keep it from learning",
            config.method
        )
    } else {
        changed.join(", ")
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::camera::NotSeen;

    fn outcome(start_mm: f64, end_mm: f64, lost: bool) -> TrialOutcome {
        TrialOutcome {
            distances_mm: vec![start_mm, end_mm],
            failure: lost.then_some(Failure::LostObject(NotSeen::OutsideFrame)),
            reached: false,
            seconds: 1.0,
            moved_deg: 1.0,
            proposed_deg: 1.0,
            start_distance_mm: Some(start_mm),
        }
    }

    /// A run of 200 trials (window 20) whose trial t ends at `end(t)` mm from 300 and is
    /// lost when `lost(t)`.
    fn run(end: impl Fn(usize) -> f64, lost: impl Fn(usize) -> bool) -> Progress {
        let mut progress = Progress::new(200);
        for t in 1..=200 {
            progress.trial_done(t, &outcome(300.0, end(t), lost(t)));
        }
        progress
    }

    #[test]
    fn trials_that_end_near_their_targets_with_few_losses_learned() {
        assert_eq!(run(|_| 15.0, |t| t % 3 == 0).stalled(20), None);
        assert_eq!(run(|_| 199.0, |t| t < 20).stalled(20), None);
    }

    #[test]
    fn trials_that_end_at_two_thirds_of_their_start_distance_or_farther_came_no_closer() {
        let (how, what) = run(|_| 200.0, |_| false).stalled(20).unwrap();
        assert_eq!(how, Stalled::NoCloser);
        assert!(
            what.contains(
                "the last 20 trials ended 200 mm from their targets on average, 67 % of the 300 mm"
            ),
            "{what}"
        );
    }

    #[test]
    fn losses_near_the_first_trials_rate_are_no_learning() {
        let (how, what) = run(|_| 10.0, |t| t % 2 == 0).stalled(20).unwrap();
        assert_eq!(how, Stalled::LostAsOften);
        assert!(
            what.contains("in 10 of the last 20 trials (50 %), against 10 of the first 20 (50 %)"),
            "{what}"
        );
        // fewer than half lost, or well under the first trials' rate: learning
        assert_eq!(run(|_| 10.0, |t| t % 3 == 0).stalled(20), None);
        assert_eq!(run(|_| 10.0, |t| t <= 20 || t % 2 == 0).stalled(20), None);
    }

    #[test]
    fn short_windows_and_default_watches_are_not_judged() {
        assert_eq!(run(|_| 300.0, |_| true).stalled(9), None);
        let mut progress = Progress::default();
        progress.trial_done(1, &outcome(300.0, 300.0, true));
        assert_eq!(progress.stalled(20), None);
    }
}
