//! The replay buffer: the most recent learning patterns, numbered, oldest first.

use super::network::Input;
use nalgebra::Vector3;
use std::collections::VecDeque;

/// A learning pattern as the net sees it, with its number.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct Sample {
    /// The scaled input.
    pub(super) input: Input,
    /// The scaled input with the target centred (cx*, cy*, cz* = 0).
    pub(super) centred: Input,
    /// The target in `norm_out` units.
    pub(super) target: Vector3<f64>,
    /// The pattern's number in the run (0 first).
    pub(super) seq: u64,
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

    /// Drops every sample numbered below `seq`.
    pub(super) fn drop_before(&mut self, seq: u64) {
        while self.samples.front().is_some_and(|s| s.seq < seq) {
            self.samples.pop_front();
        }
    }
}
