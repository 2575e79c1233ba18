//! Settings of the `broyden` controller.

use crate::learn::MethodFacts;

/// How the image Jacobian follows each move (the config's `broyden_update`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub enum BroydenUpdate {
    /// Broyden's rank-one secant update (`broyden`, the default).
    #[default]
    Broyden,
    /// Recursive least squares with exponential forgetting (`rls`).
    Rls,
}

/// Settings of the `broyden` controller.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BroydenSettings {
    /// The update after each move; Broyden's by default.
    pub update: BroydenUpdate,
    /// α, the gain of Broyden's update (1: each move's secant condition met exactly); 1 by
    /// default.
    pub rate: f64,
    /// λ, the forgetting factor of the recursive least-squares update; 0.9 by default.
    pub forgetting: f64,
    /// μ² of the damped least-squares step as a share of JᵀJ's mean diagonal; 0.001 by
    /// default.
    pub damping: f64,
    /// Largest joint turn of one step (degrees); 15 by default.
    pub max_step_deg: f64,
    /// Each exploratory move of the first trial turns one joint by this (degrees); 1 by
    /// default.
    pub probe_deg: f64,
}

impl Default for BroydenSettings {
    fn default() -> Self {
        BroydenSettings {
            update: BroydenUpdate::Broyden,
            rate: 1.0,
            forgetting: 0.9,
            damping: 0.001,
            max_step_deg: 15.0,
            probe_deg: 1.0,
        }
    }
}

/// What the program knows of `broyden` besides its learner (see [`Method::facts`](crate::learn::Method::facts)).
pub(crate) const BROYDEN_FACTS: MethodFacts = MethodFacts {
    name: "broyden",
    size: |_| "one 3×3 image Jacobian; ".to_string(),
    counts_nodes: false,
    kb_per_trial: 0.0,
    bounded: false,
    watches_changes: false,
    slow_entries: "feedback_steps, bin_size, max_stored_patterns",
    // Its Jacobian is estimated within each trial, not learned across them: 1,000 trials
    // measure it.
    shared_defaults: &[("trials", "1000")],
};
