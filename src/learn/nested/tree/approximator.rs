//! What a tree node's model must do.

use nalgebra::{SVector, Vector3};
use rand_chacha::ChaCha8Rng;

/// A stored pattern as a model is re-trained on it: local input and target Δθ (degrees).
pub(crate) type Sample<const N: usize> = (SVector<f64, N>, Vector3<f64>);

/// A node's local model of the mapping input → Δθ.
///
/// Inputs are in the node's local coordinates (its box mapped to [−1, 1] in every
/// dimension, see [`Region::local`](super::Region::local)); targets and answers are joint
/// moves in degrees. A new node's model is spawned from a template.
pub(crate) trait Approximator<const N: usize>: Clone + std::fmt::Debug {
    /// Whether the model is re-trained on stored patterns after every trial (a network,
    /// which learns only a little from each pattern it takes in). The tree then books which
    /// nodes took in patterns; see [`NestedTree::retrain_due`](super::NestedTree::retrain_due).
    const RETRAINED: bool = false;

    /// A new node's model, from this template: a copy unless the model draws its start
    /// from `rng`.
    fn spawn(&self, _rng: &mut ChaCha8Rng) -> Self {
        self.clone()
    }

    /// Takes in one pattern, number `seq` in the order the tree was given patterns (a known
    /// pattern carries the number of the pattern that earned it). The answer may lag behind
    /// until [`refit`](Self::refit).
    fn add(&mut self, input: &SVector<f64, N>, target: &Vector3<f64>, seq: u64);

    /// Brings the answer up to date with every pattern taken in.
    fn refit(&mut self);

    /// The model's Δθ at `input`, or `None` while it has no usable model (too few
    /// patterns, a singular fit). Never NaN or infinite for a finite input.
    fn answer(&self, input: &SVector<f64, N>) -> Option<Vector3<f64>>;

    /// Whether the model's fit at `input` is backed by the patterns it was fitted to rather
    /// than an extrapolation beyond them (true by default, and whenever the model cannot
    /// tell).
    fn supports(&self, _input: &SVector<f64, N>) -> bool {
        true
    }

    /// Forgets what came from patterns numbered below `cutoff` (the mapping changed there),
    /// if the model can tell them apart. True when it started over and must be given the
    /// stored patterns from `cutoff` on again; by default nothing is forgotten (a re-trained
    /// model is re-trained on the stored patterns, which by then are all newer).
    fn forget_before(&mut self, _cutoff: u64) -> bool {
        false
    }

    /// The answer at `input` of the model as it was before it last forgot, if it kept it
    /// (`None` by default).
    fn stale_answer(&self, _input: &SVector<f64, N>) -> Option<Vector3<f64>> {
        None
    }

    /// Re-trains the model on `batch`, a sample of the stored patterns of its box. Only
    /// called when [`RETRAINED`](Self::RETRAINED); nothing by default.
    fn retrain(&mut self, _batch: &[Sample<N>]) {}
}
