//! What every nested learner does around its tree: turning a trial's pose pairs into
//! patterns, training them, re-training after the trial, asking to relearn after a reset,
//! and — under `merge_strategy change_detection` — watching the trials for a change of the
//! mapping and recovering from it. Merges and detected changes are reported as
//! [`ModelEvent`]s.

use super::{Approximator, BranchRule, NestedTree, Records, TreeEvent, TreeSettings};
use crate::experiment::{Config, MergeStrategy};
use crate::learn::change::{ChangeWatch, WatchStep};
use crate::learn::{pose_pairs, Observation, Pattern};
use crate::learn::{LearnError, LearnerStats, ModelEvent};
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
    /// The change detection (`None` under `merge_strategy thesis`).
    watch: Option<ChangeWatch>,
    /// `change_min_fresh`: patterns from after a change a node needs to answer again.
    min_fresh: usize,
    /// A pattern file that failed while recovering before a trial; reported by the next
    /// [`learn`](Self::learn).
    failed: Option<LearnError>,
}

impl<A: Approximator<N>, R: BranchRule<N>, const N: usize> NestedLearner<A, R, N> {
    /// A learner growing its tree by `settings` from the box of `rule`, its models spawned
    /// from `template`, its patterns made by `pattern_of`; `minimal_joint_move`,
    /// `merge_strategy` and the `change_*` entries from `config`, its draws from stream
    /// `stream` of the config's `seed`. Patterns are kept in `pat_file` when given (created
    /// or emptied now), otherwise in memory.
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
        let watch = (config.merge_strategy == MergeStrategy::ChangeDetection)
            .then(|| ChangeWatch::new(config));
        Ok(NestedLearner {
            tree: NestedTree::new(settings, rule, template, records, rng),
            pattern_of,
            minimal_joint_move: config.minimal_joint_move,
            relearn: false,
            watch,
            min_fresh: config.change_min_fresh,
            failed: None,
        })
    }

    /// The tree's Δθ at input `x`; always finite.
    pub(crate) fn answer(&self, x: &SVector<f64, N>) -> Vector3<f64> {
        self.tree.answer(x)
    }

    /// Learns a trial's poses. Fails only when the patterns are kept in a file that can no
    /// longer be written or read: the run cannot go on without them.
    pub(crate) fn learn(&mut self, path: &[Observation]) -> Result<(), LearnError> {
        if let Some(error) = self.failed.take() {
            return Err(error);
        }
        for (from, to) in pose_pairs(path, self.minimal_joint_move) {
            let pattern = (self.pattern_of)(from, to);
            let event = self.tree.train(&pattern)?;
            if let Some(watch) = &mut self.watch {
                if event == TreeEvent::Reset {
                    watch.restart();
                }
                watch.pattern(self.tree.last_error, pattern.target.norm());
            }
            self.relearn |= event == TreeEvent::Reset;
        }
        self.tree.retrain_due().map(drop)
    }

    /// Nodes, bins and patterns, in total and per depth.
    pub(crate) fn stats(&self) -> LearnerStats {
        self.tree.stats()
    }

    /// True once after the root was merged (everything thrown away), or after a detected
    /// change left the root nothing to answer from.
    pub(crate) fn take_relearn_request(&mut self) -> bool {
        std::mem::take(&mut self.relearn)
    }

    /// What is learned from now on belongs to `trial` (0: pre-learning). Under change
    /// detection, the trial before is weighed first: after a detected change the tree
    /// forgets what came before it, and a grace period later cuts what is still starved.
    pub(crate) fn start_trial(&mut self, trial: usize) {
        let Some(watch) = &mut self.watch else {
            return;
        };
        match watch.start_trial(trial, self.tree.next_seq) {
            WatchStep::Nothing => {}
            WatchStep::Forget {
                estimated_trial,
                cutoff,
            } => {
                self.tree
                    .events
                    .push(ModelEvent::Change { estimated_trial });
                if let Err(error) = self.tree.forget_before(cutoff, self.min_fresh) {
                    self.failed = Some(error);
                }
                self.relearn |= !self.tree.root_answers();
            }
            WatchStep::CutStarved => {
                if !self.tree.cut_starved() {
                    watch.postpone_cut(trial);
                }
            }
        }
    }

    /// Moves the merges and detected changes since the last call into `sink`.
    pub(crate) fn drain_events(&mut self, sink: &mut Vec<ModelEvent>) {
        sink.append(&mut self.tree.events);
    }
}

/// Implements [`Learner`](crate::learn::Learner) for a learner that keeps its
/// [`NestedLearner`] in a field `nested`: `$method` is its [`Method`](crate::learn::Method),
/// `$input` turns a [`Query`](crate::learn::Query) into the tree's input.
macro_rules! learner_on_nested_tree {
    ($learner:ty, $method:expr, $input:expr) => {
        impl $crate::learn::Learner for $learner {
            fn method(&self) -> $crate::learn::Method {
                $method
            }

            fn propose(&mut self, query: &$crate::learn::Query) -> nalgebra::Vector3<f64> {
                self.nested.answer(&$input(query))
            }

            fn learn(
                &mut self,
                path: &[$crate::learn::Observation],
            ) -> Result<(), $crate::learn::LearnError> {
                self.nested.learn(path)
            }

            fn stats(&self) -> $crate::learn::LearnerStats {
                self.nested.stats()
            }

            fn take_relearn_request(&mut self) -> bool {
                self.nested.take_relearn_request()
            }

            fn start_trial(&mut self, trial: usize) {
                self.nested.start_trial(trial);
            }

            fn drain_events(&mut self, sink: &mut Vec<$crate::learn::ModelEvent>) {
                self.nested.drain_events(sink);
            }
        }
    };
}
pub(crate) use learner_on_nested_tree;
