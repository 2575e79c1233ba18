//! What a learner did to its model that a run logs: merges (the `merges` file) and detected
//! changes of the mapping (the `changes` file).

use std::fmt;

/// Why a subtree was cut.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum MergeKind {
    /// A node's running error passed `am_error_tresh` (study §2.4.3).
    Absolute,
    /// A child's running error passed its parent's on the child's box by `merge_error`.
    Relative,
    /// After a detected change, a subtree got too few new patterns to relearn.
    Starved,
}

impl fmt::Display for MergeKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            MergeKind::Absolute => "absolute",
            MergeKind::Relative => "relative",
            MergeKind::Starved => "starved",
        })
    }
}

/// A change a learner made to its model, or saw in the mapping.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum ModelEvent {
    /// A subtree was cut.
    Merge {
        /// Why.
        kind: MergeKind,
        /// Depth of the cut node (0: the root, i.e. everything).
        depth: usize,
        /// Nodes cut, the node itself included.
        nodes: usize,
    },
    /// The change detector fired.
    Change {
        /// The trial at which the mapping is estimated to have changed.
        estimated_trial: usize,
    },
}

impl ModelEvent {
    /// Whether the event cut the whole tree (a merge at the root): the learner starts over.
    pub fn is_root_merge(&self) -> bool {
        matches!(self, ModelEvent::Merge { depth: 0, .. })
    }
}
