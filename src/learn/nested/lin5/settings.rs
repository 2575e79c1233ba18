//! What a `lin5` learner is set up by.

use crate::learn::nested::perceptron::PerceptronSettings;
use crate::learn::nested::tree::tree_size;
use crate::learn::nested::tree::NestedSettings;
use crate::learn::MethodFacts;

/// The input box of the 5-input learners in the shipped configs: (θ2, θ3) in degrees,
/// (cx, cy) in pixels, cz in the area measure (`boundary_0` … `boundary_4`).
pub(crate) const FIVE_INPUT_BOUNDS: [(f64, f64); 5] = [
    (-10.0, 80.0),
    (40.0, 145.0),
    (-512.0, 256.0),
    (-512.0, 256.0),
    (-150.0, 300.0),
];

/// Settings of `lin5`, the Nested Perceptron with input adjustment. The defaults are the
/// config entries' declared defaults (a test holds them equal).
#[derive(Debug, Clone, PartialEq)]
pub struct Lin5Settings {
    /// The root box of the inputs (θ2, θ3, cx*, cy*, cz*) as (low, high) per input
    /// (`boundary_0` … `boundary_4`; degrees, pixels, the area measure); by default
    /// (−10, 80), (40, 145), (−512, 256), (−512, 256), (−150, 300).
    pub bounds: [(f64, f64); 5],
    /// The tree, merges, change detection, `minimal_joint_move` and the seed.
    pub nested: NestedSettings,
    /// Each node's perceptron.
    pub perceptron: PerceptronSettings,
}

impl Default for Lin5Settings {
    fn default() -> Self {
        Lin5Settings {
            bounds: FIVE_INPUT_BOUNDS,
            nested: NestedSettings::default(),
            perceptron: PerceptronSettings::default(),
        }
    }
}

/// What the program knows of `lin5` besides its learner (see [`Method::facts`](crate::learn::Method::facts)).
pub(crate) const LIN5_FACTS: MethodFacts = MethodFacts {
    name: "lin5",
    size: tree_size,
    counts_nodes: true,
    kb_per_trial: 2.1,
    bounded: true,
    watches_changes: true,
    slow_entries: "feedback_steps, bin_size, max_stored_patterns",
    shared_defaults: &[],
};
