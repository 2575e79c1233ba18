//! What a perceptron node is set up by.

/// How each node's perceptron keeps its normal-equation sums (study §4.2.1).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct PerceptronSettings {
    /// Staggered sum-sets each node keeps (`nr_of_matrices`); 5 by default.
    pub sum_sets: usize,
    /// Patterns a sum-set takes before it is emptied and refilled (`max_pats_in_mat`);
    /// 1,000 by default; at least `sum_sets` (a smaller value counts as `sum_sets`).
    pub set_size: usize,
}

impl Default for PerceptronSettings {
    fn default() -> Self {
        PerceptronSettings {
            sum_sets: 5,
            set_size: 1000,
        }
    }
}
