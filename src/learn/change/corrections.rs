//! The corrections of the readings a learner answers through after detected changes
//! (`change_recovery correct`), shared by the nested learners and the single-model wrapper:
//! the learner's model is kept as it was, and a [`ReadingCorrection`] fitted from the
//! patterns since the change carries the new readings back to the ones it learned.
//!
//! At an alarm the patterns of the trials since the estimated change (learned before it was
//! found) that end near the centre seed the fit: those whose later pose reads at most
//! [`SEED_SHARE`] of the earlier one's. Before the alarm the old model lost its way; a pair
//! that ends far off is where the old model is poor in any case, or (its adjusted form) only
//! a first-order estimate, and when frames during moves are learned such pairs are most of
//! a trial's and pulled the fit of a 30° turn to 17°. From then on the learner learns nothing
//! while the correction is fitted: each trial's patterns join the fit, which is redone after
//! the trial, and queries are answered through it as soon as [`FIT_FROM`] patterns are in.
//! Once `change_fit_patterns` are and a refit no longer moves it, the correction is fixed,
//! the patterns that came after the alarm are learned through it, and every later pattern
//! and query goes through it: the learner goes on learning, in the readings it knows. A
//! later change adds a correction on top of those before it.

use super::ReadingCorrection;
use crate::learn::{Observation, Pattern};
use nalgebra::SVector;
use std::collections::VecDeque;

/// Patterns since a change before queries are answered through its correction.
pub(crate) const FIT_FROM: usize = 30;
/// A pattern of a trial before the alarm seeds the fit if its later pose reads at most this
/// share of its earlier one's (seeds 1–8, with frames during moves and without:
/// docs/ADAPTATION.md).
const SEED_SHARE: f64 = 0.05;
/// Trials whose seeds are kept: an alarm dates a change within its run of positive sums,
/// which for every event measured began at most 46 trials before it.
pub(crate) const SEED_TRIALS: usize = 200;
/// A correction has settled when a refit moves no entry of A by more than this: only then
/// is it fixed (lin8 learning during moves fixed a 90° turn at 59° while it still moved,
/// and never recovered: docs/ADAPTATION.md).
const SETTLED: f64 = 0.005;
/// A correction that has not settled is fixed all the same once it has this many times
/// `change_fit_patterns` patterns.
const UNSETTLED_LIMIT: usize = 4;

/// The corrections fixed so far, applied in order, and the one being fitted.
#[derive(Debug, Clone)]
pub(crate) struct Corrections<const N: usize> {
    fixed: Vec<ReadingCorrection<N>>,
    fitting: Option<Fitting<N>>,
    /// Patterns since a change its correction is fitted from before it is fixed.
    fit_patterns: usize,
    /// The seeds of the recent trials, with their trial, oldest first.
    seeds: VecDeque<(usize, Pattern<N>)>,
}

/// A correction being fitted, and its patterns (in the readings of the fixed corrections).
#[derive(Debug, Clone)]
struct Fitting<const N: usize> {
    correction: ReadingCorrection<N>,
    patterns: Vec<Pattern<N>>,
    /// How many of `patterns` (the first ones) the learner learned before the alarm.
    learned: usize,
}

impl<const N: usize> Corrections<N> {
    /// No correction yet; each will be fixed once fitted from `fit_patterns` patterns.
    pub(crate) fn new(fit_patterns: usize) -> Self {
        Corrections {
            fixed: Vec::new(),
            fitting: None,
            fit_patterns,
            seeds: VecDeque::new(),
        }
    }

    /// Keeps `pattern`, made of the pose pair (`from`, `to`) of trial `trial`, as a seed of
    /// a later fit if it ends near the centre; forgets the seeds of trials too old to seed
    /// one.
    pub(crate) fn remember(
        &mut self,
        trial: usize,
        (from, to): (&Observation, &Observation),
        pattern: &Pattern<N>,
    ) {
        while self
            .seeds
            .front()
            .is_some_and(|&(t, _)| t + SEED_TRIALS <= trial)
        {
            self.seeds.pop_front();
        }
        if to.c.norm() <= SEED_SHARE * from.c.norm() {
            self.seeds.push_back((trial, *pattern));
        }
    }

    /// Whether a correction is being fitted: the learner must learn nothing meanwhile.
    pub(crate) fn fitting(&self) -> bool {
        self.fitting.is_some()
    }

    /// The input `x` through the fixed corrections.
    pub(crate) fn through_fixed(&self, x: &SVector<f64, N>) -> SVector<f64, N> {
        self.fixed.iter().fold(*x, |x, c| c.apply(&x))
    }

    /// The input a query at `x` is answered at.
    pub(crate) fn query(&self, x: &SVector<f64, N>) -> SVector<f64, N> {
        let x = self.through_fixed(x);
        match &self.fitting {
            Some(f) if f.patterns.len() >= FIT_FROM => f.correction.apply(&x),
            _ => x,
        }
    }

    /// The pattern the learner learns for `pattern` once no correction is being fitted.
    pub(crate) fn pattern(&self, pattern: &Pattern<N>) -> Pattern<N> {
        Pattern {
            input: self.through_fixed(&pattern.input),
            target: pattern.target,
        }
    }

    /// Starts fitting a correction for a change at trial `changed_at`, seeded by the kept
    /// patterns of the trials since then. A correction still being fitted is dropped: the
    /// change it was for is part of this one.
    pub(crate) fn start(
        &mut self,
        changed_at: usize,
        low: &SVector<f64, N>,
        high: &SVector<f64, N>,
    ) {
        let since: Vec<Pattern<N>> = self
            .seeds
            .iter()
            .filter(|&&(t, _)| t >= changed_at)
            .map(|(_, p)| self.pattern(p))
            .collect();
        self.fitting = Some(Fitting {
            correction: ReadingCorrection::identity(low, high),
            learned: since.len(),
            patterns: since,
        });
    }

    /// Books a pattern of a trial while a correction is fitted.
    pub(crate) fn book(&mut self, pattern: &Pattern<N>) {
        let input = self.through_fixed(&pattern.input);
        if let Some(f) = &mut self.fitting {
            f.patterns.push(Pattern {
                input,
                target: pattern.target,
            });
        }
    }

    /// After a trial: fits the correction to the patterns since the change by `answer`
    /// (the learner's). Once there are `fit_patterns` and the fit has settled (or there are
    /// [`UNSETTLED_LIMIT`] times as many), fixes it and returns the patterns from after the
    /// alarm, through it, for the learner to learn (`None` while it is not fixed).
    pub(crate) fn refit(
        &mut self,
        answer: impl FnMut(&SVector<f64, N>) -> nalgebra::Vector3<f64>,
    ) -> Option<Vec<Pattern<N>>> {
        let f = self.fitting.as_mut()?;
        let before = f.correction.clone();
        if f.patterns.len() >= FIT_FROM {
            f.correction.fit(&f.patterns, answer);
        }
        let settled = f.correction.moved_from(&before) <= SETTLED;
        if f.patterns.len() < self.fit_patterns
            || !settled && f.patterns.len() < UNSETTLED_LIMIT * self.fit_patterns
        {
            return None;
        }
        let Fitting {
            correction,
            patterns,
            learned,
        } = self.fitting.take().expect("fitting");
        let fresh = patterns[learned..]
            .iter()
            .map(|p| Pattern {
                input: correction.apply(&p.input),
                target: p.target,
            })
            .collect();
        self.fixed.push(correction);
        Some(fresh)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::Vector3;

    fn pose(c: f64) -> Observation {
        Observation {
            theta_deg: Vector3::new(0.0, 30.0, 60.0),
            c: Vector3::new(c, 0.0, 0.0),
        }
    }

    fn pattern(x: f64) -> Pattern<5> {
        Pattern {
            input: SVector::from([30.0, 60.0, x, 0.0, 0.0]),
            target: Vector3::new(x, 0.0, 0.0),
        }
    }

    fn seeds_from(corrections: &mut Corrections<5>, changed_at: usize) -> Vec<f64> {
        let bound = SVector::repeat(100.0);
        corrections.start(changed_at, &-bound, &bound);
        let fitting = corrections.fitting.as_ref().expect("fitting");
        assert_eq!(fitting.learned, fitting.patterns.len());
        fitting.patterns.iter().map(|p| p.input[2]).collect()
    }

    #[test]
    fn a_fit_is_seeded_by_the_pairs_since_the_change_that_end_near_the_centre() {
        let mut corrections = Corrections::<5>::new(300);
        for trial in 1..=10 {
            let t = trial as f64;
            // Ends at 4% of where it started: a seed. Ends at 10%: none.
            corrections.remember(trial, (&pose(50.0), &pose(2.0)), &pattern(t));
            corrections.remember(trial, (&pose(50.0), &pose(5.0)), &pattern(-t));
        }
        assert_eq!(seeds_from(&mut corrections, 8), [8.0, 9.0, 10.0]);
    }

    /// A linear model over lin5's inputs.
    fn learned(x: &SVector<f64, 5>) -> Vector3<f64> {
        let w = nalgebra::Matrix3::new(0.02, -0.01, 0.003, 0.015, 0.03, -0.002, 0.001, 0.004, 0.05);
        w * Vector3::new(x[2], x[3], x[4]) + Vector3::new(0.0, 0.0, 0.01 * x[1])
    }

    #[test]
    fn a_correction_is_fixed_only_once_a_refit_no_longer_moves_it() {
        let turn = nalgebra::Rotation2::new(30f64.to_radians());
        let mut corrections = Corrections::<5>::new(40);
        let bound = SVector::repeat(200.0);
        corrections.start(0, &-bound, &bound);
        for i in 0..60 {
            let f = i as f64;
            let old = SVector::from([
                f - 30.0,
                10.0 + f,
                150.0 * (0.37 * f).sin(),
                120.0 * (0.61 * f).cos(),
                40.0 * (0.23 * f).sin(),
            ]);
            let xy = turn * nalgebra::Vector2::new(old[2], old[3]);
            corrections.book(&Pattern {
                input: SVector::from([old[0], old[1], xy.x, xy.y, old[4]]),
                target: learned(&old),
            });
        }
        // The first fit carries the turn back from no correction at all: it moved.
        assert!(corrections.refit(learned).is_none());
        // The second finds it where it was: fixed, and the 60 patterns come back.
        let fresh = corrections.refit(learned).expect("fixed");
        assert_eq!(fresh.len(), 60);
        assert!(!corrections.fitting());
    }

    #[test]
    fn seeds_older_than_any_alarm_could_date_are_forgotten() {
        let mut corrections = Corrections::<5>::new(300);
        corrections.remember(1, (&pose(50.0), &pose(0.0)), &pattern(1.0));
        corrections.remember(SEED_TRIALS, (&pose(50.0), &pose(0.0)), &pattern(2.0));
        corrections.remember(SEED_TRIALS + 1, (&pose(50.0), &pose(0.0)), &pattern(3.0));
        assert_eq!(seeds_from(&mut corrections, 0), [2.0, 3.0]);
    }
}
