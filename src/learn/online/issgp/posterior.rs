//! Bayesian linear regression on the features, updated one pattern at a time.
//!
//! With the prior w ~ N(w₀, I) on each output's weights (the signal amplitude is in the
//! features) and noise σn² on the targets, the posterior mean after patterns (φₜ, yₜ) is
//! w = w₀ + A⁻¹ Σₜ φₜ(yₜ − w₀ᵀφₜ) with A = σn²·I + Σₜ φₜφₜᵀ, the same A for all three
//! outputs. A is kept as its Cholesky factor L and updated by one rank-one update per
//! pattern; w is solved from L (two triangular solves) only when an answer is asked for.
//!
//! Forgetting λ weighs A and the sums down by λ before each pattern. A and the sums share
//! one scalar factor that the weights do not depend on, so λ multiplies that scalar and
//! the pattern is added divided by its root: the factor is scaled for real (O(D²)) only
//! when the scalar would underflow.
//!
//! A learned pattern can be taken out again ([`Posterior::remove`]): a rank-one downdate of
//! the factor and its term taken off the sums, each by the weight the pattern has now. So
//! that the weight is known, every pattern is given the log of the shared scalar it was
//! added under, as it would be without folding (its ticket); the scalar's log at the last
//! fold says how far the factor was scaled since. Without forgetting every weight is 1.

use super::cholesky::{rank_one_downdate, rank_one_update};
use nalgebra::{DMatrix, DVector, Vector3};

/// Below this the shared scalar is folded into the factor and the sums.
const SMALLEST_SCALE: f64 = 1e-100;

/// The posterior of the three outputs' feature weights.
#[derive(Debug, Clone)]
pub(super) struct Posterior {
    noise: f64,
    forgetting: f64,
    /// L (lower triangular) with LLᵀ = A / `scale`.
    factor: DMatrix<f64>,
    /// Σₜ φₜ(yₜ − w₀ᵀφₜ)ᵀ / `scale`, one column per output.
    sums: DMatrix<f64>,
    scale: f64,
    /// ln of the shared scalar as it would be without folding, and its value at the last
    /// fold: `scale` is exp of their difference.
    log_scale: f64,
    log_folded: f64,
    /// w₀: the prior mean, one column per output.
    prior_mean: DMatrix<f64>,
    /// w, valid unless `stale`.
    weights: DMatrix<f64>,
    stale: bool,
    /// The pattern's scaled features, used up by the update.
    scratch: DVector<f64>,
}

impl Posterior {
    /// The prior over `features` weights per output: mean 0.
    pub(super) fn new(features: usize, noise: f64, forgetting: f64) -> Posterior {
        Posterior {
            noise,
            forgetting,
            factor: DMatrix::from_diagonal_element(features, features, noise),
            sums: DMatrix::zeros(features, 3),
            scale: 1.0,
            log_scale: 0.0,
            log_folded: 0.0,
            prior_mean: DMatrix::zeros(features, 3),
            weights: DMatrix::zeros(features, 3),
            stale: false,
            scratch: DVector::zeros(features),
        }
    }

    /// Learns the pattern with features `phi` and target `y`; returns its ticket, which
    /// [`Posterior::remove`] takes to take it out again.
    pub(super) fn add(&mut self, phi: &DVector<f64>, y: &Vector3<f64>) -> f64 {
        self.scale *= self.forgetting;
        self.log_scale += self.forgetting.ln();
        if self.scale < SMALLEST_SCALE {
            self.factor *= self.scale.sqrt();
            self.sums *= self.scale;
            self.scale = 1.0;
            self.log_folded = self.log_scale;
        }
        let residual = y - dot_columns(&self.prior_mean, phi);
        self.scratch.copy_from(phi);
        self.scratch /= self.scale.sqrt();
        rank_one_update(&mut self.factor, &mut self.scratch);
        for (i, r) in residual.iter().enumerate() {
            self.sums.column_mut(i).axpy(r / self.scale, phi, 1.0);
        }
        self.stale = true;
        self.log_scale
    }

    /// Takes out the pattern with features `phi` and target `y` that [`Posterior::add`]
    /// learned and gave `ticket`: its term leaves A and the sums (what forgetting weighed
    /// down at its coming stays weighed down). False, with the posterior left
    /// part-way, where rounding leaves the factor without it not positive definite: the
    /// caller must then restore a copy.
    pub(super) fn remove(&mut self, phi: &DVector<f64>, y: &Vector3<f64>, ticket: f64) -> bool {
        // The pattern's weight in the factor's and the sums' frame.
        let weight = (self.log_folded - ticket).exp();
        let residual = y - dot_columns(&self.prior_mean, phi);
        self.scratch.copy_from(phi);
        self.scratch *= weight.sqrt();
        self.stale = true;
        if !rank_one_downdate(&mut self.factor, &mut self.scratch) {
            return false;
        }
        for (i, r) in residual.iter().enumerate() {
            self.sums.column_mut(i).axpy(-r * weight, phi, 1.0);
        }
        true
    }

    /// The posterior mean of the weights (solved now if a pattern came since).
    pub(super) fn weights(&mut self) -> &DMatrix<f64> {
        if self.stale {
            self.weights.copy_from(&self.sums);
            self.factor
                .solve_lower_triangular_unchecked_mut(&mut self.weights);
            self.factor
                .tr_solve_lower_triangular_unchecked_mut(&mut self.weights);
            self.weights += &self.prior_mean;
            self.stale = false;
        }
        &self.weights
    }

    /// The posterior mean of the three outputs at features `phi`.
    pub(super) fn predict(&mut self, phi: &DVector<f64>) -> Vector3<f64> {
        dot_columns(self.weights(), phi)
    }

    /// Makes the current posterior mean the prior's mean and forgets every pattern's
    /// weight in A: what was learned is kept as a starting point, none of it as evidence.
    pub(super) fn restart_from_mean(&mut self) {
        self.weights();
        self.prior_mean.copy_from(&self.weights);
        self.factor.fill_with_identity();
        self.factor *= self.noise;
        self.sums.fill(0.0);
        self.scale = 1.0;
        (self.log_scale, self.log_folded) = (0.0, 0.0);
    }
}

/// Each of the three columns of `m` dotted with `v`.
fn dot_columns(m: &DMatrix<f64>, v: &DVector<f64>) -> Vector3<f64> {
    Vector3::from_fn(|i, _| m.column(i).dot(v))
}
