//! Settings of the `lwpr` learner, with the usual names and defaults of LWPR.

use crate::learn::MethodFacts;
use crate::learn::PatternSettings;

/// Settings of the `lwpr` learner. Inputs are normalised to [0, 1] by the input boundaries
/// before any of these apply, so distances and metrics are in those units.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LwprSettings {
    /// A new field's distance metric is `init_D` times the identity (per squared normalised
    /// input unit); 25 by default (a kernel of standard deviation 0.2 of each input range).
    pub init_d: f64,
    /// A new field's learning rate of every distance-metric element; 50 by default.
    pub init_alpha: f64,
    /// A new field is made at a pattern that activates no field above this; 0.1 by default.
    pub w_gen: f64,
    /// Of two fields both activated above this by one pattern, the narrower (larger trace of
    /// D) is dropped; 1.0 by default (never, as the reference library ships it).
    pub w_prune: f64,
    /// A new field's (and a new projection's) forgetting factor; 0.999 by default.
    pub init_lambda: f64,
    /// The forgetting factor approaches `final_lambda` by this factor per update of the
    /// field: λ ← τλ + (1 − τ)·final; 0.9999 by default.
    pub tau_lambda: f64,
    /// The forgetting factor a field anneals to; 0.99999 by default.
    pub final_lambda: f64,
    /// True: distance metrics are diagonal (one width per input); true by default.
    pub diag_only: bool,
    /// True: the metric's learning rates adapt themselves (second-order meta learning);
    /// false by default.
    pub meta: bool,
    /// Learning rate of the learning rates' logarithms, with `meta`; 250 by default.
    pub meta_rate: f64,
    /// Weight of the smoothness penalty Σ D²ᵢⱼ (divided by the 5 inputs) in each field's
    /// cost; 1e-6 by default.
    pub penalty: f64,
    /// Another PLS projection is added once the last one cut the leave-one-out error to
    /// below this fraction of the one before; 0.5 by default.
    pub add_threshold: f64,
    /// Outputs Δθ are learned divided by this (degrees); 10 by default.
    pub norm_out: f64,
    /// Which pose pairs are patterns (`minimal_joint_move`).
    pub patterns: PatternSettings,
}

impl Default for LwprSettings {
    fn default() -> Self {
        LwprSettings {
            init_d: 25.0,
            init_alpha: 50.0,
            w_gen: 0.1,
            w_prune: 1.0,
            init_lambda: 0.999,
            tau_lambda: 0.9999,
            final_lambda: 0.99999,
            diag_only: true,
            meta: false,
            meta_rate: 250.0,
            penalty: 1e-6,
            add_threshold: 0.5,
            norm_out: 10.0,
            patterns: PatternSettings::default(),
        }
    }
}

/// What the program knows of `lwpr` besides its learner (see [`Method::facts`](crate::learn::Method::facts)).
pub(crate) const LWPR_FACTS: MethodFacts = MethodFacts {
    name: "lwpr",
    size: |stats| format!("{} receptive fields; ", stats.nodes),
    counts_nodes: true,
    kb_per_trial: 0.0,
    bounded: true,
    watches_changes: true,
    slow_entries: "init_D, w_gen, feedback_steps",
    shared_defaults: &[],
};
