//! A receptive field: a Gaussian kernel around a centre with its own distance metric, and
//! the local linear model (weighted means and incremental PLS) it weighs its data by.

use super::metric::{DistanceMetric, MetricStep};
use super::projection::{Input, Pls, FIRST_PROJECTIONS, INPUTS};
use super::LwprSettings;

/// Patterns below this activation leave a field untouched, and answers ignore fields below
/// it.
pub(super) const MIN_ACTIVATION: f64 = 0.001;
/// A field answers once it has seen this many patterns per input.
const TRUSTED_PER_INPUT: f64 = 2.0;

/// One receptive field of one output.
#[derive(Debug, Clone)]
pub(super) struct ReceptiveField {
    centre: Input,
    metric: DistanceMetric,
    /// Weighted mean of the inputs.
    mean_x: Input,
    /// Weighted mean of the output (the model's offset).
    beta0: f64,
    pls: Pls,
    /// True once the field has seen enough data to answer.
    trusted: bool,
}

impl ReceptiveField {
    /// A field centred on `x` answering `y`. Made next to `template` (a trusted
    /// neighbour) it starts with that field's metric and number of projections, as the
    /// reference library does; otherwise with the initial metric and two projections.
    pub(super) fn new(
        x: Input,
        y: f64,
        template: Option<&ReceptiveField>,
        settings: &LwprSettings,
    ) -> ReceptiveField {
        ReceptiveField {
            centre: x,
            metric: template
                .map_or_else(|| DistanceMetric::new(settings), |t| t.metric.inherited()),
            // As in the reference library: the first pattern the field trains sets its
            // means (these carry a weight of 1e-10), and a field made next to a neighbour
            // starts from the neighbour's mean output.
            mean_x: Input::zeros(),
            beta0: template.map_or(y, |t| t.beta0),
            pls: Pls::new(
                template.map_or(FIRST_PROJECTIONS, |t| t.pls.projections().len()),
                settings.init_lambda,
            ),
            trusted: false,
        }
    }

    /// The kernel's activation at `x`, in (0, 1].
    pub(super) fn activation(&self, x: &Input) -> f64 {
        (-0.5 * self.metric.squared_distance(&(x - self.centre))).exp()
    }

    /// True once the field has seen enough data to answer.
    pub(super) fn is_trusted(&self) -> bool {
        self.trusted
    }

    /// The trace of the distance metric (larger: narrower).
    pub(super) fn narrowness(&self) -> f64 {
        self.metric.trace()
    }

    /// The local model's answer at `x`.
    pub(super) fn predict(&self, x: &Input) -> f64 {
        self.pls.predict(self.beta0, x - self.mean_x)
    }

    /// Trains the pattern (`x`, `y`) that activates this field by `w`: means, local model,
    /// distance metric, projections, then the forgetting factors. The field is trusted
    /// from the pattern after the one that took its count past two per input.
    pub(super) fn train(&mut self, x: &Input, y: f64, w: f64, settings: &LwprSettings) {
        let (discounted, n_data) = {
            let first = &self.pls.projections()[0];
            (first.sum_w * first.lambda, first.n_data)
        };
        self.trusted |= n_data > TRUSTED_PER_INPUT * INPUTS as f64;
        let inverse = 1.0 / (discounted + w);
        self.mean_x = (self.mean_x * discounted + x * w) * inverse;
        self.beta0 = (discounted * self.beta0 + w * y) * inverse;
        let errors = self.pls.train(x - self.mean_x, y - self.beta0, w);
        let step = MetricStep {
            dx: x - self.centre,
            w,
            errors,
        };
        self.metric.adapt(step, &mut self.pls, settings);
        self.pls.grow(settings.add_threshold, settings.init_lambda);
        self.pls.age(settings.tau_lambda, settings.final_lambda);
    }

    /// Forgets faster again: every λ back to `init_lambda`.
    pub(super) fn reset_lambda(&mut self, init_lambda: f64) {
        self.pls.reset_lambda(init_lambda);
    }

    /// Projections in use.
    #[cfg(test)]
    pub(super) fn projections(&self) -> usize {
        self.pls.projections().len()
    }
}
