//! The `issgp` learner: random features of the scaled adjusted 5-input patterns and the
//! posterior of their weights, with forgetting, restarted from its mean when a detected
//! change calls for it, or rid of the patterns learned since the change when a correction
//! is to carry the new readings back (it keeps the patterns of its recent trials for that).

use super::features::{Features, Input};
use super::posterior::Posterior;
use super::IssgpSettings;
use crate::learn::baselines::net::InputScaling;
use crate::learn::change::SingleModel;
use crate::learn::change::SEED_TRIALS;
use crate::learn::{
    adjusted_pattern, centred, LearnError, Learner, LearnerStats, Method, Observation, Query,
};
use nalgebra::{DVector, Vector3};
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;
use std::collections::VecDeque;

/// Incremental sparse spectrum Gaussian process regression of Δθ = N(c, θ2, θ3).
#[derive(Debug, Clone)]
pub struct Issgp {
    settings: IssgpSettings,
    /// Inputs from their boundaries onto [−1, 1].
    scaling: InputScaling<5>,
    features: Features,
    posterior: Posterior,
    /// The features of the input at hand, and (anchored) of its centred twin.
    phi: DVector<f64>,
    phi_centred: DVector<f64>,
    /// The trial going on: it dates the patterns kept in `recent`.
    trial: usize,
    /// Whether the patterns of the recent trials are kept (`change_recovery correct`).
    keeps_recent: bool,
    /// The patterns of the last [`SEED_TRIALS`] trials, oldest first, while they are kept.
    recent: VecDeque<Learned>,
}

/// A pattern learned, and what taking it out again needs.
#[derive(Debug, Clone, Copy)]
struct Learned {
    trial: usize,
    input: Input,
    target: Vector3<f64>,
    /// Its ticket from `Posterior::add`.
    ticket: f64,
}

impl Issgp {
    /// A learner for inputs (θ2, θ3, cx, cy, cz) within `bounds`, each (low, high) with
    /// low < high.
    pub fn new(settings: IssgpSettings, bounds: [(f64, f64); 5]) -> Issgp {
        let mut rng = ChaCha8Rng::seed_from_u64(settings.seed);
        // A scaled input spans 2 over its boundary range.
        let length_scales = Input::from(settings.length_scales) * 2.0;
        let features = Features::new(settings.features, &length_scales, settings.signal, &mut rng);
        Issgp {
            settings,
            scaling: InputScaling::new(bounds),
            posterior: Posterior::new(settings.features, settings.noise, settings.forgetting),
            phi: DVector::zeros(features.len()),
            phi_centred: DVector::zeros(if settings.anchored { features.len() } else { 0 }),
            features,
            trial: 0,
            keeps_recent: false,
            recent: VecDeque::new(),
        }
    }

    /// Writes the features of raw input `x` into `phi`: φ(x), anchored φ(x) − φ(x
    /// centred).
    fn write_features(&mut self, x: &Input) {
        self.features.write(&self.scaling.apply(x), &mut self.phi);
        if self.settings.anchored {
            let centred = self.scaling.apply(&centred(x));
            self.features.write(&centred, &mut self.phi_centred);
            self.phi -= &self.phi_centred;
        }
    }

    /// The answer (degrees) at raw input `x`.
    pub fn predict(&mut self, x: &Input) -> Vector3<f64> {
        self.write_features(x);
        self.posterior.predict(&self.phi) * self.settings.norm_out
    }

    /// Trains one pattern: raw input `x`, joint move `target` (degrees), both finite.
    pub fn train(&mut self, x: &Input, target: &Vector3<f64>) {
        self.write_features(x);
        let ticket = self
            .posterior
            .add(&self.phi, &(target / self.settings.norm_out));
        if self.keeps_recent {
            while self
                .recent
                .front()
                .is_some_and(|p| p.trial + SEED_TRIALS <= self.trial)
            {
                self.recent.pop_front();
            }
            self.recent.push_back(Learned {
                trial: self.trial,
                input: *x,
                target: *target,
                ticket,
            });
        }
    }

    /// Takes out every kept pattern of the trials from `trial` on; where rounding refuses
    /// one, keeps them all.
    fn untrain_since(&mut self, trial: usize) {
        let before = self.posterior.clone();
        while let Some(p) = self.recent.back().filter(|p| p.trial >= trial).copied() {
            self.recent.pop_back();
            self.write_features(&p.input);
            let target = p.target / self.settings.norm_out;
            if !self.posterior.remove(&self.phi, &target, p.ticket) {
                self.posterior = before;
                return;
            }
        }
    }
}

impl Learner for Issgp {
    fn name(&self) -> &str {
        Method::Issgp.name()
    }

    fn propose(&mut self, query: &Query) -> Vector3<f64> {
        self.predict(&query.five_inputs())
    }

    /// Trains every pose pair of the trial.
    fn learn(&mut self, path: &[Observation]) -> Result<(), LearnError> {
        for (from, to) in self.settings.patterns.pairs(path) {
            let pattern = adjusted_pattern(from, to);
            self.train(&pattern.input, &pattern.target);
        }
        Ok(())
    }

    fn stats(&self) -> LearnerStats {
        LearnerStats {
            nodes: self.features.len(),
            ..LearnerStats::default()
        }
    }

    fn start_trial(&mut self, trial: usize) {
        self.trial = trial;
    }
}

impl SingleModel for Issgp {
    /// Restarts the posterior from its mean (see the module's notes).
    fn forget_before(&mut self, _changed_at: usize) {
        self.posterior.restart_from_mean();
        self.recent.clear();
    }

    fn keep_recent_trials(&mut self) {
        self.keeps_recent = true;
    }

    /// Takes the patterns of the trials since `changed_at` out of the posterior: learned
    /// in the changed robot's readings, they would stay in the model the correction
    /// carries those readings back to.
    fn unlearn_since(&mut self, changed_at: usize) {
        self.untrain_since(changed_at);
    }
}
