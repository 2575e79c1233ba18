//! The `mlp` learner: the trials' adjusted 5-input patterns go into a replay buffer, and
//! after each trial a few Adam steps on mini-batches drawn from it train the net.

use super::adam::Adam;
use super::checkpoints::Checkpoints;
use super::network::{Input, Network};
use super::replay_buffer::{Replay, Sample};
use super::MlpSettings;
use crate::learn::baselines::net::InputScaling;
use crate::learn::change::{SingleModel, SEED_TRIALS};
use crate::learn::{
    adjusted_pattern, centred, LearnError, Learner, LearnerStats, Method, Observation, Query,
};
use nalgebra::Vector3;
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

/// A two-hidden-layer perceptron of Δθ = N(c, θ2, θ3) trained online with replay.
#[derive(Debug, Clone)]
pub struct Mlp {
    settings: MlpSettings,
    /// Inputs from their boundaries onto [−1, 1].
    scaling: InputScaling<5>,
    net: Network,
    adam: Adam,
    /// The batch's gradient (laid out as the net's parameters).
    gradient: Vec<f64>,
    replay: Replay,
    /// Draws the batches.
    rng: ChaCha8Rng,
    /// The trial going on: it dates the patterns put into the buffer.
    trial: usize,
    /// The net and Adam at the start of the recent trials (none unless asked for).
    checkpoints: Checkpoints,
}

impl Mlp {
    /// A learner for inputs (θ2, θ3, cx, cy, cz) within `bounds`, each (low, high) with
    /// low < high.
    pub fn new(settings: MlpSettings, bounds: [(f64, f64); 5]) -> Mlp {
        let mut rng = ChaCha8Rng::seed_from_u64(settings.seed);
        let net = Network::new(settings.hidden, &mut rng);
        let count = net.params().len();
        Mlp {
            settings,
            scaling: InputScaling::new(bounds),
            net,
            adam: Adam::new(settings.rate, count),
            gradient: vec![0.0; count],
            replay: Replay::new(settings.buffer),
            rng,
            trial: 0,
            checkpoints: Checkpoints::new(0),
        }
    }

    /// The answer (degrees) at raw input `x`.
    pub fn predict(&mut self, x: &Input) -> Vector3<f64> {
        let mut answer = self.net.forward(&self.scaling.apply(x));
        if self.settings.anchored {
            answer -= self.net.forward(&self.scaling.apply(&centred(x)));
        }
        answer * self.settings.norm_out
    }

    /// Keeps one pattern of the trial going on (raw input `x`, joint move `target` in
    /// degrees, both finite) for replay.
    fn remember(&mut self, x: &Input, target: &Vector3<f64>) {
        self.replay.push(Sample {
            input: self.scaling.apply(x),
            centred: self.scaling.apply(&centred(x)),
            target: target / self.settings.norm_out,
            trial: self.trial,
        });
    }

    /// One Adam step on a batch drawn uniformly (with replacement) from the buffer.
    fn step(&mut self) {
        let held = self.replay.len();
        if held == 0 {
            return;
        }
        self.gradient.fill(0.0);
        for _ in 0..self.settings.batch {
            if crate::cancel::requested() {
                return; // a signal: this step is not taken, the run ends after the trial
            }
            let i = self.rng.random_range(0..held);
            let Some(s) = self.replay.get(i) else {
                continue;
            };
            if self.settings.anchored {
                self.net.accumulate_anchored_gradient(
                    &s.input,
                    &s.centred,
                    &s.target,
                    &mut self.gradient,
                );
            } else {
                self.net
                    .accumulate_gradient(&s.input, &s.target, &mut self.gradient);
            }
        }
        let scale = 1.0 / self.settings.batch as f64;
        self.gradient.iter_mut().for_each(|g| *g *= scale);
        self.adam.step(self.net.params_mut(), &self.gradient);
    }
}

impl Learner for Mlp {
    fn name(&self) -> &str {
        Method::Mlp.name()
    }

    fn propose(&mut self, query: &Query) -> Vector3<f64> {
        self.predict(&query.five_inputs())
    }

    /// Puts every pose pair of the trial into the buffer, then takes
    /// `steps_per_trial` Adam steps.
    fn learn(&mut self, path: &[Observation]) -> Result<(), LearnError> {
        for (from, to) in self.settings.patterns.pairs(path) {
            let pattern = adjusted_pattern(from, to);
            self.remember(&pattern.input, &pattern.target);
        }
        for _ in 0..self.settings.steps_per_trial {
            if crate::cancel::requested() {
                break; // a signal: the run ends after this trial
            }
            self.step();
        }
        Ok(())
    }

    fn stats(&self) -> LearnerStats {
        LearnerStats {
            nodes: 1,
            patterns: self.replay.len(),
            ..LearnerStats::default()
        }
    }

    fn start_trial(&mut self, trial: usize) {
        self.trial = trial;
        self.checkpoints.keep(trial, self.net.params(), &self.adam);
    }
}

impl SingleModel for Mlp {
    /// Drops every buffered pattern of the trials before `changed_at` (see the module's
    /// notes).
    fn forget_before(&mut self, changed_at: usize) {
        self.replay.drop_before(changed_at);
    }

    fn keep_recent_trials(&mut self) {
        self.checkpoints = Checkpoints::new(SEED_TRIALS);
    }

    /// Drops every buffered pattern of the trials since `changed_at` and sets the net and
    /// Adam back to where they were before it: those trials are in the readings the
    /// correction is about to carry back.
    fn unlearn_since(&mut self, changed_at: usize) {
        self.replay.drop_since(changed_at);
        self.checkpoints
            .restore(changed_at, self.net.params_mut(), &mut self.adam);
    }
}
