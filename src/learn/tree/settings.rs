//! The tree's settings, taken from the config entries of the same names.

use crate::experiment::Config;

/// How the nested tree grows, shrinks, stores and measures.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct TreeSettings {
    /// `tree_depth`: the deepest a node can be (the root is at 0); bins are this fine.
    pub(crate) max_depth: usize,
    /// `bin_size`: patterns a bin keeps.
    pub(crate) bin_size: usize,
    /// `min_pats_for_split`: stored patterns a sub-box needs to be split off.
    pub(crate) min_pats_for_split: usize,
    /// `split_error`: a sub-box is split off when its mean squared error E² (degrees²) is
    /// above this.
    pub(crate) split_error: f64,
    /// `am_error_tresh`: a node is merged when its mean error E (degrees) is above this.
    pub(crate) am_error_tresh: f64,
    /// `am_error_iters`: patterns the node and sub-box errors are averaged over.
    pub(crate) am_error_iters: usize,
    /// `merge_error`: a child is merged when its mean error E is above its parent's on the
    /// child's box by more than this (degrees).
    pub(crate) merge_error: f64,
    /// `monitor_ave`: patterns each depth's error is averaged over.
    pub(crate) monitor_ave: usize,
    /// `known_pattern_perc`: known patterns per 100 regular patterns trained to a node.
    pub(crate) known_pattern_perc: f64,
    /// `nnw_train_limit`: at most this many stored patterns re-train a node (re-trained
    /// models only).
    pub(crate) retrain_limit: usize,
    /// `nnw_train_delay`: a node is re-trained once it took in this many new patterns
    /// (at least one; re-trained models only).
    pub(crate) retrain_delay: usize,
}

impl TreeSettings {
    /// The settings a run's config gives.
    pub(crate) fn from_config(config: &Config) -> Self {
        TreeSettings {
            max_depth: config.tree_depth,
            bin_size: config.bin_size,
            min_pats_for_split: config.min_pats_for_split,
            split_error: config.split_error,
            am_error_tresh: config.am_error_tresh,
            am_error_iters: config.am_error_iters,
            merge_error: config.merge_error,
            monitor_ave: config.monitor_ave,
            known_pattern_perc: config.known_pattern_perc,
            retrain_limit: config.nnw_train_limit,
            retrain_delay: config.nnw_train_delay,
        }
    }

    /// Sub-box errors a split test needs: as many as the stored patterns it needs, but
    /// never more than a window holds.
    pub(crate) fn split_evidence(&self) -> usize {
        self.min_pats_for_split.min(self.am_error_iters).max(1)
    }
}
