//! Re-training: models that learn little from each pattern (networks) are trained again on
//! a sample of their box's stored patterns (study §3.2.2, §5.1).
//!
//! After a trial, every node that took in at least `nnw_train_delay` patterns since its
//! last re-training is re-trained; so is a new child as soon as it is split off. Its sample
//! is the newest pattern of each bin in its box — its own bins and those of its
//! descendants, since a bin hangs on the deepest node covering it — and when there are
//! more than `nnw_train_limit` such bins, that many of them drawn at random (from the
//! tree's seeded generator). After a detected change every node is re-trained this way on
//! the patterns from after it. Models that are not re-trained never get here.

use super::{Approximator, BranchRule, NestedTree, NONE};
use crate::learn::LearnError;
use rand::Rng;

impl<A: Approximator<N>, R: BranchRule<N>, const N: usize> NestedTree<A, R, N> {
    /// Re-trains every node that is due; returns how many were.
    pub(crate) fn retrain_due(&mut self) -> Result<usize, LearnError> {
        if !A::RETRAINED {
            return Ok(0);
        }
        let delay = self.settings.retrain_delay.max(1);
        let mut touched = std::mem::take(&mut self.retraining.touched);
        let mut retrained = 0;
        let mut result = Ok(());
        touched.retain(|&id| {
            let fresh = self.nodes[id as usize].fresh;
            if fresh >= delay && result.is_ok() {
                result = self.retrain(id);
                retrained += 1;
                return false;
            }
            // (A node gone or listed twice has nothing new and drops out.)
            fresh > 0
        });
        self.retraining.touched = touched;
        result.map(|()| retrained)
    }

    /// Re-trains node `id` on the newest pattern of (at most `retrain_limit`) bins of its
    /// subtree.
    pub(super) fn retrain(&mut self, id: u32) -> Result<(), LearnError> {
        let mut picked = std::mem::take(&mut self.retraining.picked);
        let mut stack = std::mem::take(&mut self.scratch);
        picked.clear();
        stack.push(id);
        while let Some(x) = stack.pop() {
            let node = &self.nodes[x as usize];
            // (A bin emptied by a detected change has nothing to give.)
            picked.extend(node.bins.iter().copied().filter(|&b| self.bins.len(b) > 0));
            stack.extend(node.children.iter().copied().filter(|&c| c != NONE));
        }
        self.scratch = stack;
        let limit = self.settings.retrain_limit;
        if picked.len() > limit {
            // The first `limit` places of a Fisher–Yates shuffle: a uniform sample.
            for i in 0..limit {
                let j = self.rng.random_range(i..picked.len());
                picked.swap(i, j);
            }
            picked.truncate(limit);
        }
        let region = self.nodes[id as usize].region;
        self.retraining.batch.clear();
        for &bin in &picked {
            let p = self.bins.latest(bin)?;
            self.retraining
                .batch
                .push((region.local(&p.input), p.target));
        }
        self.retraining.picked = picked;
        let node = &mut self.nodes[id as usize];
        node.model.retrain(&self.retraining.batch);
        node.fresh = 0;
        Ok(())
    }
}
