//! A tree node: its box, its model, its error monitors and the bins that hang on it.

use super::{Approximator, Monitor, Region, StaleVerdict, BRANCHES};
use nalgebra::{SVector, Vector3};
use rand::Rng;
use rand_chacha::ChaCha8Rng;

/// The index of "no node" (no parent, no child).
pub(crate) const NONE: u32 = u32::MAX;
/// A sub-box with no error monitor yet.
const NO_SLOT: u8 = u8::MAX;

/// One node of the tree, stored in the tree's arena and linked by indices.
#[derive(Debug, Clone)]
pub(crate) struct Node<A, const N: usize> {
    /// The parent's index, [`NONE`] for the root.
    pub(super) parent: u32,
    /// This node's branch number under its parent.
    pub(super) branch: u8,
    /// Depth: 0 for the root.
    pub(super) depth: usize,
    /// Child index per branch, [`NONE`] where there is none.
    pub(super) children: [u32; BRANCHES],
    /// The node's box.
    pub(super) region: Region<N>,
    /// The node's model.
    pub(super) model: A,
    /// Its own running error E, for the absolute and relative merge.
    pub(super) errors: Monitor,
    /// Its running error on each sub-box: the split test where there is no child yet, its
    /// side of the relative merge test where there is one. Made on first use, in the order
    /// of first use; `box_slots` says where each sub-box's is. (Most nodes see only a few
    /// sub-boxes, and nodes at the deepest depth none: 32 monitors in place would be 2 kB
    /// a node.)
    box_errors: Vec<Monitor>,
    /// Per sub-box: its monitor's place in `box_errors`, [`NO_SLOT`] until made.
    box_slots: [u8; BRANCHES],
    /// The bins hanging on this node: those whose deepest existing node it is.
    pub(super) bins: Vec<u32>,
    /// Patterns kept in those bins (changed only through the methods below).
    patterns: usize,
    /// Of those, the patterns in each sub-box.
    box_patterns: [usize; BRANCHES],
    /// Patterns taken in since the model was last re-trained (re-trained models only).
    pub(super) fresh: usize,
    /// The number of the first pattern trained to the tree after this node was made.
    pub(super) born: u64,
    /// Patterns taken in since it was made (known patterns, and those it was split off
    /// with, aside).
    pub(super) taken: u64,
    /// At the last detected change: patterns it took in per pattern trained to the tree
    /// until then.
    pub(super) pace: f64,
    /// After a detected change: patterns from after it the node still needs before its
    /// model answers again (0: it answers whenever its model can). Meanwhile it may answer
    /// from its model's stale fit, see [`answer_or_stale`](Self::answer_or_stale).
    pub(super) awaiting: usize,
    /// Meanwhile: how its stale fit did against its nearest answering ancestor.
    pub(super) verdict: StaleVerdict,
    known_anchor: Option<SVector<f64, N>>,
    /// Known patterns owed: a fraction of one.
    known_credit: f64,
}

impl<A: Approximator<N>, const N: usize> Node<A, N> {
    /// A node with a fresh `model` for box `region`; errors averaged over `window`.
    pub(super) fn new(
        model: A,
        region: Region<N>,
        parent: u32,
        branch: u8,
        depth: usize,
        window: usize,
    ) -> Self {
        Node {
            parent,
            branch,
            depth,
            children: [NONE; BRANCHES],
            region,
            model,
            errors: Monitor::new(window),
            box_errors: Vec::new(),
            box_slots: [NO_SLOT; BRANCHES],
            bins: Vec::new(),
            patterns: 0,
            box_patterns: [0; BRANCHES],
            fresh: 0,
            born: 0,
            taken: 0,
            pace: 0.0,
            awaiting: 0,
            verdict: StaleVerdict::default(),
            known_anchor: region.known_anchor(),
            known_credit: 0.0,
        }
    }

    /// The node's own answer at global input `x`, if its model has one and it is not
    /// awaiting patterns from after a change.
    pub(super) fn answer(&self, x: &SVector<f64, N>) -> Option<Vector3<f64>> {
        if self.awaiting > 0 {
            return None;
        }
        self.model
            .answer(&self.region.local(x))
            .filter(|o| o.iter().all(|v| v.is_finite()))
    }

    /// Whether the node's fit is backed by its patterns at global input `x`.
    pub(super) fn supports(&self, x: &SVector<f64, N>) -> bool {
        self.model.supports(&self.region.local(x))
    }

    /// While the node awaits patterns from after a change: its model's fit from before
    /// the change at global input `x`, if it kept one.
    pub(super) fn stale_answer(&self, x: &SVector<f64, N>) -> Option<Vector3<f64>> {
        if self.awaiting == 0 {
            return None;
        }
        self.model
            .stale_answer(&self.region.local(x))
            .filter(|o| o.iter().all(|v| v.is_finite()))
    }

    /// Whether the node, while it awaits patterns, answers from its stale fit: by its own
    /// verdict once that has enough comparisons, by the tree's (`tree`) until then.
    pub(super) fn stale_ok(&self, tree: &StaleVerdict) -> bool {
        self.verdict.decided().unwrap_or_else(|| tree.stale_ok())
    }

    /// The node's answer at `x`: its own, or while it awaits patterns its stale one if
    /// that does better (see [`stale_ok`](Self::stale_ok)).
    pub(super) fn answer_or_stale(
        &self,
        x: &SVector<f64, N>,
        tree: &StaleVerdict,
    ) -> Option<Vector3<f64>> {
        self.answer(x)
            .or_else(|| self.stale_ok(tree).then(|| self.stale_answer(x)).flatten())
    }

    /// Trains pattern number `seq` (`x` global, `target`) to the model, followed by the
    /// known patterns it earns: `known_share` of one per pattern, drawn with `rng`. A node
    /// whose box does not hold the camera zero gets none. The model still needs a refit.
    pub(super) fn take_in(
        &mut self,
        x: &SVector<f64, N>,
        target: &Vector3<f64>,
        seq: u64,
        known_share: f64,
        rng: &mut ChaCha8Rng,
    ) {
        self.awaiting = self.awaiting.saturating_sub(1);
        self.taken += 1;
        self.model.add(&self.region.local(x), target, seq);
        let Some(anchor) = self.known_anchor else {
            return;
        };
        self.known_credit += known_share;
        while self.known_credit >= 1.0 {
            self.known_credit -= 1.0;
            let mut known = anchor;
            known[0] = rng.random_range(-1.0..=1.0);
            known[1] = rng.random_range(-1.0..=1.0);
            self.model.add(&known, &Vector3::zeros(), seq);
        }
    }

    /// The running error on sub-box `branch`, if any was measured.
    pub(super) fn box_errors(&self, branch: u8) -> Option<&Monitor> {
        let slot = self.box_slots[usize::from(branch)];
        (slot != NO_SLOT).then(|| &self.box_errors[usize::from(slot)])
    }

    /// The running error on sub-box `branch`, made with `window` on first use.
    pub(super) fn box_errors_mut(&mut self, branch: u8, window: usize) -> &mut Monitor {
        let slot = &mut self.box_slots[usize::from(branch)];
        if *slot == NO_SLOT {
            // (At most BRANCHES = 32 sub-boxes: a slot always fits a u8 below NO_SLOT.)
            *slot = self.box_errors.len() as u8;
            self.box_errors.push(Monitor::new(window));
        }
        &mut self.box_errors[usize::from(*slot)]
    }

    /// Starts measuring every sub-box anew.
    pub(super) fn clear_all_box_errors(&mut self) {
        self.box_errors.iter_mut().for_each(Monitor::clear);
    }

    /// Patterns kept in the bins hanging on this node.
    pub(super) fn patterns(&self) -> usize {
        self.patterns
    }

    /// Of those, the patterns in each sub-box.
    pub(super) fn box_patterns(&self) -> [usize; BRANCHES] {
        self.box_patterns
    }

    /// `n` patterns came into this node's bins, in sub-box `branch` (`None`: at the
    /// deepest depth, where there are no sub-boxes).
    pub(super) fn patterns_added(&mut self, branch: Option<u8>, n: usize) {
        self.patterns += n;
        if let Some(branch) = branch {
            self.box_patterns[usize::from(branch)] += n;
        }
    }

    /// `n` patterns left this node's bins, from sub-box `branch` (`None` as above).
    pub(super) fn patterns_removed(&mut self, branch: Option<u8>, n: usize) {
        self.patterns -= n;
        if let Some(branch) = branch {
            self.box_patterns[usize::from(branch)] -= n;
        }
    }

    /// Sub-box `branch`'s bins, holding `n` patterns, went down to a new child.
    pub(super) fn box_split_off(&mut self, branch: u8, n: usize) {
        debug_assert_eq!(self.box_patterns[usize::from(branch)], n);
        self.patterns -= n;
        self.box_patterns[usize::from(branch)] = 0;
    }

    /// Starts measuring sub-box `branch` anew.
    pub(super) fn clear_box_errors(&mut self, branch: u8) {
        let slot = self.box_slots[usize::from(branch)];
        if slot != NO_SLOT {
            self.box_errors[usize::from(slot)].clear();
        }
    }
}
