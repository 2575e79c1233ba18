//! The `lwpr` learner: three output models over the normalised adjusted 5-input patterns,
//! with forgetting, set back to its start when a detected change calls for it.

use super::output_model::OutputModel;
use super::projection::Input;
use super::LwprSettings;
use crate::learn::change::SingleModel;
use crate::learn::{
    adjusted_pattern, LearnError, Learner, LearnerStats, Method, Observation, Query,
};
use nalgebra::Vector3;

/// Locally weighted projection regression of Δθ = N(c, θ2, θ3).
#[derive(Debug, Clone)]
pub struct Lwpr {
    settings: LwprSettings,
    /// The inputs' lower boundaries and ranges: x ↦ (x − low) / span.
    low: Input,
    span: Input,
    /// One model per joint move Δθ1, Δθ2, Δθ3.
    outputs: [OutputModel; 3],
}

impl Lwpr {
    /// A learner for inputs (θ2, θ3, cx, cy, cz) within `bounds`, each (low, high) with
    /// low < high.
    pub fn new(settings: LwprSettings, bounds: [(f64, f64); 5]) -> Lwpr {
        Lwpr {
            settings,
            low: Input::from_fn(|i, _| bounds[i].0),
            span: Input::from_fn(|i, _| bounds[i].1 - bounds[i].0),
            outputs: Default::default(),
        }
    }

    /// Receptive fields of each output.
    pub fn fields(&self) -> [usize; 3] {
        std::array::from_fn(|i| self.outputs[i].len())
    }

    /// The input in normalised units (0 to 1 inside the boundaries).
    fn normalise(&self, x: &Input) -> Input {
        (x - self.low).component_div(&self.span)
    }

    /// The answer (degrees) at raw input `x`, `None` for outputs no field covers.
    pub(super) fn answer(&self, x: &Input) -> [Option<f64>; 3] {
        let x = self.normalise(x);
        std::array::from_fn(|i| {
            self.outputs[i]
                .predict(&x)
                .map(|y| y * self.settings.norm_out)
        })
    }

    /// The reference library's answer (degrees) at raw input `x`: the trusted fields'
    /// alone, `None` for outputs no trusted field covers.
    #[cfg(test)]
    pub(super) fn answer_trusted(&self, x: &Input) -> [Option<f64>; 3] {
        let x = self.normalise(x);
        std::array::from_fn(|i| {
            self.outputs[i]
                .predict_trusted(&x)
                .map(|y| y * self.settings.norm_out)
        })
    }

    /// Trains one pattern: raw input `x`, joint move `target` (degrees), both finite.
    pub fn train(&mut self, x: &Input, target: &Vector3<f64>) {
        let x = self.normalise(x);
        for (model, t) in self.outputs.iter_mut().zip(target.iter()) {
            model.train(&x, t / self.settings.norm_out, &self.settings);
        }
    }
}

impl Learner for Lwpr {
    fn name(&self) -> &str {
        Method::Lwpr.name()
    }

    /// The answer, zero for outputs no field covers (not finite for inputs far outside the
    /// boundaries: the [`WatchedLearner`](crate::learn::change::WatchedLearner) it runs in
    /// answers zero then).
    fn propose(&mut self, query: &Query) -> Vector3<f64> {
        let answer = self.answer(&query.five_inputs()).map(|a| a.unwrap_or(0.0));
        Vector3::from(answer)
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
            nodes: self.fields().iter().sum(),
            ..LearnerStats::default()
        }
    }
}

impl SingleModel for Lwpr {
    /// Sets every field's forgetting factor back to `init_lambda` (see the module's notes
    /// for why).
    fn forget_before(&mut self, _changed_at: usize) {
        for model in &mut self.outputs {
            model.reset_lambda(self.settings.init_lambda);
        }
    }
}
