//! Whether a run learned anything: a run whose every trial failed, whose trials gave its
//! learner no pattern, whose arm stayed at its start pose in every trial of its last
//! window, or whose last trials end no closer to their targets or lose the object as often
//! as its first (`learning_progress.rs`) learned nothing, and says so with the likely cause
//! it can see.

use crate::control::TrialOutcome;
use crate::experiment::verdict::failures::FailureTally;
use crate::experiment::verdict::learning_progress::{Progress, Stalled};
use crate::learn::Observation;
use serde::{Deserialize, Serialize};

/// Within this many degrees of its start pose (every controlled joint, true angles) the arm
/// has not moved in a trial; a proposal this small is a zero move.
pub const STILL_DEG: f64 = 0.001;
/// The share of moves stopped by a contact from which a run that learned nothing names
/// contacts as the likely cause.
const MOSTLY_STOPPED: f64 = 0.5;

/// How a run learned nothing (`summary.json`'s `not_learned.kind`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum NotLearnedKind {
    /// No trial finished (a signal stopped the run first).
    NoTrialFinished,
    /// Every trial failed, or every trial of the window.
    EveryTrialFailed,
    /// No pose pair of any trial had a joint moved by `minimal_joint_move`.
    NoPattern,
    /// The arm stayed within [`STILL_DEG`] of its start pose in every trial of the window.
    ArmStayedAtStart,
    /// The window's trials ended, on average, at two thirds of their start distance from
    /// their targets or farther.
    NoCloser,
    /// The learner's moves lost the object in half of the window's trials or more, at three
    /// quarters of the first trials' rate or more.
    LostAsOften,
}

/// Why a run learned nothing, as `summary.json` gives it.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct NotLearned {
    /// What the run saw.
    pub kind: NotLearnedKind,
    /// The same in words, with the likely cause the run can see.
    pub reason: String,
}

/// What a run's trials showed of its learning, gathered trial by trial.
#[derive(Debug, Clone, Default)]
pub struct LearningWatch {
    finished: usize,
    trials_with_a_pattern: usize,
    last_succeeded: Option<usize>,
    last_moved: Option<usize>,
    last_proposed: Option<usize>,
    progress: Progress,
}

/// What the run's end adds to the trials for the verdict.
#[derive(Debug, Clone, Copy)]
pub struct RunEnd<'a> {
    /// The failed trials.
    pub failures: &'a FailureTally,
    /// The trials the distance figures are taken over (the last ones).
    pub window: usize,
    /// Moves the arm made.
    pub moves: u64,
    /// Moves stopped by a contact.
    pub contact_stops: u64,
    /// Moves, placings and link changes after which the arm had not settled in time.
    pub settle_timeouts: u64,
    /// Patterns the learner reports it stores.
    pub patterns: usize,
    /// The config's `minimal_joint_move` (degrees).
    pub minimal_joint_move: f64,
    /// The learner's entries set away from their defaults, in words (the likely cause of
    /// its moves going astray).
    pub learner_settings: &'a str,
}

impl LearningWatch {
    /// A watch on a run of `trials` trials that also judges whether its last trials came
    /// closer to their targets and lost the object less often than its first (a
    /// [`Default`] watch judges neither).
    pub fn for_trials(trials: usize) -> LearningWatch {
        LearningWatch {
            progress: Progress::new(trials),
            ..LearningWatch::default()
        }
    }

    /// Takes in trial `trial`'s outcome and the path of poses it saw; a trial's poses make
    /// a pattern when a joint's reported angle spans `minimal_joint_move` (degrees) or more.
    pub fn trial_done(
        &mut self,
        trial: usize,
        outcome: &TrialOutcome,
        path: &[Observation],
        minimal_joint_move: f64,
    ) {
        self.finished = trial;
        self.progress.trial_done(trial, outcome);
        if outcome.failure.is_none() {
            self.last_succeeded = Some(trial);
        }
        if outcome.moved_deg >= STILL_DEG {
            self.last_moved = Some(trial);
        }
        if outcome.proposed_deg >= STILL_DEG {
            self.last_proposed = Some(trial);
        }
        if joint_span_deg(path) >= minimal_joint_move {
            self.trials_with_a_pattern += 1;
        }
    }

    /// `None` when the run learned, or why it did not.
    pub fn verdict(&self, end: &RunEnd) -> Option<NotLearned> {
        let (kind, what) = self.what_failed(end)?;
        let cause = match kind {
            NotLearnedKind::NoTrialFinished => None,
            NotLearnedKind::EveryTrialFailed => failure_cause(end),
            NotLearnedKind::NoCloser | NotLearnedKind::LostAsOften => {
                Some(end.learner_settings.to_string())
            }
            _ => self.still_cause(end),
        };
        let reason = match cause {
            Some(cause) => format!("{what}; likely cause: {cause}"),
            None => what,
        };
        Some(NotLearned { kind, reason })
    }

    /// The first trial of the window of `window` last trials (at least one).
    fn window_start(&self, window: usize) -> usize {
        self.finished.saturating_sub(window.max(1)) + 1
    }

    /// The first of the ways to learn nothing that the run shows, in words.
    fn what_failed(&self, end: &RunEnd) -> Option<(NotLearnedKind, String)> {
        let window_start = self.window_start(end.window);
        if self.finished == 0 {
            Some((
                NotLearnedKind::NoTrialFinished,
                "no trial finished".to_string(),
            ))
        } else if end.failures.total() == self.finished {
            Some((
                NotLearnedKind::EveryTrialFailed,
                format!("all {} trials failed ({})", self.finished, end.failures),
            ))
        } else if self.last_succeeded.is_none_or(|t| t < window_start) {
            Some((
                NotLearnedKind::EveryTrialFailed,
                format!(
                    "each of the last {} trials failed ({} of {} in all: {})",
                    self.finished + 1 - window_start,
                    end.failures.total(),
                    self.finished,
                    end.failures
                ),
            ))
        } else if self.trials_with_a_pattern == 0 {
            Some((
                NotLearnedKind::NoPattern,
                format!(
                    "no trial of {} gave the learner a pattern (no joint moved by minimal_joint_move {}°)",
                    self.finished, end.minimal_joint_move
                ),
            ))
        } else if self.last_moved.is_none_or(|t| t < window_start) {
            Some((
                NotLearnedKind::ArmStayedAtStart,
                format!(
                    "the arm stayed within {STILL_DEG}° of its start pose in each of the last {} trials",
                    self.finished + 1 - window_start
                ),
            ))
        } else {
            self.progress.stalled(end.window).map(|(how, what)| {
                let kind = match how {
                    Stalled::NoCloser => NotLearnedKind::NoCloser,
                    Stalled::LostAsOften => NotLearnedKind::LostAsOften,
                };
                (kind, what)
            })
        }
    }

    /// What most likely kept the arm still.
    fn still_cause(&self, end: &RunEnd) -> Option<String> {
        let window_start = self.window_start(end.window);
        if end.contact_stops as f64 > MOSTLY_STOPPED * end.moves as f64 {
            Some(format!(
                "{} of {} moves were stopped by a contact (the floor, an obstacle or another link): the start or pre-learning poses may be in contact",
                end.contact_stops, end.moves
            ))
        } else if self.last_proposed.is_none_or(|t| t < window_start) {
            Some(format!(
                "the learner answered zero moves (it stores {} patterns)",
                end.patterns
            ))
        } else {
            None
        }
    }
}

/// The likely cause of every trial failing, when one reason makes most of the failures.
fn failure_cause(end: &RunEnd) -> Option<String> {
    let (failures, learner_settings) = (end.failures, end.learner_settings);
    let most = |count: usize| 2 * count > failures.total();
    let unsettled = end.settle_timeouts as f64 > MOSTLY_STOPPED * end.moves.max(1) as f64;
    if most(failures.no_start_seen) && unsettled {
        Some(format!("the arm did not settle in time ({} settle timeouts, {} moves made): its motors may be too weak to hold it against gravity (the URDF's joint effort limits and link masses) or settle_timeout too short, so the camera does not see the object at the start", end.settle_timeouts, end.moves))
    } else if most(failures.no_start_seen) {
        Some("the object is out of the camera's view at the start (camera_link, camera_offset, obstacles)".into())
    } else if most(failures.left_the_image + failures.too_close) {
        Some(format!("the learner's moves lose the object (out of the image or too close): its answers are far off ({learner_settings}; or the run's events)"))
    } else if most(failures.hidden) {
        Some("something hides the object from the camera (obstacles)".into())
    } else if most(failures.unreachable_target) {
        Some("the targets are out of the arm's reach (reach_space)".into())
    } else {
        None
    }
}

/// The largest span (degrees) of one joint's reported angle over `path`: the largest move
/// between two of its poses.
fn joint_span_deg(path: &[Observation]) -> f64 {
    let Some(first) = path.first() else {
        return 0.0;
    };
    let (low, high) = path
        .iter()
        .fold((first.theta_deg, first.theta_deg), |(l, h), o| {
            (l.inf(&o.theta_deg), h.sup(&o.theta_deg))
        });
    (high - low).amax()
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::Vector3;

    fn outcome(moved_deg: f64, proposed_deg: f64) -> TrialOutcome {
        TrialOutcome {
            distances_mm: vec![100.0],
            failure: None,
            reached: false,
            seconds: 1.0,
            moved_deg,
            proposed_deg,
            start_distance_mm: Some(200.0),
        }
    }

    fn pose(theta: [f64; 3]) -> Observation {
        Observation {
            theta_deg: Vector3::from(theta),
            c: Vector3::zeros(),
        }
    }

    fn end(failures: &FailureTally, window: usize) -> RunEnd<'_> {
        RunEnd {
            failures,
            window,
            moves: 100,
            contact_stops: 0,
            settle_timeouts: 0,
            patterns: 8,
            minimal_joint_move: 0.01,
            learner_settings: "mlp_rate 1 (default 0.001)",
        }
    }

    #[test]
    fn an_arm_that_moves_in_the_window_learned() {
        let mut watch = LearningWatch::default();
        let moving = [pose([0.0; 3]), pose([0.0, 2.0, 0.0])];
        for trial in 1..=10 {
            watch.trial_done(trial, &outcome(2.0, 2.0), &moving, 0.01);
        }
        assert_eq!(watch.verdict(&end(&FailureTally::default(), 3)), None);
    }

    #[test]
    fn an_arm_still_through_the_window_learned_nothing_and_the_zero_answers_are_named() {
        let mut watch = LearningWatch::default();
        let moving = [pose([0.0; 3]), pose([0.0, 2.0, 0.0])];
        let still = [pose([1.0; 3]), pose([1.0; 3])];
        watch.trial_done(1, &outcome(2.0, 2.0), &moving, 0.01);
        for trial in 2..=10 {
            watch.trial_done(trial, &outcome(0.0, 0.0), &still, 0.01);
        }
        let verdict = watch.verdict(&end(&FailureTally::default(), 3)).unwrap();
        assert_eq!(verdict.kind, NotLearnedKind::ArmStayedAtStart);
        assert!(
            verdict.reason.contains("each of the last 3 trials"),
            "{verdict:?}"
        );
        assert!(verdict
            .reason
            .contains("answered zero moves (it stores 8 patterns)"));
        watch.trial_done(11, &outcome(STILL_DEG, 1.0), &still, 0.01);
        assert_eq!(watch.verdict(&end(&FailureTally::default(), 3)), None);
    }

    #[test]
    fn trials_without_a_pattern_and_failed_trials_are_told_apart() {
        let mut watch = LearningWatch::default();
        let tiny = [pose([0.0; 3]), pose([0.0, 0.005, 0.0])];
        watch.trial_done(1, &outcome(0.005, 0.005), &tiny, 0.01);
        let verdict = watch.verdict(&end(&FailureTally::default(), 1)).unwrap();
        assert_eq!(verdict.kind, NotLearnedKind::NoPattern);
        let mut failures = FailureTally {
            no_start_seen: 1,
            ..FailureTally::default()
        };
        let verdict = watch.verdict(&end(&failures, 1)).unwrap();
        assert_eq!(verdict.kind, NotLearnedKind::EveryTrialFailed);
        assert!(
            verdict.reason.contains("out of the camera's view"),
            "{verdict:?}"
        );
        let mut lost = outcome(2.0, 2.0);
        lost.failure = Some(crate::control::Failure::LostObject(
            crate::camera::NotSeen::OutsideFrame,
        ));
        let moving = [pose([0.0; 3]), pose([0.0, 2.0, 0.0])];
        watch.trial_done(2, &outcome(2.0, 2.0), &moving, 0.01);
        for trial in 3..=5 {
            watch.trial_done(trial, &lost, &moving, 0.01);
        }
        failures.left_the_image = 3;
        let verdict = watch.verdict(&end(&failures, 3)).unwrap();
        assert_eq!(verdict.kind, NotLearnedKind::EveryTrialFailed);
        assert!(
            verdict
                .reason
                .starts_with("each of the last 3 trials failed (4 of 5 in all"),
            "{verdict:?}"
        );
        assert!(verdict.reason.contains("lose the object"), "{verdict:?}");
        assert_eq!(
            LearningWatch::default()
                .verdict(&end(&failures, 1))
                .unwrap()
                .kind,
            NotLearnedKind::NoTrialFinished
        );
    }
}
