//! Splitting: a badly approximated sub-box of a node gets a child of its own.
//!
//! A sub-box of the deepest node a pattern reached is split off when
//! - the child would be no deeper than `tree_depth` (the sub-box exists),
//! - the bins in it keep at least `min_pats_for_split` patterns, and
//! - the node's mean squared error E² on that sub-box, over its most recent patterns (at
//!   least as many as a split needs, or a full `am_error_iters` window), is above
//!   `split_error`.
//!
//! The bins the child covers sink onto it, and the child is trained at once with their
//! patterns (bin by bin, each bin oldest first) and the known patterns they earn; a model
//! that is re-trained (see [`retrain`](super::retrain)) is re-trained on them right after.

use super::{Approximator, BinKey, BranchRule, NestedTree, NONE};
use crate::learn::LearnError;

impl<A: Approximator<N>, R: BranchRule<N>, const N: usize> NestedTree<A, R, N> {
    /// Splits off the sub-box of node `id` that the point with `key` lies in, if due.
    /// True when it split.
    pub(super) fn split_if_due(&mut self, id: u32, key: BinKey) -> Result<bool, LearnError> {
        let node = &self.nodes[id as usize];
        let Some(branch) = key.branch(node.depth + 1) else {
            return Ok(false);
        };
        let s = self.settings();
        let due = node.box_patterns()[usize::from(branch)] >= s.min_pats_for_split
            && node.box_errors(branch).is_some_and(|errors| {
                errors.len() >= s.split_evidence()
                    && errors.mean_square().is_some_and(|e2| e2 > s.split_error)
            });
        if due {
            self.split(id, branch)?;
        }
        Ok(due)
    }

    /// Creates the child of `parent` at `branch`, sinks the bins it covers onto it and
    /// trains it with their patterns. Returns the child.
    pub(super) fn split(&mut self, parent: u32, branch: u8) -> Result<u32, LearnError> {
        debug_assert_eq!(
            self.nodes[parent as usize].children[usize::from(branch)],
            NONE
        );
        let child = self.add_child(parent, branch);
        self.store.sink(&mut self.nodes, parent, child);
        // From now on this measures the parent on its child's box (relative merge).
        self.nodes[parent as usize].clear_box_errors(branch);

        let known_share = self.settings().known_pattern_perc / 100.0;
        let node = &mut self.nodes[child as usize];
        for i in 0..node.bins.len() {
            let (bin, rng) = (node.bins[i], &mut self.rng);
            self.store.for_each_pattern(bin, |pattern, seq| {
                node.take_in(&pattern.input, &pattern.target, seq, known_share, rng);
            })?;
        }
        node.model.refit();
        // (Its pace counts the patterns that come after it was made.)
        node.taken = 0;
        if A::RETRAINED {
            self.retrain(child)?;
        }
        Ok(child)
    }
}
