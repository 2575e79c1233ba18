//! The library's front door for a learner written outside the crate: the `Learner` trait
//! and what it is handed (queries, observed paths, patterns), the config and its input
//! boundaries, and the calls that run it. `use eyehand::prelude::*;` is all such a
//! learner needs (`examples/custom_learner.rs`).

pub use crate::experiment::setup::input_bounds;
pub use crate::experiment::{run_learner, Config, Event, RunOptions, RunResult, RunSetup};
pub use crate::learn::{
    adjusted_pattern, pose_pairs, unadjusted_pattern, LearnError, Learner, LearnerStats,
    Observation, Pattern, Pattern5, Pattern8, PatternSettings, Query,
};
