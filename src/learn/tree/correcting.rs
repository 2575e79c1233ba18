//! Recovering from a detected change by correcting the readings (`change_recovery
//! correct`): the tree is kept as it was, and a [`ReadingCorrection`] fitted from the
//! patterns since the change carries the new readings back to the ones it learned.
//!
//! At an alarm the patterns stored since the estimated change (learned before it was
//! found) seed the fit. From then on the tree learns nothing while the correction is fitted:
//! each trial's patterns join the fit, which is redone after the trial, and queries are
//! answered through it as soon as [`FIT_FROM`] patterns are in. Once `change_fit_patterns`
//! are, the correction is fixed, the patterns that came after the alarm are trained through it,
//! and every later pattern and query goes through it: the tree goes on learning, in the
//! readings it knows, and what the correction misses it learns as it would any new
//! pattern, splitting sub-boxes off at `change_split_patterns` stored patterns from then on
//! (the changed robot works in poses the tree covers only coarsely) and answering a query
//! only from nodes whose fit supports it. A later change adds a correction on top of those
//! before it.

use super::{Approximator, BranchRule, NestedTree};
use crate::learn::change::ReadingCorrection;
use crate::learn::{LearnError, Pattern};
use nalgebra::SVector;

/// Patterns since a change before queries are answered through its correction.
pub(crate) const FIT_FROM: usize = 30;

/// The corrections fixed so far, applied in order, and the one being fitted.
#[derive(Debug, Clone)]
pub(crate) struct Corrections<const N: usize> {
    fixed: Vec<ReadingCorrection<N>>,
    fitting: Option<Fitting<N>>,
    /// Patterns since a change its correction is fitted from before it is fixed.
    fit_patterns: usize,
}

/// A correction being fitted, and its patterns (in the readings of the fixed corrections).
#[derive(Debug, Clone)]
struct Fitting<const N: usize> {
    correction: ReadingCorrection<N>,
    patterns: Vec<Pattern<N>>,
    /// How many of `patterns` (the first ones) the tree learned before the alarm.
    learned: usize,
}

impl<const N: usize> Corrections<N> {
    /// No correction yet; each will be fixed once fitted from `fit_patterns` patterns.
    pub(crate) fn new(fit_patterns: usize) -> Self {
        Corrections {
            fixed: Vec::new(),
            fitting: None,
            fit_patterns,
        }
    }

    /// Whether a correction is being fitted: the tree must learn nothing meanwhile.
    pub(crate) fn fitting(&self) -> bool {
        self.fitting.is_some()
    }

    /// The input `x` through the fixed corrections.
    fn through_fixed(&self, x: &SVector<f64, N>) -> SVector<f64, N> {
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

    /// The pattern the tree learns for `pattern` once no correction is being fitted.
    pub(crate) fn pattern(&self, pattern: &Pattern<N>) -> Pattern<N> {
        Pattern {
            input: self.through_fixed(&pattern.input),
            target: pattern.target,
        }
    }

    /// Starts fitting a correction for a change, from the patterns `since` it that the tree
    /// stored (already in the fixed corrections' readings). A correction still being
    /// fitted is dropped: the change it was for is part of this one.
    pub(crate) fn start(
        &mut self,
        since: Vec<Pattern<N>>,
        low: &SVector<f64, N>,
        high: &SVector<f64, N>,
    ) {
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
    /// (the tree's). Once there are `fit_patterns`, fixes it and returns the patterns
    /// from after the alarm, through it, for the tree to learn (`None` while it is not
    /// fixed).
    pub(crate) fn refit(
        &mut self,
        answer: impl Fn(&SVector<f64, N>) -> nalgebra::Vector3<f64>,
    ) -> Option<Vec<Pattern<N>>> {
        let f = self.fitting.as_mut()?;
        if f.patterns.len() >= FIT_FROM {
            f.correction.fit(&f.patterns, answer);
        }
        if f.patterns.len() < self.fit_patterns {
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

impl<A: Approximator<N>, R: BranchRule<N>, const N: usize> NestedTree<A, R, N> {
    /// Copies of the stored patterns numbered `cutoff` or later.
    pub(crate) fn stored_since(&mut self, cutoff: u64) -> Result<Vec<Pattern<N>>, LearnError> {
        let mut since = Vec::new();
        for id in self.reachable() {
            for i in 0..self.nodes[id as usize].bins.len() {
                let bin = self.nodes[id as usize].bins[i];
                self.bins.for_each_pattern(bin, |pattern, seq| {
                    if seq >= cutoff {
                        since.push(*pattern);
                    }
                })?;
            }
        }
        Ok(since)
    }

    /// Once a correction is fixed the tree learns a changed robot, which works in poses the
    /// tree covers only coarsely: from then on a sub-box is split off once it holds
    /// `split_patterns` stored patterns (if that is sooner than before), and, since a node
    /// split off from so few patterns may fit them in a way that runs far off between and
    /// beyond them, a query is answered by the deepest node whose fit supports it.
    pub(crate) fn after_correction(&mut self, split_patterns: usize) {
        let split = &mut self.settings.min_pats_for_split;
        *split = (*split).min(split_patterns);
        self.supported_answers = true;
    }

    /// The corners of the root's box.
    pub(crate) fn root_box(&self) -> (SVector<f64, N>, SVector<f64, N>) {
        let region = &self.nodes[super::ROOT as usize].region;
        (region.low(), region.high())
    }
}
