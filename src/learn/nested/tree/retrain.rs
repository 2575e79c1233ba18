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

use super::{Approximator, BranchRule, NestedTree, Sample};
use crate::learn::LearnError;
use rand::Rng;

/// Re-training's bookkeeping (re-trained models only) and its reused buffers.
#[derive(Debug)]
pub(crate) struct Retraining<const N: usize> {
    /// Nodes that took in patterns since their last re-training; may hold a node twice or
    /// one that is gone.
    touched: Vec<u32>,
    /// The bins sampled for one node.
    picked: Vec<u32>,
    /// Their patterns, in the node's local coordinates.
    batch: Vec<Sample<N>>,
}

impl<const N: usize> Default for Retraining<N> {
    fn default() -> Self {
        Retraining {
            touched: Vec::new(),
            picked: Vec::new(),
            batch: Vec::new(),
        }
    }
}

impl<const N: usize> Retraining<N> {
    /// Node `id` took in its first pattern since its last re-training.
    pub(crate) fn touch(&mut self, id: u32) {
        self.touched.push(id);
    }

    /// Forgets every node listed (the tree starts afresh).
    pub(crate) fn clear(&mut self) {
        self.touched.clear();
    }

    /// Whether no node is listed as due for re-training.
    #[cfg(test)]
    pub(crate) fn is_idle(&self) -> bool {
        self.touched.is_empty()
    }
}

impl<A: Approximator<N>, R: BranchRule<N>, const N: usize> NestedTree<A, R, N> {
    /// Re-trains every node that is due; returns how many were.
    pub(crate) fn retrain_due(&mut self) -> Result<usize, LearnError> {
        if !A::RETRAINED {
            return Ok(0);
        }
        let delay = self.settings().retrain_delay.max(1);
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
        picked.clear();
        for x in self.subtree(id) {
            let bins = self.store.bins();
            // (A bin emptied by a detected change has nothing to give.)
            picked.extend(
                self.nodes[x as usize]
                    .bins
                    .iter()
                    .copied()
                    .filter(|&b| bins.len(b) > 0),
            );
        }
        let limit = self.settings().retrain_limit;
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
            let p = self.store.latest(bin)?;
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
