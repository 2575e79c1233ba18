//! What every nested learner does around its tree: turning a trial's pose pairs into
//! patterns, training them, re-training after the trial, asking to relearn after a reset.

use super::{Approximator, BranchRule, NestedTree, Records, TreeEvent, TreeSettings};
use crate::control::{pose_pairs, Observation, Pattern};
use crate::experiment::Config;
use crate::learn::{LearnError, LearnerStats};
use nalgebra::{SVector, Vector3};
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;
use std::path::PathBuf;

/// How a pose pair (before, after) becomes a learning pattern.
pub(crate) type PatternOf<const N: usize> = fn(&Observation, &Observation) -> Pattern<N>;

/// A nested tree of `A` models over `N` inputs branching by `R`, and how it learns from a
/// trial: every pose pair that moved gives a pattern, trained to its node and all of the
/// node's ancestors; nodes that are due are then re-trained.
#[derive(Debug)]
pub(crate) struct NestedLearner<A, R, const N: usize> {
    tree: NestedTree<A, R, N>,
    pattern_of: PatternOf<N>,
    minimal_joint_move: f64,
    relearn: bool,
}

impl<A: Approximator<N>, R: BranchRule<N>, const N: usize> NestedLearner<A, R, N> {
    /// A learner growing its tree by `settings` from the box of `rule`, its models spawned
    /// from `template`, its patterns made by `pattern_of`; `minimal_joint_move` from
    /// `config`, its draws from stream `stream` of the config's `seed`. Patterns are kept
    /// in `pat_file` when given (created or emptied now), otherwise in memory.
    pub(crate) fn new(
        config: &Config,
        settings: TreeSettings,
        rule: R,
        template: A,
        pattern_of: PatternOf<N>,
        pat_file: Option<PathBuf>,
        stream: u64,
    ) -> Result<Self, LearnError> {
        let records = match pat_file {
            Some(path) => Records::in_file(&path)?,
            None => Records::in_memory(),
        };
        let mut rng = ChaCha8Rng::seed_from_u64(config.seed);
        rng.set_stream(stream);
        Ok(NestedLearner {
            tree: NestedTree::new(settings, rule, template, records, rng),
            pattern_of,
            minimal_joint_move: config.minimal_joint_move,
            relearn: false,
        })
    }

    /// The tree's Δθ at input `x`; always finite.
    pub(crate) fn answer(&self, x: &SVector<f64, N>) -> Vector3<f64> {
        self.tree.answer(x)
    }

    /// Learns a trial's poses. Fails only when the patterns are kept in a file that can no
    /// longer be written or read: the run cannot go on without them.
    pub(crate) fn learn(&mut self, path: &[Observation]) -> Result<(), LearnError> {
        for (from, to) in pose_pairs(path, self.minimal_joint_move) {
            if self.tree.train(&(self.pattern_of)(from, to))? == TreeEvent::Reset {
                self.relearn = true;
            }
        }
        self.tree.retrain_due().map(drop)
    }

    /// Nodes, bins and patterns, in total and per depth.
    pub(crate) fn stats(&self) -> LearnerStats {
        self.tree.stats()
    }

    /// True once after the root was merged (everything thrown away).
    pub(crate) fn take_relearn_request(&mut self) -> bool {
        std::mem::take(&mut self.relearn)
    }
}
