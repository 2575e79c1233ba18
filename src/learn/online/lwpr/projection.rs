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
/// Directions are renormalised only when the correlation's squared length passes this.
const MIN_DIRECTION_NORM_SQUARED: f64 = 1e-24;

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

    /// The answer at mean-free input `x`: `offset` (the field's mean output) plus the
    /// projections' regressions. The newest projection joins once it has seen enough data.
    pub(super) fn predict(&self, offset: f64, mut x: Input) -> f64 {
        let mut y = offset;
        for (r, proj) in self.projections().iter().enumerate() {
            if self.is_immature(r) {
                break;
            }
            let s = dot(&proj.u, &x);
            y += s * proj.beta;
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

    /// Trains the mean-free pattern (`x`, `y`) with activation `w` and counts its weight;
    /// returns its errors. The arithmetic follows the reference library's order.
    pub(super) fn train(&mut self, x: Input, y: f64, w: f64) -> PlsErrors {
        let used = self.used;
        let mut residuals = [Input::zeros(); INPUTS];
        let mut targets = [0.0; INPUTS];
        let mut projected = [0.0; INPUTS];
        let mut cv = [0.0; INPUTS];
        let (mut x_r, mut explained) = (x, 0.0);
        for r in 0..used {
            let proj = &mut self.projections[r];
            let s = dot(&proj.u, &x_r);
            (residuals[r], projected[r]) = (x_r, s);
            targets[r] = if r == 0 { y } else { cv[r - 1] };
            x_r -= proj.p * s;
            explained = if r == 0 {
                proj.beta * s
            } else {
                proj.beta * s + explained
            };
            cv[r] = y - explained;
            proj.sum_w = proj.sum_w * proj.lambda + w;
        }
        for r in 0..used {
            let proj = &mut self.projections[r];
            let (x_r, y_r, s) = (residuals[r], targets[r], projected[r]);
            // The direction forgets more slowly than the regressions on it.
            let slow = 0.9 + 0.1 * proj.lambda;
            proj.sxy = proj.sxy * slow + x_r * (w * y_r);
            let norm2 = dot(&proj.sxy, &proj.sxy);
            if norm2 > MIN_DIRECTION_NORM_SQUARED {
                proj.u = proj.sxy * (1.0 / norm2.sqrt());
            }
            let ws = w * s;
            proj.ss2 = proj.lambda * proj.ss2 + s * ws;
            proj.ssy = proj.lambda * proj.ssy + y_r * ws;
            proj.ssx = proj.ssx * proj.lambda + x_r * ws;
            let inverse = 1.0 / proj.ss2;
            proj.beta = proj.ssy * inverse;
            proj.p = proj.ssx * inverse;
        }
        let fit = y - self.project_and_predict(x);
        let first = &self.projections[0];
        if first.n_data * (1.0 - first.lambda) > 0.1 {
            self.sum_e2 = self.sum_e2 * self.projections[used - 1].lambda + w * fit * fit;
            for (proj, e) in self.projections[..used].iter_mut().zip(cv) {
                proj.sum_e_cv2 = proj.sum_e_cv2 * proj.lambda + w * e * e;
            }
        }
        PlsErrors {
            cv: cv[self.newest_mature_index()],
            fit,
        }
    }

    /// Like [`predict`](Self::predict) without the offset, and keeps each projection's s
    /// (the newest one's too while it is immature) for the metric.
    fn project_and_predict(&mut self, mut x: Input) -> f64 {
        let mut y = 0.0;
        for r in 0..self.used {
            let immature = self.is_immature(r);
            let proj = &mut self.projections[r];
            proj.s = dot(&proj.u, &x);
            x -= proj.p * proj.s;
            if !immature {
                y += proj.beta * proj.s;
            }
        }
        y
    }

    /// Adds a projection when the newest one cut the mean leave-one-out error to below
    /// `add_threshold` of the one before and has seen nearly all of the field's data; the
    /// new one forgets by `lambda` and, as in the reference library, starts with no count.
    pub(super) fn grow(&mut self, add_threshold: f64, lambda: f64) {
        if self.used == INPUTS {
            return;
        }
        let mse = |p: &Projection| p.sum_e_cv2 / p.sum_w + 1e-10;
        let (last, before) = (
            &self.projections[self.used - 1],
            &self.projections[self.used - 2],
        );
        if mse(last) < add_threshold * mse(before)
            && last.n_data > 0.99 * self.projections[0].n_data
            && last.n_data * (1.0 - last.lambda) > 0.5
        {
            self.projections[self.used] = Projection {
                n_data: 0.0,
                ..Projection::along(self.used, lambda)
            };
            self.used += 1;
        }
    }

    /// Counts a pattern and anneals each λ towards `final_lambda` by `tau`.
    pub(super) fn age(&mut self, tau: f64, final_lambda: f64) {
        for proj in self.projections_mut() {
            proj.n_data = proj.n_data * proj.lambda + 1.0;
            proj.lambda = tau * proj.lambda + final_lambda * (1.0 - tau);
        }
    }

    /// Sets every λ back to `lambda`: faster forgetting after a change.
    pub(super) fn reset_lambda(&mut self, lambda: f64) {
        for proj in self.projections_mut() {
            proj.lambda = lambda;
        }
    }
}

/// The dot product summed in index order (as the reference library sums it).
pub(super) fn dot(a: &Input, b: &Input) -> f64 {
    a.iter().zip(b.iter()).fold(0.0, |sum, (a, b)| sum + b * a)
}
