//! `lin5`: the Nested Perceptron with input adjustment (study chapter 4).
//!
//! The input is (θ2, θ3, cx*, cy*, cz*), 5 dimensions, each halved at every depth (32
//! branches); every tree node holds a [`Perceptron`]. A trial's pose pairs give adjusted
//! patterns (see [`adjusted_pattern`]), all of which are trained, each to its node and all
//! of the node's ancestors. A query asks for the move that brings the camera reading to
//! zero, so its input is the reading itself: (θ2, θ3, cx, cy, cz).
//!
//! Input boundaries are `boundary_0` … `boundary_4`. As the study advises (§2.4.6), the
//! camera boundaries should put zero at one third or two thirds of their range: halving then
//! keeps zero away from every box edge at every depth, so answers near the target
//! interpolate rather than extrapolate.

use super::perceptron::Perceptron;
use super::tree::{learner_on_nested_tree, Halving, NestedLearner, Region, TreeSettings};
use super::{LearnError, Method};
use crate::experiment::Config;
use crate::learn::{adjusted_pattern, Query};
use nalgebra::SVector;
use std::path::PathBuf;

/// The stream of the run's seed that lin5's own draws (known patterns) come from, apart
/// from the trial loop's.
const RNG_STREAM: u64 = 0x6c69_6e35;

/// The `lin5` learner: a nested tree of perceptrons over the adjusted 5-input patterns.
#[derive(Debug)]
pub struct Lin5 {
    nested: NestedLearner<Perceptron<5, 6>, Halving<5>, 5>,
}

impl Lin5 {
    /// A `lin5` learner set up by `config` (boundaries 0–4, tree, perceptron, split, merge
    /// and change-detection entries, `seed`), keeping its patterns in `pat_file` when given
    /// (the file is created or emptied now), otherwise in memory.
    pub fn new(config: &Config, pat_file: Option<PathBuf>) -> Result<Self, LearnError> {
        let low = SVector::<f64, 5>::from_fn(|i, _| config.boundary(i).0);
        let high = SVector::<f64, 5>::from_fn(|i, _| config.boundary(i).1);
        let nested = NestedLearner::new(
            config,
            TreeSettings::from_config(config),
            Halving::new(Region::from_bounds(low, high)),
            Perceptron::new(config.nr_of_matrices, config.max_pats_in_mat),
            adjusted_pattern,
            pat_file,
            RNG_STREAM,
        )?;
        Ok(Lin5 { nested })
    }
}

learner_on_nested_tree!(Lin5, Method::Lin5, Query::five_inputs);

#[cfg(test)]
mod tests;
