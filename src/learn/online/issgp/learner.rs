//! The `issgp` learner: random features of the scaled adjusted 5-input patterns and the
//! posterior of their weights, with forgetting, restarted from its mean when a detected
//! change calls for it.

use super::features::{Features, Input};
use super::posterior::Posterior;
use super::IssgpSettings;
use crate::learn::baselines::net::InputScaling;
use crate::learn::change::SingleModel;
use crate::learn::{
    adjusted_pattern, centred, LearnError, Learner, LearnerStats, Method, Observation, Query,
};
use nalgebra::{DVector, Vector3};
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;

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
        self.posterior
            .add(&self.phi, &(target / self.settings.norm_out));
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
}

impl SingleModel for Issgp {
    /// Restarts the posterior from its mean (see the module's notes).
    fn forget_before(&mut self, _changed_at: usize) {
        self.posterior.restart_from_mean();
    }
}
