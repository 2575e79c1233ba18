//! What a tree node's model must do.

use nalgebra::{SVector, Vector3};

/// A node's local model of the mapping input → Δθ.
///
/// Inputs are in the node's local coordinates (its box mapped to [−1, 1] in every
/// dimension, see [`Region::local`](super::Region::local)); targets and answers are joint
/// moves in degrees. New nodes are clones of a fresh model.
pub(crate) trait Approximator<const N: usize>: Clone + std::fmt::Debug {
    /// Takes in one pattern. The answer may lag behind until [`refit`](Self::refit).
    fn add(&mut self, input: &SVector<f64, N>, target: &Vector3<f64>);

    /// Brings the answer up to date with every pattern taken in.
    fn refit(&mut self);

    /// The model's Δθ at `input`, or `None` while it has no usable model (too few
    /// patterns, a singular fit). Never NaN or infinite for a finite input.
    fn answer(&self, input: &SVector<f64, N>) -> Option<Vector3<f64>>;
}
