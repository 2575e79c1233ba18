//! A receptive field's distance metric D = MᵀM (M upper triangular, or diagonal) and its
//! adaptation: one step of gradient descent per pattern on the field's penalised
//! leave-one-out cost J = (1/W)·Σ w·e_cv² + γ·Σ D²ᵢⱼ, with the cost's dependence on the
//! current pattern's weight carried by the traces H and r of each projection (the
//! incremental approximation of the LWPR paper). Each element of M has its own learning
//! rate α; with `meta` the rates adapt by a second-order step on log α.
//!
//! With the Gaussian kernel w = exp(−q/2), q = ‖M·dx‖², the derivative of q by Mₙₘ is
//! 2·(M·dx)ₙ·dxₘ and that of Σ D²ᵢⱼ is 4·(M·D)ₙₘ.

use super::projection::{Input, Pls, PlsErrors, Projection, INPUTS};
use super::LwprSettings;
use nalgebra::SMatrix;

/// A matrix over the inputs.
type Square = SMatrix<f64, INPUTS, INPUTS>;

/// Bounds of the logarithm of a learning rate (with `meta`).
const MAX_LOG_RATE: f64 = 10.0;
/// The largest change of a log learning rate per pattern (with `meta`).
const MAX_LOG_RATE_STEP: f64 = 0.1;
/// A step that would shrink an element of M by more than this fraction of M's largest
/// element is refused and that element's learning rate halved (as in the reference
/// library, a step that grows it is never refused).
const MAX_RELATIVE_STEP: f64 = 0.1;

/// The distance metric of a field and what adapts it.
#[derive(Debug, Clone)]
pub(super) struct DistanceMetric {
    /// The upper triangular factor of D.
    m: Square,
    /// D = MᵀM.
    d: Square,
    /// Learning rate of each element of M.
    alpha: Square,
    /// ln α (with `meta`).
    log_alpha: Square,
    /// The meta-learning memory of past steps (with `meta`).
    memory: Square,
}

/// What one gradient step needs from the field besides the metric.
#[derive(Debug, Clone, Copy)]
pub(super) struct MetricStep {
    /// The input less the field's centre (normalised units).
    pub(super) dx: Input,
    /// The pattern's activation of the field.
    pub(super) w: f64,
    /// The pattern's errors in the field's local model.
    pub(super) errors: PlsErrors,
}

/// ln α of each rate (kept finite for a zero rate).
fn log_rates(alpha: &Square) -> Square {
    alpha.map(|a| (a + 1e-10).ln())
}

impl DistanceMetric {
    /// The metric `init_D`·I with every rate `init_alpha`.
    pub(super) fn new(settings: &LwprSettings) -> DistanceMetric {
        let alpha = Square::from_element(settings.init_alpha);
        DistanceMetric {
            m: Square::from_diagonal_element(settings.init_d.sqrt()),
            d: Square::from_diagonal_element(settings.init_d),
            alpha,
            log_alpha: log_rates(&alpha),
            memory: Square::zeros(),
        }
    }

    /// A new field's copy of this metric: M, D and the rates, with the meta-learning
    /// memory fresh and the log rates taken from the rates.
    pub(super) fn inherited(&self) -> DistanceMetric {
        DistanceMetric {
            log_alpha: log_rates(&self.alpha),
            memory: Square::zeros(),
            ..self.clone()
        }
    }

    /// The squared distance dxᵀ·D·dx.
    pub(super) fn squared_distance(&self, dx: &Input) -> f64 {
        (self.m * dx).norm_squared()
    }

    /// The trace of D: larger for a narrower field.
    pub(super) fn trace(&self) -> f64 {
        self.d.trace()
    }

    /// One gradient step on the field's cost after it trained a pattern (`step`); also
    /// updates the traces of `pls`' projections.
    pub(super) fn adapt(&mut self, step: MetricStep, pls: &mut Pls, settings: &LwprSettings) {
        let MetricStep { dx, w, errors } = step;
        let projections = pls.projections();
        let first = &projections[0];
        // A projection feeds the gradient once its data count, discounted by the first
        // projection's forgetting, is large enough.
        let forgetting = 1.0 - first.lambda;
        let supported = |p: &Projection| p.n_data * forgetting > 0.1;
        if !supported(first) {
            return;
        }
        let (mut h_per_w, mut pse_h, mut ps2_r, mut ps_h, mut s_pse) = (0.0, 0.0, 0.0, 0.0, 0.0);
        for p in projections.iter().filter(|p| supported(p)) {
            let ps = p.s / p.ss2;
            h_per_w += p.s * ps;
            pse_h += ps * errors.fit * p.trace_h;
            ps2_r += ps * ps * p.trace_r;
            ps_h += ps * p.trace_h;
            s_pse += p.s * ps * errors.fit;
        }
        let h = w * h_per_w;
        if !h.is_finite() {
            return;
        }
        let big_w = first.sum_w * first.lambda + w;
        let sum_cv2 = pls.newest_mature().sum_e_cv2;
        let transient = (pls.sum_e2 / (sum_cv2 + 1e-10)).powi(4).min(1.0);
        let e_cv2 = errors.cv * errors.cv;
        let dj1_dw = -sum_cv2 / big_w.powi(2) + (e_cv2 - 2.0 * pse_h - 2.0 * ps2_r) / big_w;
        let d2j1_dw2 = -e_cv2 / big_w.powi(2) - 2.0 / big_w * (-pse_h / big_w - 2.0 * s_pse * ps_h)
            + 2.0 / big_w * errors.fit * errors.fit * h_per_w
            - (e_cv2 - 2.0 * pse_h) / big_w.powi(2)
            + sum_cv2 / big_w.powi(3);
        let penalty = settings.penalty / INPUTS as f64;
        let md = self.m * dx;
        let m_times_d = self.m * self.d;
        let mut gradient = Square::zeros();
        let mut curvature = Square::zeros();
        for n in 0..INPUTS {
            let columns = if settings.diag_only {
                n..n + 1
            } else {
                n..INPUTS
            };
            for m in columns {
                let dq = 2.0 * md[n] * dx[m];
                let dw = -0.5 * w * dq;
                gradient[(n, m)] = dw * dj1_dw + w / big_w * 4.0 * penalty * m_times_d[(n, m)];
                if settings.meta {
                    let d2w = 0.25 * w * dq * dq - w * dx[m] * dx[m];
                    let row = self.m.row(n).norm_squared();
                    let d2j2 = 4.0 * penalty * (self.d[(m, m)] + row + self.m[(n, m)].powi(2));
                    curvature[(n, m)] = d2w * dj1_dw + dw * dw * d2j1_dw2 + w / big_w * d2j2;
                }
            }
        }
        if !gradient
            .iter()
            .chain(curvature.iter())
            .all(|g| g.is_finite())
        {
            return;
        }
        if settings.meta {
            self.adapt_rates(&gradient, &curvature, transient, settings.meta_rate);
        }
        self.descend(&gradient, transient);
        let scale = w / (1.0 - h) * transient;
        for p in pls.projections_mut() {
            if supported(p) {
                p.trace_h = p.lambda * p.trace_h + scale * p.s * errors.cv;
                p.trace_r = p.lambda * p.trace_r + scale * w * e_cv2 * p.s * p.s;
            }
        }
    }

    /// The meta step: log rates move against the correlation of this gradient with the
    /// memory of past steps.
    fn adapt_rates(&mut self, gradient: &Square, curvature: &Square, transient: f64, rate: f64) {
        for k in 0..INPUTS * INPUTS {
            let step = (rate * transient * gradient[k] * self.memory[k])
                .clamp(-MAX_LOG_RATE_STEP, MAX_LOG_RATE_STEP);
            self.log_alpha[k] = (self.log_alpha[k] - step).clamp(-MAX_LOG_RATE, MAX_LOG_RATE);
            self.alpha[k] = self.log_alpha[k].exp();
            let keep = (1.0 - self.alpha[k] * curvature[k] * transient).max(0.0);
            self.memory[k] = self.memory[k] * keep - self.alpha[k] * gradient[k] * transient;
        }
    }

    /// The gradient step on M, refusing (and slowing) a step that shrinks an element by
    /// too much for M. The halved rate lasts until the next meta step sets it from its log.
    fn descend(&mut self, gradient: &Square, transient: f64) {
        let limit = MAX_RELATIVE_STEP * self.m.amax();
        for k in 0..INPUTS * INPUTS {
            let step = self.alpha[k] * gradient[k] * transient;
            if step > limit {
                self.alpha[k] /= 2.0;
            } else {
                self.m[k] -= step;
            }
        }
        self.d = self.m.transpose() * self.m;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A metric of `init_D` 4 (M = 2·I) with every rate 1.
    fn metric() -> DistanceMetric {
        DistanceMetric::new(&LwprSettings {
            init_d: 4.0,
            init_alpha: 1.0,
            ..LwprSettings::default()
        })
    }

    #[test]
    fn a_large_step_that_grows_m_is_taken_and_one_that_shrinks_it_is_refused() {
        let mut metric = metric();
        let mut gradient = Square::zeros();
        gradient[(0, 0)] = -1.0; // grows M₀₀ by 1, half of max M
        gradient[(1, 1)] = 1.0; // would shrink M₁₁ by 1
        metric.descend(&gradient, 1.0);
        assert_eq!(metric.m[(0, 0)], 3.0);
        assert_eq!(metric.alpha[(0, 0)], 1.0);
        assert_eq!(metric.m[(1, 1)], 2.0);
        assert_eq!(metric.alpha[(1, 1)], 0.5);
        assert_eq!(metric.d[(0, 0)], 9.0);
    }
}
