//! The contract every learner keeps with the trial loop.

use super::{LearnError, LearnerStats, ModelEvent};
use crate::learn::{Observation, Query};
use nalgebra::Vector3;

/// A learner of the eye-hand mapping `Δθ = N(c, θ2, θ3)`.
///
/// Angles are in degrees, camera readings in the camera's units (pixels for cx, cy; the
/// area measure for cz).
pub trait Learner: std::fmt::Debug {
    /// The learner's name: runs of it are filed under `data/<name>/` and reported under it
    /// (summary.json's `method`). A built-in learner answers its [`Method`](crate::learn::Method)'s name.
    fn name(&self) -> &str;

    /// The joint move (Δθ1, Δθ2, Δθ3 in degrees) this learner proposes for `query`.
    /// Must always be finite.
    fn propose(&mut self, query: &Query) -> Vector3<f64>;

    /// Learns from the observations of one finished trial (or pre-learning move), in the
    /// order they were made: every pair of poses gives a learning pattern. Fails only when
    /// the learner's storage (a pattern file) fails; the run then stops with what it wrote.
    fn learn(&mut self, path: &[Observation]) -> Result<(), LearnError>;

    /// Figures for the run's data files (`nodes`, `bins`, `patterns`, `abs_err`); all zero
    /// by default.
    fn stats(&self) -> LearnerStats {
        LearnerStats::default()
    }

    /// True once after the learner threw away everything it knew (a root merge), or after a
    /// detected change left it nothing valid to answer from: the trial loop then repeats
    /// pre-learning before the next trial.
    fn take_relearn_request(&mut self) -> bool {
        false
    }

    /// Tells the learner which trial comes next (1-based; 0 is pre-learning), so it can
    /// date what it learns. A learner watching for changes of the mapping weighs the trial
    /// before here, and may forget or cut before this trial's first move.
    fn start_trial(&mut self, _trial: usize) {}

    /// Moves the merges and detected changes since the last call into `sink`.
    fn drain_events(&mut self, _sink: &mut Vec<ModelEvent>) {}
}
