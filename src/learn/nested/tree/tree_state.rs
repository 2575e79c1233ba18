//! The smaller parts of the tree's state, each with what it is for: the journal of what
//! training did, and the recovery state after a detected change.

use super::StaleVerdict;
use crate::learn::ModelEvent;

/// What training has done so far: how many patterns were numbered, the last one's error,
/// and the merges not yet taken by the learner.
#[derive(Debug, Default)]
pub(crate) struct Journal {
    /// The number the next pattern trained gets (from 0, never reset).
    next_seq: u64,
    /// The error of the deepest node that answered the last pattern trained, before it was
    /// trained (`None` if no node had an answer).
    last_error: Option<f64>,
    /// Merges and detected changes since they were last taken.
    events: Vec<ModelEvent>,
}

impl Journal {
    /// The number the next pattern trained gets.
    pub(crate) fn next_seq(&self) -> u64 {
        self.next_seq
    }

    /// Numbers a pattern: the next number, from 0 on.
    pub(crate) fn number(&mut self) -> u64 {
        let seq = self.next_seq;
        self.next_seq += 1;
        seq
    }

    /// The error of the deepest node that answered the last pattern trained.
    pub(crate) fn last_error(&self) -> Option<f64> {
        self.last_error
    }

    /// A new pattern is on its way down: no node has answered it yet.
    pub(crate) fn clear_last_error(&mut self) {
        self.last_error = None;
    }

    /// A node deeper than the last one to answer measured `error`, if it answered.
    pub(crate) fn answered(&mut self, error: Option<f64>) {
        self.last_error = error.or(self.last_error);
    }

    /// Books `event` for the learner to take.
    pub(crate) fn book(&mut self, event: ModelEvent) {
        self.events.push(event);
    }

    /// Moves the events booked since the last call into `sink`.
    pub(crate) fn drain_into(&mut self, sink: &mut Vec<ModelEvent>) {
        sink.append(&mut self.events);
    }
}

/// The tree's state after a detected change (empty before the first and after a reset).
#[derive(Debug, Default)]
pub(crate) struct RecoveryState {
    /// Whether nodes that await new patterns answer from their stale fits.
    verdict: StaleVerdict,
    /// The last detected change: the first valid pattern's number, and the patterns a node
    /// needs from then on (`change_min_fresh`).
    change: Option<(u64, usize)>,
}

impl RecoveryState {
    /// A change was detected at pattern number `cutoff`; nodes need `min_fresh` patterns
    /// from then on. The verdict starts anew.
    pub(crate) fn start(&mut self, cutoff: u64, min_fresh: usize) {
        self.verdict = StaleVerdict::default();
        self.change = Some((cutoff, min_fresh));
    }

    /// No node awaits patterns from after the last change any more.
    pub(crate) fn end(&mut self) {
        *self = RecoveryState::default();
    }

    /// The last detected change that nodes still recover from: its first valid pattern's
    /// number and the patterns a node needs from then on.
    pub(crate) fn change(&self) -> Option<(u64, usize)> {
        self.change
    }

    /// Whether nodes that await new patterns answer from their stale fits.
    pub(crate) fn verdict(&self) -> &StaleVerdict {
        &self.verdict
    }

    /// Books one pattern for the tree's verdict: a stale fit missed it by `stale`, the
    /// nearest answering ancestor by `fallback`.
    pub(crate) fn compare(&mut self, stale: f64, fallback: f64) {
        self.verdict.compare(stale, fallback);
    }
}
