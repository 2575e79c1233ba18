//! The `lwpr` learner: three output models over the normalised adjusted 5-input patterns,
//! with forgetting and, under change detection, a watch that resets it.

use super::output_model::OutputModel;
use super::projection::Input;
use super::LwprSettings;
use crate::learn::change::TrialMiss;
use crate::learn::inputs::finite_or_still;
use crate::learn::{
    adjusted_pattern, LearnError, Learner, LearnerStats, Method, ModelEvent, Observation, Query,
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
    watch: Option<TrialMiss>,
    /// Patterns trained so far (the watch dates a change by them).
    patterns: u64,
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
            watch: settings.change_detection.as_ref().map(TrialMiss::new),
            patterns: 0,
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

    /// How far the answer at raw input `x` misses `target` (degrees); `None` where some
    /// output has no field.
    fn miss(&self, x: &Input, target: &Vector3<f64>) -> Option<f64> {
        let answer = self.answer(x);
        let squares = answer
            .iter()
            .zip(target.iter())
            .map(|(a, t)| a.map(|a| (a - t).powi(2)));
        squares.sum::<Option<f64>>().map(f64::sqrt)
    }

    /// Trains one pattern: raw input `x`, joint move `target` (degrees). A pattern with a
    /// value that is not finite is skipped.
    pub fn train(&mut self, x: &Input, target: &Vector3<f64>) {
        if !x.iter().chain(target.iter()).all(|v| v.is_finite()) {
            return;
        }
        let x = self.normalise(x);
        for (model, t) in self.outputs.iter_mut().zip(target.iter()) {
            model.train(&x, t / self.settings.norm_out, &self.settings);
        }
        self.patterns += 1;
    }
}

impl Learner for Lwpr {
    fn name(&self) -> &str {
        Method::Lwpr.name()
    }

    fn propose(&mut self, query: &Query) -> Vector3<f64> {
        let answer = self.answer(&query.five_inputs()).map(|a| a.unwrap_or(0.0));
        finite_or_still(Vector3::from(answer))
    }

    /// Trains every pose pair of the trial. Under change detection the watch is given
    /// the trial's summed miss (before training) relative to its summed move: see the
    /// module's notes for why not each pattern's.
    fn learn(&mut self, path: &[Observation]) -> Result<(), LearnError> {
        for (from, to) in self.settings.patterns.pairs(path) {
            let pattern = adjusted_pattern(from, to);
            if self.watch.is_some() {
                let miss = self.miss(&pattern.input, &pattern.target);
                if let Some(watch) = &mut self.watch {
                    watch.book(miss, pattern.target.norm());
                }
            }
            self.train(&pattern.input, &pattern.target);
        }
        if let Some(watch) = &mut self.watch {
            watch.close_trial();
        }
        Ok(())
    }

    fn stats(&self) -> LearnerStats {
        LearnerStats {
            nodes: self.fields().iter().sum(),
            ..LearnerStats::default()
        }
    }

    /// Under change detection, a detected change sets every field's forgetting factor
    /// back to `init_lambda` (see the module's notes for why).
    fn start_trial(&mut self, trial: usize) {
        let Some(watch) = &mut self.watch else {
            return;
        };
        if watch.start_trial(trial, self.patterns).is_some() {
            for model in &mut self.outputs {
                model.reset_lambda(self.settings.init_lambda);
            }
        }
    }

    fn drain_events(&mut self, sink: &mut Vec<ModelEvent>) {
        if let Some(watch) = &mut self.watch {
            watch.drain_events(sink);
        }
    }
}
