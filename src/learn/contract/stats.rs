//! Figures a learner reports for the run's data files.

/// One tree level's figures.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct LevelStats {
    /// Nodes at this depth.
    pub nodes: usize,
    /// Bins attached to nodes at this depth.
    pub bins: usize,
    /// Learning patterns stored in those bins.
    pub patterns: usize,
    /// Running mean pattern error at this depth (degrees), `None` before any pattern.
    pub error: Option<f64>,
}

/// A learner's figures at one moment of a run.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct LearnerStats {
    /// Approximators (tree nodes, networks, neurons) in use.
    pub nodes: usize,
    /// Bins holding stored patterns.
    pub bins: usize,
    /// Learning patterns stored.
    pub patterns: usize,
    /// Per-depth figures of a tree learner, root first; empty for other learners.
    pub levels: Vec<LevelStats>,
}
