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

mod settings;

use super::perceptron::Perceptron;
use super::tree::{Halving, NestedLearner, Region};
use crate::learn::{adjusted_pattern, LearnError, Method, Query};
use nalgebra::SVector;
use std::path::PathBuf;

pub use settings::Lin5Settings;
pub(crate) use settings::FIVE_INPUT_BOUNDS;
pub(crate) use settings::LIN5_FACTS;

/// The stream of the run's seed that lin5's own draws (known patterns) come from, apart
/// from the trial loop's.
const RNG_STREAM: u64 = 0x6c69_6e35;

/// The `lin5` learner: a nested tree of perceptrons over the adjusted 5-input patterns.
pub type Lin5 = NestedLearner<Perceptron<5, 6>, Halving<5>, 5>;

impl Lin5 {
    /// A `lin5` learner set up by `settings`, keeping its patterns in `pat_file` when given
    /// (the file is created or emptied now), otherwise in memory.
    pub fn new(settings: &Lin5Settings, pat_file: Option<PathBuf>) -> Result<Self, LearnError> {
        let low = SVector::<f64, 5>::from_fn(|i, _| settings.bounds[i].0);
        let high = SVector::<f64, 5>::from_fn(|i, _| settings.bounds[i].1);
        NestedLearner::build(
            Method::Lin5,
            &settings.nested,
            (
                Halving::new(Region::from_bounds(low, high)),
                Perceptron::new(settings.perceptron),
            ),
            (adjusted_pattern, Query::five_inputs),
            pat_file,
            RNG_STREAM,
        )
    }
}

#[cfg(test)]
mod tests;
