//! Merging: cutting off a subtree that does worse than it should.
//!
//! A node's running error E is the mean miss (degrees, study §2.2.4) of the tree's answer
//! over the last `am_error_iters` of the patterns it monitors: one per step of a trial, the
//! step's move to where the trial ended. A node monitors once it has taken in a full window
//! of patterns (see docs/STUDY.md for the reading and the passages behind it). Going down a
//! pattern's path, the first node that is due is merged:
//! - **absolute merge** (the root): its running error is above `am_error_tresh`. Every
//!   pattern reaches the root, so after a major change of the mapping its error is the
//!   first to cross, and the tree starts afresh; a deeper node's running error, over a
//!   smaller and often harder box, crosses it while nothing changed (§4.4.2, §4.4.3);
//! - **relative merge** (not the root): its running error is above its parent's mean
//!   error on the node's box by more than `merge_error`. (The study's eq. 2.2 has its two
//!   sides swapped; this is the rule its text describes.)
//!
//! A merge cuts the node and its whole subtree; their bins, with their patterns, go back to
//! the parent. Merging the root throws everything away: the tree starts afresh. Every merge
//! is booked as a [`ModelEvent::Merge`]: its kind, the depth of the cut node and the nodes
//! cut (a root merge: every node there was).

use super::{Approximator, BranchRule, NestedTree, Path, TreeEvent, NONE, ROOT};
use crate::learn::{LearnError, MergeKind, ModelEvent};

impl<A: Approximator<N>, R: BranchRule<N>, const N: usize> NestedTree<A, R, N> {
    /// Merges the shallowest node on `path` that is due, if any.
    pub(super) fn merge_if_due(&mut self, path: &Path) -> Result<Option<TreeEvent>, LearnError> {
        let s = self.settings();
        let due = path.nodes().iter().find_map(|&id| {
            let node = &self.nodes[id as usize];
            let own = node.errors.mean().filter(|_| node.errors.is_full())?;
            let parents = (id != ROOT)
                .then(|| self.nodes[node.parent as usize].box_errors(node.branch))
                .flatten()
                .filter(|errors| errors.is_full())
                .and_then(|errors| errors.mean());
            if id == ROOT && own > s.am_error_tresh {
                Some((id, MergeKind::Absolute))
            } else if parents.is_some_and(|parents| own > parents + s.merge_error) {
                Some((id, MergeKind::Relative))
            } else {
                None
            }
        });
        match due {
            None => Ok(None),
            Some((ROOT, kind)) => {
                let nodes = self.store.total_nodes();
                self.journal.book(ModelEvent::Merge {
                    kind,
                    depth: 0,
                    nodes,
                });
                self.reset()?;
                Ok(Some(TreeEvent::Reset))
            }
            Some((id, kind)) => {
                self.cut_as(id, kind);
                Ok(Some(TreeEvent::Merged))
            }
        }
    }

    /// Cuts node `id` (not the root) and its subtree, and books it as a merge of `kind`.
    pub(super) fn cut_as(&mut self, id: u32, kind: MergeKind) {
        let depth = self.nodes[id as usize].depth;
        let nodes = self.cut(id);
        self.journal.book(ModelEvent::Merge { kind, depth, nodes });
    }

    /// Cuts node `id` (not the root) and its subtree; every bin they held goes back to the
    /// parent, patterns and all. Returns the nodes cut.
    pub(super) fn cut(&mut self, id: u32) -> usize {
        let (parent, branch) = (
            self.nodes[id as usize].parent,
            self.nodes[id as usize].branch,
        );
        let cut = self.subtree(id);
        for &x in &cut {
            self.store.lift(&mut self.nodes, x, parent, branch);
            self.release(x);
        }
        let p = &mut self.nodes[parent as usize];
        p.children[usize::from(branch)] = NONE;
        // Evidence for splitting this sub-box again must be fresh.
        p.clear_box_errors(branch);
        cut.len()
    }
}
