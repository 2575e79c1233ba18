//! The Nested Perceptron's node model: a linear least-squares fit from incrementally
//! updated normal-equation sums, in staggered sum-sets that forget (study §4.1, §4.2.1).
//!
//! A pattern (input u, target Δθ) adds z zᵀ and z Δθᵀ, z = (u, 1), to the sums of every
//! sum-set taking patterns (see [`stagger`] for which), kept as blocks that each pattern
//! is added to once, the sets being sums of blocks. A refit solves the current set's
//! normal equations once for all three joints; between two switches of the current set,
//! which then only gains patterns, that fit is carried by rank-one updates instead (see
//! [`carried`]), and a refit has nothing left to do. Each block knows the sequence number
//! of the oldest pattern in it; after a detected change of the mapping, a perceptron
//! holding a pattern older than the change drops every block and starts over (the tree
//! then gives it back the stored patterns from after the change), keeping the fit it had
//! as its stale answer. Inputs are in the node's local coordinates (its box mapped to
//! [−1, 1]), which keeps the sums well scaled however small the box. A singular or
//! ill-conditioned fit gives no answer, so the tree asks the node's parent instead; the
//! model never answers NaN. Inputs that queries always hold at 0 (lin8's readings after
//! the move) may be left out of a fit while they have not varied.

mod carried;
mod lu;
mod settings;
mod stagger;
mod sums;

pub use settings::PerceptronSettings;

use crate::learn::nested::tree::Approximator;
use carried::CarriedFit;
use nalgebra::{SMatrix, SVector, Vector3};
use stagger::Stagger;
use std::collections::VecDeque;
use std::ops::Range;
use sums::NormalSums;

/// The highest leverage zᵀ(Σ z zᵀ)⁻¹z of an input at which a fit supports it: the answer's
/// variance there is at most this many times a single pattern's. (The set's own patterns
/// never exceed 1; after a change, 1 kept lin5 from young nodes it needed, 10 let lin8's
/// run far off: docs/ADAPTATION.md.)
const MAX_LEVERAGE: f64 = 3.0;

/// A perceptron over `N` inputs; `M` = N + 1 (the inputs and a constant).
#[derive(Debug, Clone)]
pub struct Perceptron<const N: usize, const M: usize> {
    /// The sums of the patterns since each set's (re)start, a block per start; the
    /// current set is their sum. The front block is number `front` (see [`Stagger`]).
    blocks: VecDeque<NormalSums<M>>,
    front: u64,
    stagger: Stagger,
    /// The current fit: Δθ = weights · (u, 1).
    weights: Option<SMatrix<f64, 3, M>>,
    /// While `weights` is the current set's exact fit and no input is idle: what carries
    /// it to each pattern the set takes.
    carried: Option<CarriedFit<M>>,
    /// Which of (u, 1) may be left out of a fit while they stay 0.
    may_idle: [bool; M],
    /// The fit before the last start-over (after a detected change).
    stale: Option<Box<SMatrix<f64, 3, M>>>,
}

impl<const N: usize, const M: usize> Perceptron<N, M> {
    const AUGMENTED: () = assert!(M == N + 1, "a perceptron has N inputs and a constant");

    /// A perceptron with `settings.sum_sets` staggered sum-sets of at most
    /// `settings.set_size` patterns each; both at least 1.
    pub(crate) fn new(settings: PerceptronSettings) -> Self {
        let () = Self::AUGMENTED;
        let PerceptronSettings {
            sum_sets: sets,
            set_size,
        } = settings;
        let stagger = Stagger::new(sets, set_size);
        Perceptron {
            blocks: VecDeque::with_capacity(sets.max(1)),
            front: 0,
            stagger,
            weights: None,
            carried: None,
            may_idle: [false; M],
            stale: None,
        }
    }

    /// This perceptron, told that queries always hold `inputs` at 0 in local coordinates
    /// (lin8's d, the middle of its d box). While such an input has not varied — lin8's
    /// pre-learning and known patterns all end at d = 0 — the fit leaves it out (weight 0,
    /// exact at 0) instead of giving no answer. Other inputs that never vary still make the
    /// fit singular.
    pub(crate) fn asked_at_zero(mut self, inputs: Range<usize>) -> Self {
        for i in inputs.filter(|&i| i < N) {
            self.may_idle[i] = true;
        }
        self
    }

    fn augmented(input: &SVector<f64, N>) -> SVector<f64, M> {
        SVector::from_fn(|i, _| if i < N { input[i] } else { 1.0 })
    }
}

impl<const N: usize, const M: usize> Approximator<N> for Perceptron<N, M> {
    fn add(&mut self, input: &SVector<f64, N>, target: &Vector3<f64>, seq: u64) {
        let z = Self::augmented(input);
        let arrival = self.stagger.arrive();
        if arrival.switched {
            self.carried = None;
        }
        let mut spare = None;
        while self.front < self.stagger.first_block() {
            spare = self.blocks.pop_front();
            self.front += 1;
        }
        if arrival.opens {
            let mut block = spare.unwrap_or_else(NormalSums::new);
            block.clear();
            self.blocks.push_back(block);
        }
        // (The first pattern opens a block: there always is one.)
        if let Some(block) = self.blocks.back_mut() {
            block.add(&z, target, seq);
        }
        // (The current set takes every pattern.)
        if let (Some(carried), Some(weights)) = (&mut self.carried, &mut self.weights) {
            if !carried.take(weights, &z, target) {
                self.carried = None;
            }
        }
    }

    /// A set holding a pattern numbered below `cutoff` makes the perceptron start over:
    /// every set cleared, the stagger schedule restarted, no answer until refitted; the fit
    /// it had becomes its stale answer.
    fn forget_before(&mut self, cutoff: u64) -> bool {
        let stale = self
            .blocks
            .iter()
            .any(|block| block.oldest().is_some_and(|oldest| oldest < cutoff));
        if stale {
            self.blocks.clear();
            self.front = 0;
            self.stagger.restart();
            self.carried = None;
            self.stale = self.weights.take().map(Box::new);
        }
        stale
    }

    /// Nothing to do while the fit is carried; otherwise a full solve of the current set,
    /// which establishes a carried fit when it answers with no idle input.
    fn refit(&mut self) {
        if self.carried.is_some() {
            return;
        }
        let solution = self.current_set().solve(&self.may_idle);
        self.weights = solution.as_ref().map(|s| s.weights);
        self.carried = solution.and_then(|s| s.inverse.as_ref().map(CarriedFit::new));
    }

    fn answer(&self, input: &SVector<f64, N>) -> Option<Vector3<f64>> {
        self.weights.map(|w| w * Self::augmented(input))
    }

    /// True unless the fit is carried (its inverse at hand) and `input`'s leverage is above
    /// [`MAX_LEVERAGE`].
    fn supports(&self, input: &SVector<f64, N>) -> bool {
        self.carried
            .as_ref()
            .is_none_or(|c| c.leverage(&Self::augmented(input)) <= MAX_LEVERAGE)
    }

    fn stale_answer(&self, input: &SVector<f64, N>) -> Option<Vector3<f64>> {
        self.stale.as_ref().map(|w| **w * Self::augmented(input))
    }
}

impl<const N: usize, const M: usize> Perceptron<N, M> {
    /// The current set's sums: those of every block kept.
    fn current_set(&self) -> NormalSums<M> {
        let mut set = NormalSums::new();
        for block in &self.blocks {
            set.absorb(block);
        }
        set
    }

    /// The sequence number of the oldest pattern in the set the answer is solved from.
    #[cfg(test)]
    pub(crate) fn answering_oldest(&self) -> Option<u64> {
        self.current_set().oldest()
    }
}

#[cfg(test)]
mod tests;
