//! The receptive fields of one output: training every field a pattern activates, making a
//! field where none is active enough (`w_gen`), dropping one of two that overlap too much
//! (`w_prune`), and answering by the activation-weighted mean of the fields' models.

use super::field::{ReceptiveField, MIN_ACTIVATION};
use super::projection::Input;
use super::LwprSettings;

/// The fields of one output.
#[derive(Debug, Clone, Default)]
pub(super) struct OutputModel {
    fields: Vec<ReceptiveField>,
}

/// The two most activated fields of a pattern, as (index, activation).
#[derive(Debug, Clone, Copy)]
struct TopTwo {
    first: Option<(usize, f64)>,
    second: Option<(usize, f64)>,
}

impl TopTwo {
    fn offer(&mut self, index: usize, w: f64) {
        if self.first.is_none_or(|(_, best)| w > best) {
            self.second = self.first;
            self.first = Some((index, w));
        } else if self.second.is_none_or(|(_, next)| w > next) {
            self.second = Some((index, w));
        }
    }
}

impl OutputModel {
    /// Receptive fields in use.
    pub(super) fn len(&self) -> usize {
        self.fields.len()
    }

    /// The fields (for tests).
    #[cfg(test)]
    pub(super) fn fields(&self) -> &[ReceptiveField] {
        &self.fields
    }

    /// Trains the pattern (`x`, `y`).
    pub(super) fn train(&mut self, x: &Input, y: f64, settings: &LwprSettings) {
        let mut top = TopTwo {
            first: None,
            second: None,
        };
        for (index, field) in self.fields.iter_mut().enumerate() {
            let w = field.activation(x);
            top.offer(index, w);
            if w > MIN_ACTIVATION {
                field.train(x, y, w, settings);
            }
        }
        let best = top.first.filter(|&(_, w)| w > settings.w_gen);
        if best.is_none() {
            // A neighbour's adapted metric is a better start than the initial one.
            let template = top
                .first
                .filter(|&(i, w)| w > 0.1 * settings.w_gen && self.fields[i].is_trusted())
                .map(|(i, _)| &self.fields[i]);
            let field = ReceptiveField::new(*x, y, template, settings);
            self.fields.push(field);
        }
        if let (Some((a, _)), Some((b, w))) = (top.first, top.second) {
            if w > settings.w_prune {
                let narrower = if self.fields[a].narrowness() > self.fields[b].narrowness() {
                    a
                } else {
                    b
                };
                self.fields.swap_remove(narrower);
            }
        }
    }

    /// The answer at `x`: the activation-weighted mean of the trusted fields above the
    /// minimal activation, or of every such field while none is trusted; `None` when no
    /// field is active there. (The reference library answers only from trusted fields;
    /// answering from the others until then is what lets a run's first moves happen.)
    pub(super) fn predict(&self, x: &Input) -> Option<f64> {
        let (trusted, any) = self.blends(x);
        trusted.or(any).filter(|a| a.is_finite())
    }

    /// The answer at `x` of the trusted fields alone, as the reference library gives it.
    #[cfg(test)]
    pub(super) fn predict_trusted(&self, x: &Input) -> Option<f64> {
        self.blends(x).0
    }

    /// The activation-weighted means at `x` of the trusted fields and of all fields above
    /// the minimal activation, each `None` without such fields.
    fn blends(&self, x: &Input) -> (Option<f64>, Option<f64>) {
        let (mut trusted, mut trusted_w, mut any, mut any_w) = (0.0, 0.0, 0.0, 0.0);
        for field in &self.fields {
            let w = field.activation(x);
            if w <= MIN_ACTIVATION {
                continue;
            }
            let y = w * field.predict(x);
            if field.is_trusted() {
                (trusted, trusted_w) = (trusted + y, trusted_w + w);
            }
            (any, any_w) = (any + y, any_w + w);
        }
        let mean = |sum: f64, weight: f64| (weight > 0.0).then(|| sum / weight);
        (mean(trusted, trusted_w), mean(any, any_w))
    }

    /// Every field forgets faster again.
    pub(super) fn reset_lambda(&mut self, init_lambda: f64) {
        for field in &mut self.fields {
            field.reset_lambda(init_lambda);
        }
    }
}
