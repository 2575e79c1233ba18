//! Recovering from a detected change by correcting the readings (`change_recovery
//! correct`): the tree is kept as it was and answers through the [`Corrections`]
//! (`learn/change/corrections.rs`) fitted since the change; what the correction misses it
//! learns as it would any new pattern, splitting sub-boxes off at `change_split_patterns`
//! stored patterns from then on (the changed robot works in poses the tree covers only
//! coarsely) and answering a query only from nodes whose fit supports it.
//!
//! [`Corrections`]: crate::learn::change::Corrections

use super::{Approximator, BranchRule, NestedTree};
use nalgebra::SVector;

impl<A: Approximator<N>, R: BranchRule<N>, const N: usize> NestedTree<A, R, N> {
    /// Once a correction is fixed the tree learns a changed robot, which works in poses the
    /// tree covers only coarsely: from then on a sub-box is split off once it holds
    /// `split_patterns` stored patterns (if that is sooner than before), and, since a node
    /// split off from so few patterns may fit them in a way that runs far off between and
    /// beyond them, a query is answered by the deepest node whose fit supports it.
    pub(crate) fn after_correction(&mut self, split_patterns: usize) {
        self.answer_where_supported(split_patterns);
    }

    /// The corners of the root's box.
    pub(crate) fn root_box(&self) -> (SVector<f64, N>, SVector<f64, N>) {
        let region = &self.nodes[super::ROOT as usize].region;
        (region.low(), region.high())
    }
}
