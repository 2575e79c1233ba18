//! Recovering from a detected change of the mapping (the study's §4.4.6): forgetting what
//! was learned before it, and cutting what cannot relearn.
//!
//! [`forget_before`](NestedTree::forget_before) a change at pattern number C:
//! - every stored pattern numbered below C is dropped from its bin;
//! - every node whose model learned from such a pattern forgets it
//!   ([`Approximator::forget_before`]): a perceptron with a sum-set older than C clears all
//!   its sets and is given back the stored patterns from C on (those of its box: its own
//!   bins and its descendants'), so it answers at once from what is valid now;
//! - every node but the root that learned from before C awaits `min_fresh` patterns from C
//!   on (those replayed count) before its model answers again. Meanwhile it answers from
//!   its stale fit (its model's fit from before C) while that has missed the new patterns
//!   by less than its nearest answering ancestor (see [`StaleVerdict`]); otherwise it
//!   leaves the answer to that ancestor and measures no errors, so nothing below it splits;
//! - every node's error monitors start over (they measured the old mapping);
//! - models that are re-trained (networks) are re-trained after the trial on the stored
//!   patterns, all of them from C on by then.
//!
//! [`cut_starved`](NestedTree::cut_starved), a grace period later and again every grace
//! period while nodes still await patterns: a subtree whose top node still awaits them,
//! gets them at less than a quarter of the pace it got patterns before the change although
//! that pace would have brought it `4 × min_fresh` by now, and does no better from its stale
//! fit than its ancestors, is starved: its box is no longer where the arm works. It is cut
//! (a [`MergeKind::Starved`] merge) and its box falls back to the parent, which splits it
//! off again if new patterns there call for it. A node that is merely slow to fill (its
//! box never got many patterns) waits on, deferring to its ancestors, which costs nothing.
//! Nodes split off after the change are never starved: they only ever learned from valid
//! patterns.
//!
//! Both walk the tree: they run once per detected change, not per pattern.

use super::{Approximator, BranchRule, NestedTree, NONE, ROOT};
use crate::learn::{LearnError, MergeKind};

/// A node is starved when it got fewer than 1/`STARVED` of the new patterns its pace before
/// the change would have brought it.
const STARVED: f64 = 4.0;
/// Comparisons the tree's verdict needs before stale fits can be preferred.
const TREE_COMPARED: usize = 20;
/// Comparisons a node's own verdict needs before it decides for the node.
const NODE_COMPARED: usize = 10;
/// Comparisons the running means reach back over.
const VERDICT_WINDOW: usize = 500;

/// After a detected change: whether nodes that await new patterns do better answering from
/// their stale fits than leaving it to their nearest ancestors that answer from their own
/// (new) models. Every pattern that meets such a node on its path compares the two
/// misses, for that node and for the tree as a whole; running mean misses decide. A node
/// goes by its own verdict once it has one, by the tree's until then. A small change (a
/// link a few centimetres longer) leaves most fine stale fits better than the coarse new
/// ones; a large one (a camera turned 30° or more) leaves none.
#[derive(Debug, Clone, Default)]
pub(crate) struct StaleVerdict {
    stale: f64,
    fallback: f64,
    compared: usize,
}

impl StaleVerdict {
    /// Books one pattern: the stale fit missed it by `stale`, the ancestor by `fallback`.
    pub(super) fn compare(&mut self, stale: f64, fallback: f64) {
        self.compared += 1;
        let rate = 1.0 / self.compared.min(VERDICT_WINDOW) as f64;
        self.stale += rate * (stale - self.stale);
        self.fallback += rate * (fallback - self.fallback);
    }

    /// The tree's verdict: whether stale fits answer where nodes have no verdict of their
    /// own.
    pub(super) fn stale_ok(&self) -> bool {
        self.compared >= TREE_COMPARED && self.stale < self.fallback
    }

    /// A node's verdict, once it has enough comparisons.
    pub(super) fn decided(&self) -> Option<bool> {
        (self.compared >= NODE_COMPARED).then_some(self.stale < self.fallback)
    }
}

impl<A: Approximator<N>, R: BranchRule<N>, const N: usize> NestedTree<A, R, N> {
    /// Forgets every pattern numbered below `cutoff` (see the module doc); nodes that
    /// learned from one await `min_fresh` newer patterns before they answer again.
    pub(crate) fn forget_before(
        &mut self,
        cutoff: u64,
        min_fresh: usize,
    ) -> Result<(), LearnError> {
        self.recovery.start(cutoff, min_fresh);
        let order = self.reachable();
        // Per node (by arena index): whether it is replayed, and the valid patterns in its box.
        let mut replayed = vec![false; self.nodes.len()];
        let mut fresh = vec![0usize; self.nodes.len()];
        for &id in &order {
            self.store.drop_before(&mut self.nodes, id, cutoff);
            let node = &mut self.nodes[id as usize];
            node.pace = node.taken as f64 / cutoff.saturating_sub(node.born).max(1) as f64;
            replayed[id as usize] = node.model.forget_before(cutoff);
            node.errors.clear();
            node.clear_all_box_errors();
            node.verdict = StaleVerdict::default();
        }
        let known_share = self.settings().known_pattern_perc / 100.0;
        let retrain_delay = self.settings().retrain_delay.max(1);
        for &id in &order {
            let (nodes, rng) = (&mut self.nodes, &mut self.rng);
            for i in 0..nodes[id as usize].bins.len() {
                let bin = nodes[id as usize].bins[i];
                self.store.for_each_pattern(bin, |pattern, seq| {
                    let mut at = id;
                    while at != NONE {
                        fresh[at as usize] += 1;
                        let node = &mut nodes[at as usize];
                        if replayed[at as usize] {
                            node.take_in(&pattern.input, &pattern.target, seq, known_share, rng);
                        }
                        at = node.parent;
                    }
                })?;
            }
        }
        for &id in &order {
            let stale = replayed[id as usize] || A::RETRAINED;
            let node = &mut self.nodes[id as usize];
            if replayed[id as usize] {
                node.model.refit();
                // (Its pace counts each pattern once.)
                node.taken -= fresh[id as usize] as u64;
            }
            if stale && id != ROOT {
                node.awaiting = min_fresh.saturating_sub(fresh[id as usize]);
            }
            if A::RETRAINED {
                // Re-trained after this trial, on the valid patterns only.
                if node.fresh == 0 {
                    self.retraining.touch(id);
                }
                node.fresh = node.fresh.max(retrain_delay);
            }
        }
        Ok(())
    }

    /// Cuts every starved subtree (see the module doc), booking each as a starved merge.
    /// True when no node awaits patterns from after the last change any more.
    pub(crate) fn cut_starved(&mut self) -> bool {
        let Some((cutoff, min_fresh)) = self.recovery.change() else {
            return true;
        };
        let since = self.journal.next_seq().saturating_sub(cutoff) as f64;
        let root = &self.nodes[ROOT as usize];
        let mut stack: Vec<u32> = root
            .children
            .iter()
            .copied()
            .filter(|&c| c != NONE)
            .collect();
        let mut waiting = false;
        while let Some(id) = stack.pop() {
            let node = &self.nodes[id as usize];
            let starved = node.awaiting > 0
                && node.pace * since >= STARVED * min_fresh as f64
                && !node.stale_ok(self.recovery.verdict());
            if starved {
                self.cut_as(id, MergeKind::Starved);
                continue;
            }
            waiting |= node.awaiting > 0;
            stack.extend(node.children.iter().copied().filter(|&c| c != NONE));
        }
        if !waiting {
            self.recovery.end();
        }
        !waiting
    }

    /// Whether the root has an answer of its own (it may have none right after a change,
    /// with too few valid patterns for a fit).
    pub(crate) fn root_answers(&self) -> bool {
        let root = &self.nodes[ROOT as usize];
        root.answer(&((root.region.low() + root.region.high()) / 2.0))
            .is_some()
    }

    /// Every node, parents before their children.
    pub(super) fn reachable(&self) -> Vec<u32> {
        let mut order = vec![ROOT];
        let mut i = 0;
        while i < order.len() {
            let node = &self.nodes[order[i] as usize];
            order.extend(node.children.iter().copied().filter(|&c| c != NONE));
            i += 1;
        }
        order
    }
}
