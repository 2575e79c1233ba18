//! The settings of the nested tree and of what the nested learners share around it.

use crate::learn::change::ChangeSettings;
use crate::learn::{MergeStrategy, PatternSettings};

/// How the nested tree grows, shrinks, stores and measures. The defaults are the config
/// entries' declared defaults (a test holds them equal).
#[derive(Debug, Clone, PartialEq)]
pub struct TreeSettings {
    /// The deepest a node can be (the root is at 0); bins are this fine (`tree_depth`);
    /// 8 by default.
    pub max_depth: usize,
    /// Patterns a bin keeps (`bin_size`); 5 by default.
    pub bin_size: usize,
    /// At most this many patterns are stored in all bins together
    /// (`max_stored_patterns`); past it the bins stored to least recently are dropped
    /// whole. 0 is no cap; 2,000,000 by default (about 200 MB in memory, reached after
    /// about 200,000 lin5 trials). At least `bin_size` when set.
    pub max_stored_patterns: usize,
    /// Stored patterns a sub-box needs to be split off (`min_pats_for_split`); 50 by
    /// default.
    pub min_pats_for_split: usize,
    /// A sub-box is split off when its mean squared error E² is above this (`split_error`,
    /// degrees²); 1e-4 by default.
    pub split_error: f64,
    /// A node is merged when its mean error E is above this (`am_error_tresh`, degrees);
    /// 20 by default.
    pub am_error_tresh: f64,
    /// Patterns the node and sub-box errors are averaged over (`am_error_iters`); 300 by
    /// default.
    pub am_error_iters: usize,
    /// A child is merged when its mean error E is above its parent's on the child's box by
    /// more than this (`merge_error`, degrees); 99.05 by default (never, in practice).
    pub merge_error: f64,
    /// Patterns each depth's reported error is averaged over (`monitor_ave`); 100 by
    /// default.
    pub monitor_ave: usize,
    /// Known patterns per 100 regular patterns trained to a node (`known_pattern_perc`);
    /// 50 by default.
    pub known_pattern_perc: f64,
    /// At most this many stored patterns re-train a node (`nnw_train_limit`; re-trained
    /// models only); 300 by default.
    pub retrain_limit: usize,
    /// A node is re-trained once it took in this many new patterns (`nnw_train_delay`; at
    /// least one; re-trained models only); 15 by default.
    pub retrain_delay: usize,
}

impl Default for TreeSettings {
    fn default() -> Self {
        TreeSettings {
            max_depth: 8,
            bin_size: 5,
            max_stored_patterns: 2_000_000,
            min_pats_for_split: 50,
            split_error: 1e-4,
            am_error_tresh: 20.0,
            am_error_iters: 300,
            merge_error: 99.05,
            monitor_ave: 100,
            known_pattern_perc: 50.0,
            retrain_limit: 300,
            retrain_delay: 15,
        }
    }
}

impl TreeSettings {
    /// Sub-box errors a split test needs: as many as the stored patterns it needs, but
    /// never more than a window holds.
    pub(crate) fn split_evidence(&self) -> usize {
        self.min_pats_for_split.min(self.am_error_iters).max(1)
    }
}

/// What every nested learner (lin5, lin8, nnw) is set up by besides its node model and
/// input box.
#[derive(Debug, Clone, PartialEq)]
pub struct NestedSettings {
    /// The tree.
    pub tree: TreeSettings,
    /// How changes of the mapping are handled (`merge_strategy`); `thesis` by default.
    pub merge_strategy: MergeStrategy,
    /// Change detection and recovery, used under `change_detection` only.
    pub change: ChangeSettings,
    /// Which pose pairs are patterns (`minimal_joint_move`).
    pub patterns: PatternSettings,
    /// The seed of the learner's own draws (`seed`); 1 by default.
    pub seed: u64,
}

impl Default for NestedSettings {
    fn default() -> Self {
        NestedSettings {
            tree: TreeSettings::default(),
            merge_strategy: MergeStrategy::default(),
            change: ChangeSettings::default(),
            patterns: PatternSettings::default(),
            seed: 1,
        }
    }
}
