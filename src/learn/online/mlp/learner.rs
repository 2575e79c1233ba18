//! The `mlp` learner: the trials' adjusted 5-input patterns go into a replay buffer, and
//! after each trial a few Adam steps on mini-batches drawn from it train the net.

use super::adam::Adam;
use super::network::{Input, Network};
use super::replay_buffer::{Replay, Sample};
use super::MlpSettings;
use crate::learn::baselines::net::InputScaling;
use crate::learn::change::TrialMiss;
use crate::learn::inputs::finite_or_still;
use crate::learn::{
    adjusted_pattern, centred, LearnError, Learner, LearnerStats, Method, ModelEvent, Observation,
    Query,
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
    watch: Option<TrialMiss>,
    /// Patterns learned so far (the next one's number).
    patterns: u64,
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
            watch: settings.change_detection.as_ref().map(TrialMiss::new),
            patterns: 0,
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

    /// Keeps one pattern (raw input `x`, joint move `target` in degrees) for replay; one
    /// with a value that is not finite is skipped. Under change detection its miss by the
    /// net that drove the trial is booked first.
    fn remember(&mut self, x: &Input, target: &Vector3<f64>) {
        if !x.iter().chain(target.iter()).all(|v| v.is_finite()) {
            return;
        }
        if self.watch.is_some() {
            let miss = (self.predict(x) - target).norm();
            if let Some(watch) = &mut self.watch {
                watch.book(Some(miss), target.norm());
            }
        }
        self.replay.push(Sample {
            input: self.scaling.apply(x),
            centred: self.scaling.apply(&centred(x)),
            target: target / self.settings.norm_out,
            seq: self.patterns,
        });
        self.patterns += 1;
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
        finite_or_still(self.predict(&query.five_inputs()))
    }

    /// Puts every pose pair of the trial into the buffer, then takes
    /// `steps_per_trial` Adam steps. Under change detection the watch is given the
    /// trial's summed miss relative to its summed move (the net does not change during a
    /// trial, so that is the miss of the net that drove it).
    fn learn(&mut self, path: &[Observation]) -> Result<(), LearnError> {
        for (from, to) in self.settings.patterns.pairs(path) {
            let pattern = adjusted_pattern(from, to);
            self.remember(&pattern.input, &pattern.target);
        }
        if let Some(watch) = &mut self.watch {
            watch.close_trial();
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

    /// Under change detection, a detected change drops every buffered pattern from before
    /// the estimated change (see the module's notes).
    fn start_trial(&mut self, trial: usize) {
        let Some(watch) = &mut self.watch else {
            return;
        };
        if let Some(cutoff) = watch.start_trial(trial, self.patterns) {
            self.replay.drop_before(cutoff);
        }
    }

    fn drain_events(&mut self, sink: &mut Vec<ModelEvent>) {
        if let Some(watch) = &mut self.watch {
            watch.drain_events(sink);
        }
    }
}
