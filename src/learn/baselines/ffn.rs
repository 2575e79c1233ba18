//! The `ffn` learner: one feed-forward net over the whole input space, as the study's
//! first baseline. Its inputs are (θ2, θ3, cx, cy, cz) scaled to the config's boundaries;
//! it learns the adjusted patterns of each trial, kept in a window of the most recent ones,
//! by conjugate-gradient back-propagation on that window after every trial.

use super::net::{minimize, BatchLoss, DenseNet, InputScaling};
use crate::learn::change::SingleModel;
use crate::learn::MethodFacts;
use crate::learn::{adjusted_pattern, Observation, PatternSettings, Query};
use crate::learn::{LearnError, Learner, LearnerStats, Method};
use nalgebra::{SVector, Vector3};
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;

/// Outputs are Δθ divided by this (degrees), so the net's targets are near ±1.
const OUTPUT_SCALE_DEG: f64 = 30.0;

/// Settings of the `ffn` learner.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FfnSettings {
    /// Hidden units; 25 by default (45 repeats the study's second net).
    pub hidden_units: usize,
    /// Initial weights are drawn in ±wrange; 0.1 by default.
    pub wrange: f64,
    /// Most recent patterns the net is trained on; 1,000 by default.
    pub window: usize,
    /// Conjugate-gradient iterations after each trial; 10 by default.
    pub cg_iterations: usize,
    /// Which pose pairs are patterns (`minimal_joint_move`).
    pub patterns: PatternSettings,
}

impl Default for FfnSettings {
    fn default() -> Self {
        FfnSettings {
            hidden_units: 25,
            wrange: 0.1,
            window: 1000,
            cg_iterations: 10,
            patterns: PatternSettings::default(),
        }
    }
}

type Sample = (SVector<f64, 5>, SVector<f64, 3>);

/// One feed-forward net trained by conjugate gradients.
#[derive(Debug, Clone)]
pub struct FfnLearner {
    settings: FfnSettings,
    net: DenseNet<5, 3>,
    scaling: InputScaling<5>,
    window: Vec<Sample>,
    /// The trial each sample of the window was learned in.
    window_trials: Vec<usize>,
    next_slot: usize,
    /// The trial going on.
    trial: usize,
}

impl FfnLearner {
    /// A learner for inputs in `bounds` (θ2, θ3, cx, cy, cz), weights drawn from `seed`.
    pub fn new(settings: FfnSettings, bounds: [(f64, f64); 5], seed: u64) -> FfnLearner {
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        FfnLearner {
            settings,
            net: DenseNet::new(settings.hidden_units, settings.wrange, &mut rng),
            scaling: InputScaling::new(bounds),
            window: Vec::with_capacity(settings.window),
            window_trials: Vec::with_capacity(settings.window),
            next_slot: 0,
            trial: 0,
        }
    }

    fn remember(&mut self, sample: Sample) {
        if self.window.len() < self.settings.window {
            self.window.push(sample);
            self.window_trials.push(self.trial);
        } else {
            self.window[self.next_slot] = sample;
            self.window_trials[self.next_slot] = self.trial;
        }
        self.next_slot = (self.next_slot + 1) % self.settings.window;
    }
}

impl Learner for FfnLearner {
    fn name(&self) -> &str {
        Method::Ffn.name()
    }

    fn propose(&mut self, query: &Query) -> Vector3<f64> {
        let out = self.net.forward(&self.scaling.apply(&query.five_inputs())) * OUTPUT_SCALE_DEG;
        if out.iter().all(|v| v.is_finite()) {
            out
        } else {
            Vector3::zeros()
        }
    }

    fn learn(&mut self, path: &[Observation]) -> Result<(), LearnError> {
        let before = self.window.len();
        for (from, to) in self.settings.patterns.pairs(path) {
            let p = adjusted_pattern(from, to);
            self.remember((self.scaling.apply(&p.input), p.target / OUTPUT_SCALE_DEG));
        }
        if self.window.is_empty() || (self.window.len() == before && path.len() < 2) {
            return Ok(());
        }
        let mut params = self.net.params().to_vec();
        let mut objective = BatchLoss::new(&mut self.net, &self.window);
        minimize(&mut objective, &mut params, self.settings.cg_iterations);
        Ok(())
    }

    fn stats(&self) -> LearnerStats {
        LearnerStats {
            nodes: 1,
            bins: 0,
            patterns: self.window.len(),
            levels: Vec::new(),
        }
    }

    fn start_trial(&mut self, trial: usize) {
        self.trial = trial;
    }
}

/// It cannot forget what its net learned (the config refuses `change_recovery forget` for
/// it), but its window can drop patterns.
impl SingleModel for FfnLearner {
    /// Drops the window's patterns of the trials since `changed_at`, oldest kept first; the
    /// net is trained on what is left after the next trial.
    fn unlearn_since(&mut self, changed_at: usize) {
        let (older, newer) = self.window.split_at(self.next_slot.min(self.window.len()));
        let (older_trials, newer_trials) = self.window_trials.split_at(older.len());
        // Oldest first: the slots from `next_slot` on were written before those below it.
        let kept: Vec<(Sample, usize)> = newer
            .iter()
            .zip(newer_trials)
            .chain(older.iter().zip(older_trials))
            .filter(|&(_, &trial)| trial < changed_at)
            .map(|(&sample, &trial)| (sample, trial))
            .collect();
        (self.window, self.window_trials) = kept.into_iter().unzip();
        self.next_slot = self.window.len() % self.settings.window;
    }
}

/// What the program knows of `ffn` besides its learner (see [`Method::facts`](crate::learn::Method::facts)).
pub(crate) const FFN_FACTS: MethodFacts = MethodFacts {
    name: "ffn",
    size: |_| String::new(),
    counts_nodes: false,
    kb_per_trial: 0.0,
    bounded: true,
    watches_changes: true,
    slow_entries: "ffn_cg_iterations, ffn_window, ffn_hidden_units",
    // One net for the whole space learns slowly: its results are measured over 20,000
    // trials.
    shared_defaults: &[("trials", "20000")],
};
