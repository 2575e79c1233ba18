//! The one wrapper of every learner with a single model (lwpr, issgp, mlp, ffn, kohonen):
//! it keeps the learner's answers finite and its trials clear of readings that are not,
//! and under `merge_strategy change_detection` watches its trials for a change of the
//! mapping and recovers from one as `change_recovery` says: `forget` lets the model forget
//! ([`SingleModel::forget_before`]); `correct` answers through a correction of the
//! readings fitted from the patterns since the change, as the nested learners do within
//! their tree (`nested/tree/correct_recovery.rs`).
//!
//! The wrapper knows the learner only through the [`SingleModel`] trait. Its watch books
//! each trial's summed miss relative to its summed move (`TrialMiss`), the misses those of
//! the learner's answers to the trial's adjusted patterns before it learns them. Under
//! `correct`, at an alarm the patterns of the trials since the estimated change that end
//! near the centre seed a [`Corrections`] fit; from then on the learner learns nothing
//! while the fit runs: each trial's patterns join it, it is redone after the trial through
//! the learner's own answers, and queries go through it once it has enough patterns. Once
//! it is fixed, the trials held back are learned through it, and every later trial's
//! readings and every query go through the fixed corrections: the learner goes on learning
//! in the readings it knows.

use super::{ChangeRecovery, ChangeSettings, Corrections, SingleModel, TrialMiss};
use crate::learn::inputs::finite_or_still;
use crate::learn::{
    adjusted_pattern, LearnError, Learner, LearnerStats, ModelEvent, Observation, PatternSettings,
    Query,
};
use nalgebra::{SVector, Vector3};
use std::borrow::Cow;

/// A single-model learner with its answers kept finite and, under change detection, its
/// trials watched for a change of the mapping.
#[derive(Debug)]
pub struct WatchedLearner {
    inner: Box<dyn SingleModel>,
    /// The change watch and the recovery after an alarm; none without change detection.
    watch: Option<Watch>,
}

/// What watches a learner's trials, and what it does at an alarm.
#[derive(Debug)]
struct Watch {
    misses: TrialMiss,
    recovery: ChangeRecovery,
    corrections: Corrections<5>,
    patterns: PatternSettings,
    /// The corners of the learner's input box (θ2, θ3, cx, cy, cz).
    low: SVector<f64, 5>,
    high: SVector<f64, 5>,
    /// The trial going on, and the patterns booked so far (the watch dates by them).
    trial: usize,
    booked: u64,
    /// The trials held back from the learner while a correction is fitted.
    held: Vec<Vec<Observation>>,
}

impl WatchedLearner {
    /// `inner` with its answers kept finite and nothing watched.
    pub fn unwatched(inner: Box<dyn SingleModel>) -> WatchedLearner {
        WatchedLearner { inner, watch: None }
    }

    /// `inner` watched by `change` and recovering as its `recovery` says, its corrections
    /// made over the input box `bounds`; `patterns` says which pose pairs count.
    pub fn watched(
        mut inner: Box<dyn SingleModel>,
        change: &ChangeSettings,
        patterns: PatternSettings,
        bounds: [(f64, f64); 5],
    ) -> WatchedLearner {
        let watch = Watch {
            misses: TrialMiss::new(change),
            recovery: change.recovery,
            corrections: Corrections::new(change.fit_patterns),
            patterns,
            low: SVector::from_fn(|i, _| bounds[i].0),
            high: SVector::from_fn(|i, _| bounds[i].1),
            trial: 0,
            booked: 0,
            held: Vec::new(),
        };
        if change.recovery == ChangeRecovery::Correct {
            inner.keep_recent_trials();
        }
        WatchedLearner {
            inner,
            watch: Some(watch),
        }
    }
}

impl Watch {
    /// Books the trial's patterns with the watch, the seeds and a fit going on; `inner`
    /// answers them as it did during the trial.
    fn book(&mut self, inner: &mut dyn SingleModel, path: &[Observation]) {
        for (from, to) in self.patterns.pairs(path) {
            let pattern = adjusted_pattern(from, to);
            let answer = answer_at(inner, &self.corrections.query(&pattern.input));
            let miss = (answer - pattern.target).norm();
            self.misses.book(Some(miss), pattern.target.norm());
            if self.recovery == ChangeRecovery::Correct {
                self.corrections.remember(self.trial, (from, to), &pattern);
                if self.corrections.fitting() {
                    self.corrections.book(&pattern);
                }
            }
            self.booked += 1;
        }
        self.misses.close_trial();
    }

    /// The path with its readings through the fixed corrections.
    fn corrected(&self, path: &[Observation]) -> Vec<Observation> {
        path.iter()
            .map(|o| {
                let x = self.corrections.through_fixed(&o.query().five_inputs());
                Observation {
                    theta_deg: o.theta_deg,
                    c: Vector3::new(x[2], x[3], x[4]),
                }
            })
            .collect()
    }

    /// Books the trial, then lets `inner` learn it through the fixed corrections, or holds
    /// it back while a correction is fitted; once that is fixed, `inner` learns every trial
    /// held back through it.
    fn learn(
        &mut self,
        inner: &mut dyn SingleModel,
        path: &[Observation],
    ) -> Result<(), LearnError> {
        self.book(inner, path);
        if !self.corrections.fitting() {
            return inner.learn(&self.corrected(path));
        }
        self.held.push(path.to_vec());
        if self.corrections.refit(|x| answer_at(inner, x)).is_some() {
            for held in std::mem::take(&mut self.held) {
                inner.learn(&self.corrected(&held))?;
            }
        }
        Ok(())
    }

    /// Closes the trial booked so far before `trial`; on an alarm `inner` forgets, or it
    /// drops what it learned since the change and a correction is fitted from the trial the
    /// change is dated to.
    fn start_trial(&mut self, inner: &mut dyn SingleModel, trial: usize) {
        self.trial = trial;
        let Some(changed_at) = self.misses.start_trial(trial, self.booked) else {
            return;
        };
        match self.recovery {
            ChangeRecovery::Forget => inner.forget_before(changed_at),
            ChangeRecovery::Correct => {
                inner.unlearn_since(changed_at);
                self.corrections.start(changed_at, &self.low, &self.high);
            }
        }
    }
}

/// `learner`'s answer at the five inputs `x`.
fn answer_at(learner: &mut dyn SingleModel, x: &SVector<f64, 5>) -> Vector3<f64> {
    learner.propose(&Query {
        c: Vector3::new(x[2], x[3], x[4]),
        theta2_deg: x[0],
        theta3_deg: x[1],
    })
}

/// The path without the observations whose angles or readings are not finite.
fn finite_path(path: &[Observation]) -> Cow<'_, [Observation]> {
    let finite = |o: &Observation| o.theta_deg.iter().chain(o.c.iter()).all(|v| v.is_finite());
    if path.iter().all(finite) {
        Cow::Borrowed(path)
    } else {
        Cow::Owned(path.iter().filter(|o| finite(o)).copied().collect())
    }
}

impl Learner for WatchedLearner {
    fn name(&self) -> &str {
        self.inner.name()
    }

    /// The learner's answer (through the corrections, once there are any), zero where it
    /// is not finite.
    fn propose(&mut self, query: &Query) -> Vector3<f64> {
        let answer = match &self.watch {
            Some(watch) => answer_at(
                self.inner.as_mut(),
                &watch.corrections.query(&query.five_inputs()),
            ),
            None => self.inner.propose(query),
        };
        finite_or_still(answer)
    }

    /// Learns the trial's finite observations, booked by the watch first if there is one.
    fn learn(&mut self, path: &[Observation]) -> Result<(), LearnError> {
        let path = finite_path(path);
        match &mut self.watch {
            Some(watch) => watch.learn(self.inner.as_mut(), &path),
            None => self.inner.learn(&path),
        }
    }

    fn stats(&self) -> LearnerStats {
        self.inner.stats()
    }

    fn take_relearn_request(&mut self) -> bool {
        self.inner.take_relearn_request()
    }

    fn start_trial(&mut self, trial: usize) {
        self.inner.start_trial(trial);
        if let Some(watch) = &mut self.watch {
            watch.start_trial(self.inner.as_mut(), trial);
        }
    }

    fn drain_events(&mut self, sink: &mut Vec<ModelEvent>) {
        self.inner.drain_events(sink);
        if let Some(watch) = &mut self.watch {
            watch.misses.drain_events(sink);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::learn::{Mlp, MlpSettings};

    fn pose(theta: [f64; 3], c: [f64; 3]) -> Observation {
        Observation {
            theta_deg: Vector3::from(theta),
            c: Vector3::from(c),
        }
    }

    fn mlp() -> Box<dyn SingleModel> {
        Box::new(Mlp::new(MlpSettings::default(), [(-200.0, 200.0); 5]))
    }

    #[test]
    fn a_pose_with_a_reading_that_is_not_finite_is_left_out_of_the_trial() {
        let mut learner = WatchedLearner::unwatched(mlp());
        let path = [
            pose([0.0, 30.0, 90.0], [40.0, -20.0, 30.0]),
            pose([3.0, 32.0, 87.0], [f64::NAN, -5.0, 8.0]),
            pose([4.0, 33.0, 86.0], [0.0, 0.0, 0.0]),
        ];
        learner.learn(&path).unwrap();
        // The one pair of the two finite poses.
        assert_eq!(learner.stats().patterns, 1);
    }

    #[test]
    fn an_answer_that_is_not_finite_is_no_move() {
        let mut learner = WatchedLearner::unwatched(mlp());
        let query = Query {
            c: Vector3::new(f64::INFINITY, 0.0, 0.0),
            theta2_deg: 30.0,
            theta3_deg: f64::NAN,
        };
        assert_eq!(learner.propose(&query), Vector3::zeros());
    }
}
