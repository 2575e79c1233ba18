//! What every nested learner does around its tree: turning a trial's pose pairs into
//! patterns, training them, re-training after the trial, asking to relearn after a reset,
//! and — under `merge_strategy change_detection` — watching the trials for a change of the
//! mapping and recovering from it. Merges and detected changes are reported as
//! [`ModelEvent`]s.

use super::{Approximator, BranchRule, NestedSettings, NestedTree, Records, TreeEvent};
use crate::learn::change::{ChangeRecovery, ChangeWatch, Corrections, WatchStep};
use crate::learn::{
    LearnError, Learner, LearnerStats, MergeStrategy, Method, ModelEvent, Observation, Pattern,
    PatternSettings, Query,
};
use nalgebra::{SVector, Vector3};
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;
use std::path::PathBuf;

/// How a pose pair (before, after) becomes a learning pattern.
pub(crate) type PatternOf<const N: usize> = fn(&Observation, &Observation) -> Pattern<N>;

/// How a query becomes the tree's input.
pub(crate) type InputOf<const N: usize> = fn(&Query) -> SVector<f64, N>;

/// A nested learner: a tree of `A` models over `N` inputs branching by `R`, and how it
/// learns from a trial: every pose pair that moved gives a pattern, trained to its node and
/// all of the node's ancestors; nodes that are due are then re-trained. [`Lin5`],
/// [`Lin8`] and [`Nnw`] are its three forms.
///
/// [`Lin5`]: crate::learn::Lin5
/// [`Lin8`]: crate::learn::Lin8
/// [`Nnw`]: crate::learn::Nnw
#[derive(Debug)]
pub struct NestedLearner<A, R, const N: usize> {
    method: Method,
    tree: NestedTree<A, R, N>,
    pattern_of: PatternOf<N>,
    input_of: InputOf<N>,
    patterns: PatternSettings,
    relearn: bool,
    /// The change detection (`None` under `merge_strategy thesis`).
    watch: Option<ChangeWatch>,
    /// `change_min_fresh`: patterns from after a change a node needs to answer again.
    min_fresh: usize,
    /// `change_recovery`: what an alarm does.
    recovery: ChangeRecovery,
    /// `change_split_patterns`: the tree's split threshold once a correction is fixed.
    split_patterns: usize,
    /// The trial being learned (see [`Learner::start_trial`]).
    trial: usize,
    /// The corrections of the readings fitted after alarms (`change_recovery correct`).
    corrections: Corrections<N>,
    /// A pattern file that failed while recovering before a trial; reported by the next
    /// [`learn`](Self::learn).
    failed: Option<LearnError>,
}

/// The size of a nested learner in the one-screen report: its tree's nodes, bins and
/// stored patterns.
pub(crate) fn tree_size(stats: &LearnerStats) -> String {
    format!(
        "tree: {} nodes, {} bins, {} patterns; ",
        stats.nodes, stats.bins, stats.patterns
    )
}

// The node models and branching rules are the crate's own: users build the three forms
// (`Lin5::new`, `Lin8::new`, `Nnw::new`), not their own trees.
#[allow(private_bounds)]
impl<A: Approximator<N>, R: BranchRule<N>, const N: usize> NestedLearner<A, R, N> {
    /// A `method` learner growing its tree by `settings` from the box of `rule`, its models
    /// spawned from `template`, its patterns made by `pattern_of`, its queries turned into
    /// inputs by `input_of`, its draws from stream `stream` of the settings' seed. Patterns
    /// are kept in `pat_file` when given (created or emptied now), otherwise in memory.
    pub(crate) fn build(
        method: Method,
        settings: &NestedSettings,
        (rule, template): (R, A),
        (pattern_of, input_of): (PatternOf<N>, InputOf<N>),
        pat_file: Option<PathBuf>,
        stream: u64,
    ) -> Result<Self, LearnError> {
        let records = match pat_file {
            Some(path) => Records::in_file(&path)?,
            None => Records::in_memory(),
        };
        let mut rng = ChaCha8Rng::seed_from_u64(settings.seed);
        rng.set_stream(stream);
        let watch = (settings.merge_strategy == MergeStrategy::ChangeDetection)
            .then(|| ChangeWatch::new(&settings.change));
        Ok(NestedLearner {
            method,
            tree: NestedTree::new(settings.tree.clone(), rule, template, records, rng),
            pattern_of,
            input_of,
            patterns: settings.patterns,
            relearn: false,
            watch,
            min_fresh: settings.change.min_fresh,
            recovery: settings.change.recovery,
            split_patterns: settings.change.split_patterns,
            trial: 0,
            corrections: Corrections::new(settings.change.fit_patterns),
            failed: None,
        })
    }
}

impl<A: Approximator<N>, R: BranchRule<N>, const N: usize> Learner for NestedLearner<A, R, N> {
    fn name(&self) -> &str {
        self.method.name()
    }

    /// The tree's Δθ at the query's input (through the corrections fitted after changes);
    /// always finite.
    fn propose(&mut self, query: &Query) -> Vector3<f64> {
        self.tree
            .answer(&self.corrections.query(&(self.input_of)(query)))
    }

    /// Learns a trial's poses. Fails only when the patterns are kept in a file that can no
    /// longer be written or read: the run cannot go on without them. While a correction
    /// is fitted after a change, the patterns go to its fit instead, and the tree learns
    /// them once it is fixed. A trial that yields no pattern is booked as a failure with
    /// the change watch. Once a pattern merges the root, the rest of the trial is left
    /// unlearned: the fresh tree starts from pre-learning, as at the start of a run.
    fn learn(&mut self, path: &[Observation]) -> Result<(), LearnError> {
        if let Some(error) = self.failed.take() {
            return Err(error);
        }
        let seeding = self.watch.is_some() && self.recovery == ChangeRecovery::Correct;
        let mut patterns = 0;
        let last = path.last();
        for (from, to) in self.patterns.pairs(path) {
            patterns += 1;
            // A step's miss is what its move lacked to reach where the trial ended.
            let monitored = last.is_some_and(|last| std::ptr::eq(to, last));
            let pattern = (self.pattern_of)(from, to);
            if seeding {
                self.corrections.remember(self.trial, (from, to), &pattern);
            }
            if self.corrections.fitting() {
                self.corrections.book(&pattern);
            } else {
                let corrected = self.corrections.pattern(&pattern);
                // lin8's fresh root, given the trial's last few patterns (whose readings
                // after the move vary, too few to fit them) before pre-learning, answers
                // no move from then on: the arm stays put and learns nothing more.
                if self.train(&corrected, true, monitored)? == TreeEvent::Reset {
                    break;
                }
            }
        }
        if let (0, Some(watch)) = (patterns, &mut self.watch) {
            watch.no_pattern();
        }
        let tree = &self.tree;
        if let Some(fresh) = self.corrections.refit(|x| tree.answer(x)) {
            self.tree.after_correction(self.split_patterns);
            for pattern in fresh {
                self.train(&pattern, false, false)?;
            }
        }
        self.tree.retrain_due().map(drop)
    }

    /// Nodes, bins and patterns, in total and per depth.
    fn stats(&self) -> LearnerStats {
        self.tree.stats()
    }

    /// True once after the root was merged (everything thrown away), or after a detected
    /// change left the root nothing to answer from.
    fn take_relearn_request(&mut self) -> bool {
        std::mem::take(&mut self.relearn)
    }

    /// What is learned from now on belongs to `trial` (0: pre-learning). Under change
    /// detection, the trial before is weighed first: after a detected change the tree
    /// forgets what came before it, and a grace period later cuts what is still starved.
    fn start_trial(&mut self, trial: usize) {
        self.trial = trial;
        let Some(watch) = &mut self.watch else {
            return;
        };
        match watch.start_trial(trial, self.tree.journal.next_seq()) {
            WatchStep::Nothing => {}
            WatchStep::Forget {
                estimated_trial,
                cutoff,
            } => {
                self.tree
                    .journal
                    .book(ModelEvent::Change { estimated_trial });
                if let Err(error) = self.recover(estimated_trial, cutoff) {
                    self.failed = Some(error);
                }
            }
            WatchStep::CutStarved => {
                if !self.tree.cut_starved() {
                    watch.postpone_cut(trial);
                }
            }
        }
    }

    /// Moves the merges and detected changes since the last call into `sink`.
    fn drain_events(&mut self, sink: &mut Vec<ModelEvent>) {
        self.tree.journal.drain_into(sink);
    }
}

#[allow(private_bounds)]
impl<A: Approximator<N>, R: BranchRule<N>, const N: usize> NestedLearner<A, R, N> {
    /// Trains one pattern; `watched`: its error counts towards the change watch's value of
    /// the trial; `monitored`: towards the running errors of the nodes on its path. Returns
    /// what training it did to the tree.
    fn train(
        &mut self,
        pattern: &Pattern<N>,
        watched: bool,
        monitored: bool,
    ) -> Result<TreeEvent, LearnError> {
        let event = self.tree.train_monitored(pattern, monitored)?;
        if let Some(watch) = &mut self.watch {
            if event == TreeEvent::Reset {
                watch.restart();
            }
            if watched {
                watch.pattern(self.tree.journal.last_error(), pattern.target.norm());
            }
        }
        self.relearn |= event == TreeEvent::Reset;
        Ok(event)
    }

    /// After an alarm dating the change at trial `changed_at`, pattern number `cutoff`:
    /// starts fitting a correction, or forgets what came before the change.
    fn recover(&mut self, changed_at: usize, cutoff: u64) -> Result<(), LearnError> {
        match self.recovery {
            ChangeRecovery::Correct => {
                let (low, high) = self.tree.root_box();
                self.corrections.start(changed_at, &low, &high);
            }
            ChangeRecovery::Forget => {
                self.tree.forget_before(cutoff, self.min_fresh)?;
                self.relearn |= !self.tree.root_answers();
            }
        }
        Ok(())
    }
}
