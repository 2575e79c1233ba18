//! The replay buffer: the most recent learning patterns, dated by trial, oldest first.

use super::network::Input;
use nalgebra::Vector3;
use std::collections::VecDeque;

/// A learning pattern as the net sees it, with its trial.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct Sample {
    /// The scaled input.
    pub(super) input: Input,
    /// The scaled input with the target centred (cx*, cy*, cz* = 0).
    pub(super) centred: Input,
    /// The target in `norm_out` units.
    pub(super) target: Vector3<f64>,
    /// The trial it was learned in.
    pub(super) trial: usize,
}

/// At most `capacity` samples; a new one pushes out the oldest.
#[derive(Debug, Clone, PartialEq)]
pub(super) struct Replay {
    samples: VecDeque<Sample>,
    capacity: usize,
}

impl Replay {
    /// An empty buffer of `capacity` (at least 1) samples, allocated now.
    pub(super) fn new(capacity: usize) -> Replay {
        Replay {
            samples: VecDeque::with_capacity(capacity),
            capacity,
        }
    }

    /// Samples held.
    pub(super) fn len(&self) -> usize {
        self.samples.len()
    }

    /// The `i`-th oldest sample.
    pub(super) fn get(&self, i: usize) -> Option<&Sample> {
        self.samples.get(i)
    }

    /// Keeps `sample`, dropping the oldest when full.
    pub(super) fn push(&mut self, sample: Sample) {
        if self.samples.len() == self.capacity {
            self.samples.pop_front();
        }
        self.samples.push_back(sample);
    }

    /// Drops every sample of the trials before `trial`.
    pub(super) fn drop_before(&mut self, trial: usize) {
        while self.samples.front().is_some_and(|s| s.trial < trial) {
            self.samples.pop_front();
        }
    }

    /// Drops every sample of the trials from `trial` on.
    pub(super) fn drop_since(&mut self, trial: usize) {
        while self.samples.back().is_some_and(|s| s.trial >= trial) {
            self.samples.pop_back();
        }
    }
}
