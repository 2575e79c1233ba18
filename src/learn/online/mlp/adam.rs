//! Adam (Kingma and Ba 2015): gradient steps scaled by running estimates of each
//! parameter's gradient mean and mean square, with their start-up bias corrected.

/// Decay of the gradient's running mean.
const BETA_1: f64 = 0.9;
/// Decay of the gradient's running mean square.
const BETA_2: f64 = 0.999;
/// Keeps the step finite where the mean square is zero.
const EPSILON: f64 = 1e-8;

/// The optimiser's state for a parameter vector.
#[derive(Debug, Clone, PartialEq)]
pub(super) struct Adam {
    rate: f64,
    mean: Vec<f64>,
    square: Vec<f64>,
    /// β₁ᵗ and β₂ᵗ after t steps.
    beta_1_power: f64,
    beta_2_power: f64,
}

impl Adam {
    /// An optimiser with step size `rate` for `count` parameters.
    pub(super) fn new(rate: f64, count: usize) -> Adam {
        Adam {
            rate,
            mean: vec![0.0; count],
            square: vec![0.0; count],
            beta_1_power: 1.0,
            beta_2_power: 1.0,
        }
    }

    /// Becomes `other` (of as many parameters) without allocating.
    pub(super) fn copy_from(&mut self, other: &Adam) {
        self.rate = other.rate;
        self.mean.copy_from_slice(&other.mean);
        self.square.copy_from_slice(&other.square);
        self.beta_1_power = other.beta_1_power;
        self.beta_2_power = other.beta_2_power;
    }

    /// One step of `params` against `gradient`.
    pub(super) fn step(&mut self, params: &mut [f64], gradient: &[f64]) {
        self.beta_1_power *= BETA_1;
        self.beta_2_power *= BETA_2;
        let rate = self.rate * (1.0 - self.beta_2_power).sqrt() / (1.0 - self.beta_1_power);
        let moments = self.mean.iter_mut().zip(&mut self.square);
        for ((p, g), (m, v)) in params.iter_mut().zip(gradient).zip(moments) {
            *m = BETA_1 * *m + (1.0 - BETA_1) * g;
            *v = BETA_2 * *v + (1.0 - BETA_2) * g * g;
            *p -= rate * *m / (v.sqrt() + EPSILON);
        }
    }
}
