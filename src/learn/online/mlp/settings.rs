//! Settings of the `mlp` learner.

use crate::learn::MethodFacts;
use crate::learn::PatternSettings;

/// Settings of the `mlp` learner. Inputs are scaled onto [−1, 1] by their boundaries and
/// outputs divided by `norm_out` degrees before any of these apply.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MlpSettings {
    /// Tanh units in each of the two hidden layers; 32 by default.
    pub hidden: usize,
    /// Adam's step size; 0.001 by default.
    pub rate: f64,
    /// Patterns drawn from the replay buffer per step; 32 by default.
    pub batch: usize,
    /// Adam steps after each trial; 16 by default.
    pub steps_per_trial: usize,
    /// The replay buffer holds this many most recent patterns; 10,000 by default.
    pub buffer: usize,
    /// True: the answer is anchored at the centred target, f(x) − f(x with cx*, cy*, cz*
    /// = 0), so a centred target gives no move whatever the net learned; true by default
    /// (false: a plain net).
    pub anchored: bool,
    /// Outputs Δθ are learned divided by this (degrees); 10 by default.
    pub norm_out: f64,
    /// Which pose pairs are patterns (`minimal_joint_move`).
    pub patterns: PatternSettings,
    /// Seed of the initial weights and of the batches' draws; 1 by default.
    pub seed: u64,
}

impl Default for MlpSettings {
    fn default() -> Self {
        MlpSettings {
            hidden: 32,
            rate: 0.001,
            batch: 32,
            steps_per_trial: 16,
            buffer: 10_000,
            anchored: true,
            norm_out: 10.0,
            patterns: PatternSettings::default(),
            seed: 1,
        }
    }
}

/// What the program knows of `mlp` besides its learner (see [`Method::facts`](crate::learn::Method::facts)).
pub(crate) const MLP_FACTS: MethodFacts = MethodFacts {
    name: "mlp",
    size: |stats| format!("replay buffer: {} patterns; ", stats.patterns),
    counts_nodes: false,
    kb_per_trial: 0.0,
    bounded: true,
    watches_changes: true,
    slow_entries: "mlp_steps_per_trial, mlp_batch, mlp_hidden",
    shared_defaults: &[],
};
