//! The `issgp` learner: random features of the scaled adjusted 5-input patterns and the
//! posterior of their weights, with forgetting and, under change detection, a watch that
//! restarts the posterior from its mean.

use super::features::{Features, Input};
use super::posterior::Posterior;
use super::IssgpSettings;
use crate::learn::baselines::net::InputScaling;
use crate::learn::change::TrialMiss;
use crate::learn::inputs::finite_or_still;
use crate::learn::{
    adjusted_pattern, centred, LearnError, Learner, LearnerStats, Method, ModelEvent, Observation,
    Query,
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
    watch: Option<TrialMiss>,
    /// Patterns trained so far (the watch dates a change by them).
    patterns: u64,
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
            watch: settings.change_detection.as_ref().map(TrialMiss::new),
            patterns: 0,
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

    /// Trains one pattern: raw input `x`, joint move `target` (degrees). A pattern with a
    /// value that is not finite is skipped.
    pub fn train(&mut self, x: &Input, target: &Vector3<f64>) {
        if !x.iter().chain(target.iter()).all(|v| v.is_finite()) {
            return;
        }
        self.write_features(x);
        self.posterior
            .add(&self.phi, &(target / self.settings.norm_out));
        self.patterns += 1;
    }

    /// Books every pattern of the trial with the watch: its miss by the model that drove
    /// the trial (nothing is trained yet).
    fn book_trial(&mut self, path: &[Observation]) {
        let Some(mut watch) = self.watch.take() else {
            return;
        };
        for (from, to) in self.settings.patterns.pairs(path) {
            let pattern = adjusted_pattern(from, to);
            let miss = (self.predict(&pattern.input) - pattern.target).norm();
            watch.book(Some(miss), pattern.target.norm());
        }
        watch.close_trial();
        self.watch = Some(watch);
    }
}

impl Learner for Issgp {
    fn name(&self) -> &str {
        Method::Issgp.name()
    }

    fn propose(&mut self, query: &Query) -> Vector3<f64> {
        finite_or_still(self.predict(&query.five_inputs()))
    }

    /// Trains every pose pair of the trial. Under change detection the watch is first
    /// given the trial's summed miss relative to its summed move, by the model as it was
    /// during the trial (one solve of the weights, not one per pattern).
    fn learn(&mut self, path: &[Observation]) -> Result<(), LearnError> {
        self.book_trial(path);
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

    /// Under change detection, a detected change restarts the posterior from its mean
    /// (see the module's notes).
    fn start_trial(&mut self, trial: usize) {
        let Some(watch) = &mut self.watch else {
            return;
        };
        if watch.start_trial(trial, self.patterns).is_some() {
            self.posterior.restart_from_mean();
        }
    }

    fn drain_events(&mut self, sink: &mut Vec<ModelEvent>) {
        if let Some(watch) = &mut self.watch {
            watch.drain_events(sink);
        }
    }
}
