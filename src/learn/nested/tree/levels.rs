//! Per-depth counters of nodes, bins and stored patterns, and each depth's error monitor.
//!
//! Every change to the tree reports itself here as it happens, so the figures a run writes
//! out never need a walk over the tree.

use super::Monitor;
use crate::learn::LevelStats;

#[derive(Debug, Clone)]
struct Level {
    nodes: usize,
    bins: usize,
    patterns: usize,
    errors: Monitor,
}

/// The counters of depths 0 (the root) to the tree's maximum depth.
#[derive(Debug, Clone)]
pub(crate) struct Levels(Vec<Level>);

impl Levels {
    /// Zeroed counters for depths `0..=max_depth`; errors averaged over `window` patterns.
    pub(crate) fn new(max_depth: usize, window: usize) -> Self {
        let level = Level {
            nodes: 0,
            bins: 0,
            patterns: 0,
            errors: Monitor::new(window),
        };
        Levels(vec![level; max_depth + 1])
    }

    /// A node was created at `depth`.
    pub(crate) fn node_added(&mut self, depth: usize) {
        self.0[depth].nodes += 1;
    }

    /// A node at `depth` was deleted.
    pub(crate) fn node_removed(&mut self, depth: usize) {
        self.0[depth].nodes -= 1;
    }

    /// A bin was created on a node at `depth`.
    pub(crate) fn bin_added(&mut self, depth: usize) {
        self.0[depth].bins += 1;
    }

    /// A bin on a node at `depth` got one more pattern.
    pub(crate) fn pattern_added(&mut self, depth: usize) {
        self.0[depth].patterns += 1;
    }

    /// A bin holding `patterns` patterns was dropped from a node at `depth`.
    pub(crate) fn bin_removed(&mut self, depth: usize, patterns: usize) {
        self.0[depth].bins -= 1;
        self.0[depth].patterns -= patterns;
    }

    /// `patterns` patterns were dropped from bins on nodes at `depth`.
    pub(crate) fn patterns_removed(&mut self, depth: usize, patterns: usize) {
        self.0[depth].patterns -= patterns;
    }

    /// Nodes at every depth.
    pub(crate) fn total_nodes(&self) -> usize {
        self.0.iter().map(|level| level.nodes).sum()
    }

    /// `bins` bins holding `patterns` patterns moved from a node at `from` to one at `to`.
    pub(crate) fn bins_moved(&mut self, from: usize, to: usize, bins: usize, patterns: usize) {
        self.0[from].bins -= bins;
        self.0[from].patterns -= patterns;
        self.0[to].bins += bins;
        self.0[to].patterns += patterns;
    }

    /// A node at `depth` made error `error` on a pattern.
    pub(crate) fn record_error(&mut self, depth: usize, error: f64) {
        self.0[depth].errors.push(error);
    }

    /// Zeroes every counter and monitor.
    pub(crate) fn clear(&mut self) {
        for level in &mut self.0 {
            level.nodes = 0;
            level.bins = 0;
            level.patterns = 0;
            level.errors.clear();
        }
    }

    /// Each depth's figures, root first; the error is the depth's running mean E.
    pub(crate) fn stats(&self) -> Vec<LevelStats> {
        self.0
            .iter()
            .map(|level| LevelStats {
                nodes: level.nodes,
                bins: level.bins,
                patterns: level.patterns,
                error: level.errors.mean(),
            })
            .collect()
    }
}
