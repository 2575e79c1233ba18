//! A stand-in node model for tests of the tree's bookkeeping.

use super::{Approximator, Sample};
use nalgebra::{SVector, Vector3};

/// A model that only keeps count: patterns taken in and the batches it was re-trained on
/// (when `RETRAINED`). It answers zero.
#[derive(Debug, Clone, Default)]
pub(super) struct Tally<const RETRAINED: bool, const N: usize> {
    pub(super) added: usize,
    pub(super) batches: Vec<Vec<Sample<N>>>,
}

impl<const RETRAINED: bool, const N: usize> Approximator<N> for Tally<RETRAINED, N> {
    const RETRAINED: bool = RETRAINED;

    fn add(&mut self, _input: &SVector<f64, N>, _target: &Vector3<f64>, _seq: u64) {
        self.added += 1;
    }

    fn refit(&mut self) {}

    fn answer(&self, _input: &SVector<f64, N>) -> Option<Vector3<f64>> {
        Some(Vector3::zeros())
    }

    fn retrain(&mut self, batch: &[Sample<N>]) {
        self.batches.push(batch.to_vec());
    }
}
