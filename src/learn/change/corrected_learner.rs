//! `change_recovery correct` for any learner with a model (lwpr, issgp, mlp, ffn, kohonen):
//! a wrapper that watches the learner's trials for a change of the mapping and, after an
//! alarm, answers through a correction of the readings fitted from the patterns since the
//! change, as the nested learners do within their tree (`nested/tree/correct_recovery.rs`).
//!
//! The wrapper knows the learner only through the [`Learner`] trait. Its watch books each
//! trial's summed miss relative to its summed move (`TrialMiss`), the misses those of the
//! learner's answers to the trial's adjusted patterns before it learns them. At an alarm the
//! patterns of the trials since the estimated change that end near the centre seed a
//! `Corrections` fit; from then on the learner learns nothing while the fit runs: each
//! trial's patterns join it, it is redone after the trial through the learner's own answers,
//! and queries go through it once it has enough patterns. Once it is fixed, the trials held
//! back are learned through it, and every later trial's readings and every query go through
//! the fixed corrections: the learner goes on learning in the readings it knows.

use super::{ChangeSettings, TrialMiss};
use crate::learn::nested::tree::Corrections;
use crate::learn::{
    adjusted_pattern, LearnError, Learner, LearnerStats, ModelEvent, Observation, PatternSettings,
    Query,
};
use nalgebra::{SVector, Vector3};

/// A learner whose readings are corrected after a detected change.
#[derive(Debug)]
pub struct CorrectedLearner {
    inner: Box<dyn Learner>,
    watch: TrialMiss,
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
    events: Vec<ModelEvent>,
}

impl CorrectedLearner {
    /// `inner` (which must not watch for changes itself), watched by `change` and
    /// corrected over the input box `bounds`; `patterns` says which pose pairs count.
    pub fn new(
        inner: Box<dyn Learner>,
        change: &ChangeSettings,
        patterns: PatternSettings,
        bounds: [(f64, f64); 5],
    ) -> CorrectedLearner {
        CorrectedLearner {
            inner,
            watch: TrialMiss::new(change),
            corrections: Corrections::new(change.fit_patterns),
            patterns,
            low: SVector::from_fn(|i, _| bounds[i].0),
            high: SVector::from_fn(|i, _| bounds[i].1),
            trial: 0,
            booked: 0,
            held: Vec::new(),
            events: Vec::new(),
        }
    }

    /// Books the trial's patterns with the watch, the seeds and a fit going on.
    fn book(&mut self, path: &[Observation]) {
        for (from, to) in self.patterns.pairs(path) {
            let pattern = adjusted_pattern(from, to);
            let answer = answer_at(self.inner.as_mut(), &self.corrections.query(&pattern.input));
            let miss = (answer - pattern.target).norm();
            self.watch.book(Some(miss), pattern.target.norm());
            self.corrections.remember(self.trial, (from, to), &pattern);
            if self.corrections.fitting() {
                self.corrections.book(&pattern);
            }
            self.booked += 1;
        }
        self.watch.close_trial();
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
}

/// `learner`'s answer at the five inputs `x`.
fn answer_at(learner: &mut dyn Learner, x: &SVector<f64, 5>) -> Vector3<f64> {
    learner.propose(&Query {
        c: Vector3::new(x[2], x[3], x[4]),
        theta2_deg: x[0],
        theta3_deg: x[1],
    })
}

impl Learner for CorrectedLearner {
    fn name(&self) -> &str {
        self.inner.name()
    }

    fn propose(&mut self, query: &Query) -> Vector3<f64> {
        answer_at(
            self.inner.as_mut(),
            &self.corrections.query(&query.five_inputs()),
        )
    }

    /// Books the trial, then lets the learner learn it through the fixed corrections, or
    /// holds it back while a correction is fitted; once that is fixed, the learner learns
    /// every trial held back through it.
    fn learn(&mut self, path: &[Observation]) -> Result<(), LearnError> {
        self.book(path);
        if !self.corrections.fitting() {
            let corrected = self.corrected(path);
            return self.inner.learn(&corrected);
        }
        self.held.push(path.to_vec());
        let inner = self.inner.as_mut();
        if self.corrections.refit(|x| answer_at(inner, x)).is_some() {
            for held in std::mem::take(&mut self.held) {
                let corrected = self.corrected(&held);
                self.inner.learn(&corrected)?;
            }
        }
        Ok(())
    }

    fn stats(&self) -> LearnerStats {
        self.inner.stats()
    }

    fn take_relearn_request(&mut self) -> bool {
        self.inner.take_relearn_request()
    }

    /// Closes the watch's trial; on an alarm starts fitting a correction from the trial
    /// the change is dated to.
    fn start_trial(&mut self, trial: usize) {
        self.inner.start_trial(trial);
        self.trial = trial;
        let before = self.events.len();
        if self.watch.start_trial(trial, self.booked).is_some() {
            self.watch.drain_events(&mut self.events);
            for event in &self.events[before..] {
                if let ModelEvent::Change { estimated_trial } = *event {
                    self.corrections
                        .start(estimated_trial, &self.low, &self.high);
                }
            }
        }
    }

    fn drain_events(&mut self, sink: &mut Vec<ModelEvent>) {
        self.inner.drain_events(sink);
        sink.append(&mut self.events);
    }
}
