//! The nested tree shared by the nested learners (study §2.4, §4.2, appendix A.3–A.4).
//!
//! The root's model covers the whole input box; a child covers one of its parent's
//! sub-boxes, so deeper nodes give finer approximations. The tree is generic over the
//! node model ([`Approximator`]: a perceptron for lin5/lin8, a network for nnw), the input
//! dimension `N` and the way boxes branch ([`BranchRule`]: [`Halving`] for lin5 and nnw,
//! [`Narrowing`] for lin8). [`NestedLearner`] is what the three learners share around it.
//!
//! How it works:
//! - **Paths.** A point's branch numbers at each depth (its [`BinKey`]) lead from the root
//!   to the deepest existing node that covers it. A point outside the root box counts as in
//!   the nearest box, so every point has a path.
//! - **Answers.** The deepest node on the path that has a usable model answers; a node whose
//!   fit is singular or ill-conditioned hands over to its nearest ancestor that can; with
//!   none, the answer is zero.
//! - **Training.** A pattern trains every node on its path, root first, each followed by the
//!   known patterns it earns; before that, each node's error on it is measured.
//! - **Errors.** A pattern's error is E = ‖o − t‖, the distance in degrees by which an
//!   answer o misses the target Δθ t. Each node measures its own answer's error on the
//!   patterns of each sub-box (a running mean over the last `am_error_iters`: the split
//!   test, and the parent's side of the relative merge), and each depth its nodes' own
//!   errors over its last `monitor_ave` patterns (reported). A node's running error, for
//!   the merges, is the tree's answer's error over its last `am_error_iters` monitored
//!   patterns (one per trial step: see [`merge`]).
//!   The merge thresholds compare the mean of E (degrees, as the study words
//!   `am_error_tresh`: an average miss of 5° means the node is lost). The split threshold
//!   compares the mean of E² — the study's "average sum-squared error": its shipped values
//!   1e-4 and 1e-5 are then RMS misses of 0.01° and 0.003°, about the arm's final precision
//!   (70 µm at ~1 m reach), whereas a mean miss of 1e-4° would split every sub-box as soon
//!   as it holds enough patterns.
//! - **Bins.** Each pattern is kept in the bin of its finest box (the last `bin_size` per
//!   bin); a bin hangs on the deepest existing node covering it. A split moves exactly the
//!   bins the new child covers onto it (bin sinking); a merge moves every bin of the cut
//!   subtree back to the parent. Patterns live in memory or in the run's `pat_file`. With
//!   `max_stored_patterns` set, the bins stored to least recently are dropped whole once
//!   the store holds more; see [`eviction`].
//! - **Known patterns.** With camera readings zero the move is zero: for n patterns a node
//!   is trained with, it also gets n·`known_pattern_perc`/100 patterns (θ2, θ3 uniform in
//!   its box, every other input 0) → Δθ = 0, never stored. A fractional credit per node
//!   carries the remainder. A node whose box does not contain the camera zero gets none
//!   (they would lie outside its box). The draws come from the learner's own seeded
//!   generator.
//! - **Split and merge**: see [`split`] and [`merge`] for the
//!   exact tests. A merge of the root throws everything away. Every merge is booked (kind,
//!   depth, nodes cut) for the learner to report.
//! - **Dates.** Patterns are numbered in the order they are trained; a stored pattern and
//!   every perceptron sum-set know their numbers, so what was learned before a detected
//!   change can be told from what came after. The learner ([`NestedLearner`]) dates trials.
//! - **Recovery** (merge strategy `change_detection`): after a detected change the tree
//!   forgets what came before it, lets nodes short of new patterns defer to their
//!   ancestors (or answer from their stale fits while those do better), and later cuts the
//!   subtrees starved of new patterns; see [`forget_recovery`]. Or, by default, it keeps the tree
//!   and answers through a correction of the readings fitted since the change; see
//!   [`correct_recovery`].
//! - **Re-training** (models that ask for it: nnw's nets): after a trial, nodes that took
//!   in enough new patterns are trained again on a sample of their box's stored patterns;
//!   see [`retrain`].
//! - **Bookkeeping.** Nodes, bins and patterns per depth are counted as they change
//!   ([`Levels`]); the [`PatternStore`] changes the bins, the nodes' bin lists and tallies
//!   and these counts together. No step walks the tree except a merge, over the subtree it
//!   cuts.

mod approximator;
mod arena;
mod bins;
mod branch;
mod correct_recovery;
mod eviction;
mod forget_recovery;
mod levels;
mod merge;
mod monitor;
mod narrowing;
mod nested_learner;
mod nested_tree;
mod node;
mod pattern_store;
mod records;
mod region;
mod retrain;
mod settings;
mod split;
#[cfg(test)]
mod tests;
mod training;
mod tree_state;

pub(crate) use approximator::{Approximator, Sample};
pub(crate) use arena::NodeArena;
pub(crate) use bins::Bins;
pub(crate) use branch::{BinKey, BranchRule, Halving, BRANCHES, MAX_DEPTH};
pub(crate) use forget_recovery::StaleVerdict;
pub(crate) use levels::Levels;
pub(crate) use monitor::Monitor;
pub(crate) use narrowing::Narrowing;
pub(crate) use nested_learner::tree_size;
pub use nested_learner::NestedLearner;
pub(crate) use nested_tree::{NestedTree, TreeEvent};
pub(crate) use node::{Node, NONE};
pub(crate) use pattern_store::PatternStore;
pub(crate) use records::Records;
pub(crate) use region::Region;
pub(crate) use retrain::Retraining;
pub use settings::{NestedSettings, TreeSettings};
pub(crate) use tree_state::{Journal, RecoveryState};

use nested_tree::{Path, ROOT};
