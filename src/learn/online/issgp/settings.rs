//! Settings of the `issgp` learner.

use crate::learn::MethodFacts;
use crate::learn::PatternSettings;

/// Settings of the `issgp` learner. Inputs are measured in their boundary ranges and
/// outputs in `norm_out` degrees before any of these apply.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct IssgpSettings {
    /// D, the random Fourier features (and the side of the Cholesky factor); 500 by
    /// default.
    pub features: usize,
    /// The squared-exponential kernel's length scale of each input (θ2, θ3, cx*, cy*,
    /// cz*), as a fraction of the input's boundary range; 1, 1, 0.5, 0.5, 0.5 by default.
    pub length_scales: [f64; 5],
    /// σn, the noise of a target, in `norm_out` units; 0.01 by default.
    pub noise: f64,
    /// σf, the kernel's signal amplitude, in `norm_out` units; 1 by default.
    pub signal: f64,
    /// λ, the factor every learned pattern (and the prior) is weighed down by at each new
    /// pattern; 1 by default (no forgetting).
    pub forgetting: f64,
    /// True: the answer is anchored at the centred target, g(x) − g(x with cx*, cy*, cz*
    /// = 0), so a centred target gives no move whatever was learned (the features are the
    /// differences); true by default (false: the paper's regression).
    pub anchored: bool,
    /// Outputs Δθ are learned divided by this (degrees); 10 by default.
    pub norm_out: f64,
    /// Which pose pairs are patterns (`minimal_joint_move`).
    pub patterns: PatternSettings,
    /// Seed of the features' frequencies and phases; 1 by default.
    pub seed: u64,
}

impl Default for IssgpSettings {
    fn default() -> Self {
        IssgpSettings {
            features: 500,
            length_scales: [1.0, 1.0, 0.5, 0.5, 0.5],
            noise: 0.01,
            signal: 1.0,
            forgetting: 1.0,
            anchored: true,
            norm_out: 10.0,
            patterns: PatternSettings::default(),
            seed: 1,
        }
    }
}

/// What the program knows of `issgp` besides its learner (see [`Method::facts`](crate::learn::Method::facts)).
pub(crate) const ISSGP_FACTS: MethodFacts = MethodFacts {
    name: "issgp",
    size: |stats| format!("{} random features; ", stats.nodes),
    counts_nodes: false,
    kb_per_trial: 0.0,
    bounded: true,
    watches_changes: true,
    slow_entries: "issgp_features, feedback_steps",
    shared_defaults: &[],
};
