//! The nested tree itself: its nodes, answering, the paths down it, adding and releasing
//! nodes (training a pattern is in `training`).

use super::{
    Approximator, BinKey, BranchRule, Journal, Node, NodeArena, PatternStore, Records,
    RecoveryState, Retraining, TreeSettings, MAX_DEPTH, NONE,
};
use crate::learn::{LearnError, LearnerStats};
use nalgebra::{SVector, Vector3};
use rand_chacha::ChaCha8Rng;

/// The root's index in the arena.
pub(super) const ROOT: u32 = 0;

/// What training one pattern did to the tree.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum TreeEvent {
    /// Trained and stored; the tree kept its shape.
    Trained,
    /// Trained and stored; a sub-box of the deepest node was split off.
    Split,
    /// Trained and stored; a subtree was cut off.
    Merged,
    /// The root was merged: everything learned and stored was thrown away.
    Reset,
    /// The pattern had a value that is not finite and was left out.
    Ignored,
}

/// The nodes a point passes from the root down to the deepest existing node.
#[derive(Debug, Clone, Copy)]
pub(super) struct Path {
    nodes: [u32; MAX_DEPTH + 1],
    len: usize,
}

impl Path {
    /// The nodes, root first.
    pub(super) fn nodes(&self) -> &[u32] {
        &self.nodes[..self.len]
    }

    /// The deepest node.
    pub(super) fn deepest(&self) -> u32 {
        self.nodes[self.len - 1]
    }
}

/// A tree of local models over an `N`-dimensional input box: the root covers the whole box,
/// a child one of its parent's sub-boxes (see [`BranchRule`]). Each pattern trains every
/// node on its path and is kept in its bin; sub-boxes that stay badly approximated are
/// split off, subtrees that do worse than they should are cut.
///
/// Nodes live in an arena (`Vec` plus free list) and link by `u32` indices. Patterns are
/// numbered in the order they are trained (from 0, never reset), so what was learned can be
/// dated.
///
/// The settings, the branching rule and the answering mode are the tree's own; what the
/// tree's other files change goes through the owned parts below and their methods: the
/// pattern store (bins and per-depth counts, kept in step with the nodes), the journal,
/// the recovery state and re-training's bookkeeping.
#[derive(Debug)]
pub(crate) struct NestedTree<A, R, const N: usize> {
    settings: TreeSettings,
    rule: R,
    /// The model new nodes' models are spawned from.
    template: A,
    /// Whether a query skips nodes whose fit does not support it (see
    /// [`after_correction`](Self::after_correction)).
    supported_answers: bool,
    pub(super) nodes: NodeArena<A, N>,
    pub(super) store: PatternStore<N>,
    /// The tree's seeded generator: models' starts, known patterns, re-training samples.
    pub(super) rng: ChaCha8Rng,
    pub(super) journal: Journal,
    pub(super) recovery: RecoveryState,
    pub(super) retraining: Retraining<N>,
}

impl<A: Approximator<N>, R: BranchRule<N>, const N: usize> NestedTree<A, R, N> {
    /// A tree of one root node, its models spawned from `template`, keeping patterns in
    /// `records`; known patterns (and the models' starts, if drawn) come from `rng`.
    ///
    /// # Panics
    /// If `settings.max_depth` is above [`MAX_DEPTH`] (the config never allows it).
    pub(crate) fn new(
        settings: TreeSettings,
        rule: R,
        template: A,
        records: Records<N>,
        rng: ChaCha8Rng,
    ) -> Self {
        assert!(
            settings.max_depth <= MAX_DEPTH,
            "tree_depth {} is above the deepest tree a bin key names ({MAX_DEPTH})",
            settings.max_depth
        );
        let mut tree = NestedTree {
            store: PatternStore::new(&settings, records),
            settings,
            rule,
            template,
            supported_answers: false,
            nodes: NodeArena::new(),
            rng,
            journal: Journal::default(),
            recovery: RecoveryState::default(),
            retraining: Retraining::default(),
        };
        tree.plant_root();
        tree
    }

    /// Δθ at `x`: the answer of the deepest node on its path that has one; zero if none
    /// has. Always finite. (After a detected change, a node awaiting new patterns answers
    /// from its stale fit if that has done better than deferring; once a correction is
    /// fixed, only nodes whose fit supports `x` answer, and the root in any case.)
    pub(crate) fn answer(&self, x: &SVector<f64, N>) -> Vector3<f64> {
        self.answer_on(&self.descend(self.key(x)), x)
    }

    /// [`answer`](Self::answer) at `x`, whose path is `path`.
    pub(super) fn answer_on(&self, path: &Path, x: &SVector<f64, N>) -> Vector3<f64> {
        path.nodes()
            .iter()
            .rev()
            .filter(|&&id| {
                !self.supported_answers || id == ROOT || self.nodes[id as usize].supports(x)
            })
            .find_map(|&id| self.nodes[id as usize].answer_or_stale(x, self.recovery.verdict()))
            .unwrap_or_else(Vector3::zeros)
    }

    /// Nodes, bins and patterns, in total and per depth.
    pub(crate) fn stats(&self) -> LearnerStats {
        let levels = self.store.level_stats();
        LearnerStats {
            nodes: levels.iter().map(|l| l.nodes).sum(),
            bins: levels.iter().map(|l| l.bins).sum(),
            patterns: levels.iter().map(|l| l.patterns).sum(),
            levels,
        }
    }

    /// Throws away every node, bin and pattern; the root starts afresh.
    pub(super) fn reset(&mut self) -> Result<(), LearnError> {
        self.store.clear()?;
        self.recovery.end();
        self.plant_root();
        Ok(())
    }

    fn plant_root(&mut self) {
        self.retraining.clear();
        let window = self.settings.am_error_iters;
        let model = self.template.spawn(&mut self.rng);
        let mut root = Node::new(model, *self.rule.root(), NONE, 0, 0, window);
        root.born = self.journal.next_seq();
        self.nodes.replant(root);
        self.store.node_added(0);
    }

    /// The tree's settings.
    pub(super) fn settings(&self) -> &TreeSettings {
        &self.settings
    }

    /// The branching rule.
    #[cfg(test)]
    pub(super) fn rule(&self) -> &R {
        &self.rule
    }

    /// The bin key of input `x`: its branches down to the tree's deepest depth.
    pub(super) fn key(&self, x: &SVector<f64, N>) -> BinKey {
        self.rule.key(x, self.settings.max_depth)
    }

    /// Once a correction is fixed: from now on a sub-box is split off once it holds
    /// `patterns` stored patterns, if that is sooner than before, and a query is answered
    /// only by nodes whose fit supports it (and the root in any case).
    pub(super) fn answer_where_supported(&mut self, patterns: usize) {
        let split = &mut self.settings.min_pats_for_split;
        *split = (*split).min(patterns);
        self.supported_answers = true;
    }

    /// The path of a point with bin key `key`.
    pub(super) fn descend(&self, key: BinKey) -> Path {
        let mut path = Path {
            nodes: [ROOT; MAX_DEPTH + 1],
            len: 1,
        };
        for depth in 1..=key.reach() {
            let Some(branch) = key.branch(depth) else {
                break;
            };
            let child = self.nodes[path.deepest() as usize].children[usize::from(branch)];
            if child == NONE {
                break;
            }
            path.nodes[path.len] = child;
            path.len += 1;
        }
        path
    }

    /// A new child of `parent` at `branch`, with a fresh model and nothing else yet.
    pub(super) fn add_child(&mut self, parent: u32, branch: u8) -> u32 {
        let (region, depth) = {
            let p = &self.nodes[parent as usize];
            (self.rule.child(&p.region, p.depth + 1, branch), p.depth + 1)
        };
        let window = self.settings.am_error_iters;
        let model = self.template.spawn(&mut self.rng);
        let mut node = Node::new(model, region, parent, branch, depth, window);
        node.born = self.journal.next_seq();
        let id = self.nodes.insert(node);
        self.nodes[parent as usize].children[usize::from(branch)] = id;
        self.store.node_added(depth);
        id
    }

    /// Node `id` and every node below it, in the order a depth-first walk takes them (a
    /// node before its children, the last child first).
    pub(super) fn subtree(&self, id: u32) -> Vec<u32> {
        let (mut order, mut stack) = (Vec::new(), vec![id]);
        while let Some(x) = stack.pop() {
            order.push(x);
            let children = &self.nodes[x as usize].children;
            stack.extend(children.iter().copied().filter(|&c| c != NONE));
        }
        order
    }

    /// Returns node `id`, already unlinked, to the arena.
    pub(super) fn release(&mut self, id: u32) {
        self.nodes.release(id);
    }
}
