//! Training one pattern down its path: each node's error measured before it learns (and,
//! after a detected change, its stale fit weighed against its ancestors), the pattern taken
//! in by every node on the path and kept in its bin, then a merge or split where due.

use super::{Approximator, BinKey, BranchRule, NestedTree, Path, TreeEvent};
use crate::learn::LearnError;
use crate::learn::Pattern;
use nalgebra::Vector3;

impl<A: Approximator<N>, R: BranchRule<N>, const N: usize> NestedTree<A, R, N> {
    /// [`train_monitored`](Self::train_monitored) with every pattern monitored.
    #[cfg(test)]
    pub(crate) fn train(&mut self, pattern: &Pattern<N>) -> Result<TreeEvent, LearnError> {
        self.train_monitored(pattern, true)
    }

    /// Trains `pattern` to every node on its path, stores it in its bin, then merges or
    /// splits where that is due. The pattern gets the next sequence number. When it is
    /// `monitored` (a step's move to where its trial ended), the error of the tree's answer
    /// to it joins the running error of the nodes on its path.
    pub(crate) fn train_monitored(
        &mut self,
        pattern: &Pattern<N>,
        monitored: bool,
    ) -> Result<TreeEvent, LearnError> {
        let finite = |v: &f64| v.is_finite();
        if !(pattern.input.iter().all(finite) && pattern.target.iter().all(finite)) {
            self.journal.clear_last_error();
            return Ok(TreeEvent::Ignored);
        }
        let seq = self.journal.number();
        let key = self.key(&pattern.input);
        let path = self.descend(key);
        let miss =
            monitored.then(|| (self.answer_on(&path, &pattern.input) - pattern.target).norm());
        self.journal.clear_last_error();
        // The error of the deepest node so far that answered from its own model.
        let mut fallback = None;
        for &id in path.nodes() {
            let (answered, own) = self.train_node(id, key, pattern, seq, fallback);
            self.journal.answered(answered);
            fallback = own.or(fallback);
        }
        if let Some(miss) = miss {
            self.monitor(&path, miss);
        }
        self.store
            .keep(&mut self.nodes, path.deepest(), key, pattern, seq)?;
        self.evict_over_cap();
        if let Some(event) = self.merge_if_due(&path)? {
            return Ok(event);
        }
        Ok(if self.split_if_due(path.deepest(), key)? {
            TreeEvent::Split
        } else {
            TreeEvent::Trained
        })
    }

    /// Measures node `id`'s error on pattern number `seq` (if it answers), then trains it.
    /// `fallback` is the error of the nearest ancestor that answered from its own model;
    /// a node awaiting new patterns weighs its stale fit against it. Returns the error of
    /// the node's answer and, if that came from its own model, that error again.
    fn train_node(
        &mut self,
        id: u32,
        key: BinKey,
        pattern: &Pattern<N>,
        seq: u64,
        fallback: Option<f64>,
    ) -> (Option<f64>, Option<f64>) {
        let window = self.settings().am_error_iters;
        let known_share = self.settings().known_pattern_perc / 100.0;
        let node = &mut self.nodes[id as usize];
        let miss = |output: Vector3<f64>| (output - pattern.target).norm();
        let own = node.answer(&pattern.input).map(miss);
        let stale = node.stale_answer(&pattern.input).map(miss);
        if let (Some(stale), Some(fallback)) = (stale, fallback) {
            self.recovery.compare(stale, fallback);
            node.verdict.compare(stale, fallback);
        }
        let error = own.or(stale.filter(|_| node.stale_ok(self.recovery.verdict())));
        if let Some(error) = error {
            self.store.record_error(node.depth, error);
            if let Some(branch) = key.branch(node.depth + 1) {
                node.box_errors_mut(branch, window).push(error);
            }
        }
        node.take_in(
            &pattern.input,
            &pattern.target,
            seq,
            known_share,
            &mut self.rng,
        );
        node.model.refit();
        self.mark_touched(id);
        (error, own)
    }

    /// Adds `miss`, the error of the tree's answer to a pattern, to the running error of
    /// every node on the pattern's `path` that had taken in a full window of patterns
    /// before it: a node is watched from then on (see [`merge`](super::merge)).
    fn monitor(&mut self, path: &Path, miss: f64) {
        let window = self.settings().am_error_iters as u64;
        for &id in path.nodes() {
            let node = &mut self.nodes[id as usize];
            if node.taken > window {
                node.errors.push(miss);
            }
        }
    }

    /// Books node `id` as having taken in one more pattern since its last re-training
    /// (re-trained models only).
    pub(super) fn mark_touched(&mut self, id: u32) {
        if A::RETRAINED {
            let node = &mut self.nodes[id as usize];
            if node.fresh == 0 {
                self.retraining.touch(id);
            }
            node.fresh += 1;
        }
    }
}
