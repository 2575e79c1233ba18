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

    /// The squared distance dxᵀ·D·dx (summed in the reference library's order).
    pub(super) fn squared_distance(&self, dx: &Input) -> f64 {
        let mut q = 0.0;
        for j in 0..INPUTS {
            let mut column = 0.0;
            for i in 0..INPUTS {
                column += dx[i] * self.d[(i, j)];
            }
            q += dx[j] * column;
        }
        q
    }

    /// The trace of D: larger for a narrower field.
    pub(super) fn trace(&self) -> f64 {
        self.d.trace()
    }

    /// One gradient step on the field's cost after it trained a pattern (`step`); also
    /// updates the traces of `pls`' projections. The arithmetic follows the reference
    /// library's order, so that the two agree to rounding.
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
        let mut h = 0.0;
        for p in projections.iter().filter(|p| supported(p)) {
            h += p.s * p.s / p.ss2;
        }
        h *= w;
        if !h.is_finite() {
            return;
        }
        // The first projection's Σw already counts this pattern.
        let big_w = first.sum_w;
        let sum_cv2 = pls.newest_mature().sum_e_cv2;
        let mut transient = pls.sum_e2 / (sum_cv2 + 1e-10);
        transient *= transient;
        transient = (transient * transient).min(1.0);
        let e_cv2 = errors.cv * errors.cv;
        // ∂J₁/∂w, and Σ s·(s/Σws²)·e over the projections that feed it.
        let mut dj1_dw = -sum_cv2 / big_w + e_cv2;
        let mut s_pse = 0.0;
        for p in projections.iter().filter(|p| supported(p)) {
            let ps = p.s / p.ss2;
            let pse = errors.fit * ps;
            dj1_dw -= 2.0 * pse * p.trace_h + 2.0 * ps * ps * p.trace_r;
            s_pse += p.s * pse;
        }
        dj1_dw /= big_w;
        let d2j1_dw2 = settings.meta.then(|| {
            let mut d2 =
                2.0 * (errors.fit * errors.fit * h / w - e_cv2 / big_w) + sum_cv2 / (big_w * big_w);
            for p in projections.iter().filter(|p| supported(p)) {
                let ps = p.s / p.ss2;
                d2 += 4.0 * (errors.fit * ps / big_w + ps * s_pse) * p.trace_h;
            }
            d2 / big_w
        });
        let cost = CostSlopes {
            dx,
            w,
            w_share: w / big_w,
            dj1_dw,
            d2j1_dw2,
            penalty: settings.penalty / INPUTS as f64,
        };
        let (gradient, curvature) = self.slopes(&cost, settings.diag_only);
        if !gradient
            .iter()
            .chain(curvature.iter())
            .all(|g| g.is_finite())
        {
            return;
        }
        if settings.meta {
            self.adapt_rates(&gradient, &curvature, transient, settings);
        }
        self.descend(&gradient, transient, settings.diag_only);
        for p in pls.projections_mut() {
            if supported(p) {
                p.trace_h = p.lambda * p.trace_h + w / (1.0 - h) * p.s * errors.cv * transient;
                p.trace_r =
                    p.lambda * p.trace_r + w * w * e_cv2 / (1.0 - h) * p.s * p.s * transient;
            }
        }
    }

    /// The gradient of the field's cost by each element of M in use and, with `meta`, its
    /// second derivative (zero elsewhere).
    fn slopes(&self, cost: &CostSlopes, diag_only: bool) -> (Square, Square) {
        let CostSlopes { dx, w, .. } = *cost;
        let (dw_dq, d2w_dq2) = (-0.5 * w, 0.25 * w);
        let penalty = cost.penalty + cost.penalty;
        let mut gradient = Square::zeros();
        let mut curvature = Square::zeros();
        for (n, m) in elements(diag_only) {
            // ∂q/∂Mₙₘ, and the penalty's first and second derivatives.
            let (dq, dj2, d2j2) = if diag_only {
                let twice_m = 2.0 * self.m[(n, n)];
                let d2j2 = penalty * (2.0 * self.d[(n, n)] + twice_m * twice_m);
                (
                    dx[n] * dx[n] * twice_m,
                    penalty * self.d[(n, n)] * twice_m,
                    d2j2,
                )
            } else {
                let (mut m_dx, mut m_d, mut row) = (0.0, 0.0, 0.0);
                for i in n..INPUTS {
                    let m_ni = self.m[(n, i)];
                    m_dx += dx[i] * m_ni;
                    m_d += self.d[(i, m)] * m_ni;
                    row += if i == m {
                        2.0 * m_ni * m_ni
                    } else {
                        m_ni * m_ni
                    };
                }
                let d2j2 = 2.0 * penalty * (self.d[(m, m)] + row);
                (m_dx * (2.0 * dx[m]), 2.0 * penalty * m_d, d2j2)
            };
            let dw = dq * dw_dq;
            gradient[(n, m)] = cost.w_share * dj2 + dw * cost.dj1_dw;
            if let Some(d2j1_dw2) = cost.d2j1_dw2 {
                let d2w = d2w_dq2 * dq * dq + 2.0 * dw_dq * dx[m] * dx[m];
                curvature[(n, m)] = cost.w_share * d2j2 + d2w * cost.dj1_dw + dw * dw * d2j1_dw2;
            }
        }
        (gradient, curvature)
    }

    /// The meta step (incremental delta-bar-delta): log rates move against the
    /// correlation of this gradient with the memory of past steps.
    fn adapt_rates(
        &mut self,
        gradient: &Square,
        curvature: &Square,
        transient: f64,
        settings: &LwprSettings,
    ) {
        for k in elements(settings.diag_only) {
            let step = (settings.meta_rate * transient * gradient[k] * self.memory[k])
                .clamp(-MAX_LOG_RATE_STEP, MAX_LOG_RATE_STEP);
            self.log_alpha[k] = (self.log_alpha[k] - step).clamp(-MAX_LOG_RATE, MAX_LOG_RATE);
            self.alpha[k] = self.log_alpha[k].exp();
            let keep = (1.0 - self.alpha[k] * curvature[k] * transient).max(0.0);
            self.memory[k] = self.memory[k] * keep - self.alpha[k] * transient * gradient[k];
        }
    }

    /// The gradient step on M, refusing (and slowing) a step that shrinks an element by
    /// too much for M. The halved rate lasts until the next meta step sets it from its log.
    fn descend(&mut self, gradient: &Square, transient: f64, diag_only: bool) {
        let limit = MAX_RELATIVE_STEP * self.m.amax();
        for k in elements(diag_only) {
            let step = self.alpha[k] * transient * gradient[k];
            if step > limit {
                self.alpha[k] *= 0.5;
            } else {
                self.m[k] -= step;
            }
        }
        for j in 0..INPUTS {
            for i in j..INPUTS {
                let mut dot = 0.0;
                for k in 0..=j {
                    dot += self.m[(k, j)] * self.m[(k, i)];
                }
                (self.d[(i, j)], self.d[(j, i)]) = (dot, dot);
            }
        }
    }
}

/// What the gradient of a field's cost by M needs besides the metric.
#[derive(Debug, Clone, Copy)]
struct CostSlopes {
    /// The input less the field's centre.
    dx: Input,
    /// The pattern's activation of the field.
    w: f64,
    /// w over the field's discounted Σw.
    w_share: f64,
    /// ∂J₁/∂w of the cost's leave-one-out part.
    dj1_dw: f64,
    /// ∂²J₁/∂w², with `meta`.
    d2j1_dw2: Option<f64>,
    /// The smoothness penalty per input.
    penalty: f64,
}

/// The elements (row, column) of M that adapt: the diagonal, or the upper triangle.
fn elements(diag_only: bool) -> impl Iterator<Item = (usize, usize)> {
    (0..INPUTS).flat_map(move |n| {
        let last = if diag_only { n + 1 } else { INPUTS };
        (n..last).map(move |m| (n, m))
    })
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
        metric.descend(&gradient, 1.0, true);
        assert_eq!(metric.m[(0, 0)], 3.0);
        assert_eq!(metric.alpha[(0, 0)], 1.0);
        assert_eq!(metric.m[(1, 1)], 2.0);
        assert_eq!(metric.alpha[(1, 1)], 0.5);
        assert_eq!(metric.d[(0, 0)], 9.0);
    }
}
