//! The smaller parts of the tree's state, each with what it is for: the journal of what
//! training did, the recovery state after a detected change, and re-training's bookkeeping.

use super::{Sample, StaleVerdict};
use crate::learn::ModelEvent;

/// What training has done so far: how many patterns were numbered, the last one's error,
/// and the merges not yet taken by the learner.
#[derive(Debug, Default)]
pub(crate) struct Journal {
    /// The number the next pattern trained gets (from 0, never reset).
    pub(crate) next_seq: u64,
    /// The error of the deepest node that answered the last pattern trained, before it was
    /// trained (`None` if no node had an answer).
    pub(crate) last_error: Option<f64>,
    /// Merges since they were last taken.
    pub(crate) events: Vec<ModelEvent>,
}

/// The tree's state after a detected change (empty before the first and after a reset).
#[derive(Debug, Default)]
pub(crate) struct RecoveryState {
    /// Whether nodes that await new patterns answer from their stale fits.
    pub(crate) verdict: StaleVerdict,
    /// The last detected change: the first valid pattern's number, and the patterns a node
    /// needs from then on (`change_min_fresh`).
    pub(crate) change: Option<(u64, usize)>,
}

/// Re-training's bookkeeping (re-trained models only) and its reused buffers.
#[derive(Debug)]
pub(crate) struct Retraining<const N: usize> {
    /// Nodes that took in patterns since their last re-training; may hold a node twice or
    /// one that is gone.
    pub(crate) touched: Vec<u32>,
    /// The bins sampled for one node.
    pub(crate) picked: Vec<u32>,
    /// Their patterns, in the node's local coordinates.
    pub(crate) batch: Vec<Sample<N>>,
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
