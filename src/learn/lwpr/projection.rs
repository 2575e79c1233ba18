//! A receptive field's local model: incremental partial least squares (PLS) on the
//! field's weighted, mean-free data, one univariate regression per projection direction.
//!
//! Projection r regresses what the projections before it left of the output on
//! s_r = u_r·x_r, where x_r is what they left of the input and u_r the (normalised)
//! weighted correlation of x_r with that output residual; p_r regresses x_r on s_r so the
//! next projection sees only what is left. Every sum is discounted by the projection's own
//! forgetting factor λ. A field starts with two projections (so that their errors can be
//! compared), or with as many as the neighbour it is made next to, and adds one, up to one
//! per input, while the last one still pays off.

use nalgebra::SVector;

/// Inputs of the model (and the most projections a field can have).
pub(super) const INPUTS: usize = 5;
/// A vector over the inputs.
pub(super) type Input = SVector<f64, INPUTS>;

/// Projections a field made away from any trusted neighbour starts with.
pub(super) const FIRST_PROJECTIONS: usize = 2;
/// The starting value of a projection's Σ w s², keeping its first regression finite.
const INIT_S2: f64 = 1e-10;
/// The starting value of a projection's weight and data counts.
const INIT_COUNT: f64 = 1e-10;
/// A projection joins the answer once it has seen this many patterns per input.
const MATURE_PER_INPUT: f64 = 2.0;
/// Directions are renormalised only when the correlation is at least this long.
const MIN_DIRECTION_NORM: f64 = 1e-12;

/// The sufficient statistics of one projection.
#[derive(Debug, Clone, Copy)]
pub(super) struct Projection {
    /// Σ w·x_r·(output residual): the direction before normalising.
    sxy: Input,
    /// The unit projection direction u_r.
    u: Input,
    /// Σ w·s²: the weighted variance of the projected input.
    pub(super) ss2: f64,
    /// Σ w·s·(output residual).
    ssy: f64,
    /// Σ w·s·x_r.
    ssx: Input,
    /// The regression of the output residual on s.
    beta: f64,
    /// The regression of the input residual on s.
    p: Input,
    /// Forgetting factor λ of this projection's sums.
    pub(super) lambda: f64,
    /// Patterns seen, discounted by λ.
    pub(super) n_data: f64,
    /// Activations summed, discounted by λ.
    pub(super) sum_w: f64,
    /// Σ w·(leave-one-out error after this projection)².
    pub(super) sum_e_cv2: f64,
    /// Traces of the metric's gradient: Σ w·s·e_cv/(1 − h) and Σ w²·s²·e_cv²/(1 − h).
    pub(super) trace_h: f64,
    pub(super) trace_r: f64,
    /// The projected input of the last pattern, with the updated model.
    pub(super) s: f64,
}

impl Projection {
    /// The k-th projection of a fresh model, along input k, forgetting by `lambda`.
    fn along(k: usize, lambda: f64) -> Projection {
        Projection {
            sxy: Input::zeros(),
            u: Input::ith(k, 1.0),
            ss2: INIT_S2,
            ssy: 0.0,
            ssx: Input::zeros(),
            beta: 0.0,
            p: Input::ith(k, 1.0),
            lambda,
            n_data: INIT_COUNT,
            sum_w: INIT_COUNT,
            sum_e_cv2: 0.0,
            trace_h: 0.0,
            trace_r: 0.0,
            s: 0.0,
        }
    }
}

/// The errors of a training pattern.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct PlsErrors {
    /// The leave-one-out error: the miss of the model before it saw the pattern, up to
    /// the newest projection that answers.
    pub(super) cv: f64,
    /// The miss of the model after it saw the pattern.
    pub(super) fit: f64,
}

/// A field's incremental PLS model over mean-free inputs and outputs.
#[derive(Debug, Clone)]
pub(super) struct Pls {
    projections: [Projection; INPUTS],
    /// Projections in use (2 to 5).
    used: usize,
    /// Σ w·(error after training)², discounted.
    pub(super) sum_e2: f64,
}

impl Pls {
    /// A fresh model with its first `used` projections (2 to 5) along the first inputs.
    pub(super) fn new(used: usize, lambda: f64) -> Pls {
        Pls {
            projections: std::array::from_fn(|k| Projection::along(k, lambda)),
            used,
            sum_e2: 0.0,
        }
    }

    /// The projections in use.
    pub(super) fn projections(&self) -> &[Projection] {
        &self.projections[..self.used]
    }

    /// The projections in use, to update their traces.
    pub(super) fn projections_mut(&mut self) -> &mut [Projection] {
        &mut self.projections[..self.used]
    }

    /// The answer (mean-free) at mean-free input `x`. The newest projection joins once it
    /// has seen enough data.
    pub(super) fn predict(&self, mut x: Input) -> f64 {
        let mut y = 0.0;
        for (r, proj) in self.projections().iter().enumerate() {
            if self.is_immature(r) {
                break;
            }
            let s = proj.u.dot(&x);
            y += proj.beta * s;
            x -= proj.p * s;
        }
        y
    }

    /// The newest projection that answers: the last, or the one before it while the last
    /// is immature.
    pub(super) fn newest_mature(&self) -> &Projection {
        &self.projections[self.newest_mature_index()]
    }

    /// The index of [`newest_mature`](Self::newest_mature).
    fn newest_mature_index(&self) -> usize {
        let last = self.used - 1;
        if self.is_immature(last) {
            last - 1
        } else {
            last
        }
    }

    /// True for the newest projection while it has seen too little data to answer.
    fn is_immature(&self, r: usize) -> bool {
        r + 1 == self.used && self.projections[r].n_data <= MATURE_PER_INPUT * INPUTS as f64
    }

    /// Trains the mean-free pattern (`x`, `y`) with activation `w`; returns its errors.
    pub(super) fn train(&mut self, x: Input, y: f64, w: f64) -> PlsErrors {
        let used = self.used;
        let mut residuals = [Input::zeros(); INPUTS];
        let mut targets = [0.0; INPUTS];
        let mut projected = [0.0; INPUTS];
        let mut cv = [0.0; INPUTS];
        let (mut x_r, mut y_r) = (x, y);
        for r in 0..used {
            let proj = &self.projections[r];
            let s = proj.u.dot(&x_r);
            (residuals[r], targets[r], projected[r]) = (x_r, y_r, s);
            x_r -= proj.p * s;
            y_r -= proj.beta * s;
            cv[r] = y_r;
        }
        for r in 0..used {
            let proj = &mut self.projections[r];
            let (x_r, y_r, s) = (residuals[r], targets[r], projected[r]);
            // The direction forgets more slowly than the regressions on it.
            let slow = 0.9 + 0.1 * proj.lambda;
            proj.sxy = proj.sxy * slow + x_r * (w * y_r);
            let norm = proj.sxy.norm();
            if norm > MIN_DIRECTION_NORM {
                proj.u = proj.sxy / norm;
            }
            proj.ss2 = proj.lambda * proj.ss2 + w * s * s;
            proj.ssy = proj.lambda * proj.ssy + w * s * y_r;
            proj.ssx = proj.ssx * proj.lambda + x_r * (w * s);
            proj.beta = proj.ssy / proj.ss2;
            proj.p = proj.ssx / proj.ss2;
        }
        let fit = y - self.project_and_predict(x);
        let first = &self.projections[0];
        if first.n_data * (1.0 - first.lambda) > 0.1 {
            for (proj, e) in self.projections[..used].iter_mut().zip(cv) {
                proj.sum_e_cv2 = proj.lambda * proj.sum_e_cv2 + w * e * e;
            }
            self.sum_e2 = self.projections[used - 1].lambda * self.sum_e2 + w * fit * fit;
        }
        PlsErrors {
            cv: cv[self.newest_mature_index()],
            fit,
        }
    }

    /// Like [`predict`](Self::predict), and keeps each projection's s for the metric.
    fn project_and_predict(&mut self, mut x: Input) -> f64 {
        let mut y = 0.0;
        for r in 0..self.used {
            let immature = self.is_immature(r);
            let proj = &mut self.projections[r];
            let s = proj.u.dot(&x);
            x -= proj.p * s;
            proj.s = if immature { 0.0 } else { s };
            y += proj.beta * proj.s;
        }
        y
    }

    /// Adds a projection when the newest one cut the mean leave-one-out error to below
    /// `add_threshold` of the one before and has seen nearly all of the field's data; the
    /// new one forgets by `lambda`.
    pub(super) fn grow(&mut self, add_threshold: f64, lambda: f64) {
        if self.used == INPUTS {
            return;
        }
        let mse = |p: &Projection| p.sum_e_cv2 / p.sum_w + 1e-10;
        let (last, before) = (
            &self.projections[self.used - 1],
            &self.projections[self.used - 2],
        );
        if mse(last) / mse(before) < add_threshold
            && last.n_data / self.projections[0].n_data > 0.99
            && last.n_data * (1.0 - last.lambda) > 0.5
        {
            self.projections[self.used] = Projection::along(self.used, lambda);
            self.used += 1;
        }
    }

    /// Counts a pattern of activation `w` and anneals each λ towards `final_lambda` by
    /// `tau`.
    pub(super) fn age(&mut self, w: f64, tau: f64, final_lambda: f64) {
        for proj in self.projections_mut() {
            proj.sum_w = proj.lambda * proj.sum_w + w;
            proj.n_data = proj.lambda * proj.n_data + 1.0;
            proj.lambda = tau * proj.lambda + (1.0 - tau) * final_lambda;
        }
    }

    /// Sets every λ back to `lambda`: faster forgetting after a change.
    pub(super) fn reset_lambda(&mut self, lambda: f64) {
        for proj in self.projections_mut() {
            proj.lambda = lambda;
        }
    }
}
