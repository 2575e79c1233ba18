//! Random Fourier features of a squared-exponential kernel with a length scale per input.
//!
//! φⱼ(u) = σf·√(2/D)·cos(ωⱼ·u + bⱼ) with ωⱼ drawn from the kernel's spectral density
//! (normal, the inverse length scales as spreads) and bⱼ uniform in [0, 2π): then
//! E[φ(u)·φ(v)] = σf²·exp(−½ Σᵢ (uᵢ − vᵢ)²/ℓᵢ²). This is the phase-shifted form of the
//! features (one cosine per frequency); the paper pairs a cosine and a sine per
//! frequency, which needs two features per frequency for the same D.

use nalgebra::{DVector, SVector};
use rand::Rng;
use rand_distr::StandardNormal;

/// An input of the features (already scaled).
pub(super) type Input = SVector<f64, 5>;

/// D random Fourier features.
#[derive(Debug, Clone)]
pub(super) struct Features {
    /// Each feature's frequency, already divided by the length scales.
    frequencies: Vec<Input>,
    phases: Vec<f64>,
    amplitude: f64,
}

impl Features {
    /// `count` features of the kernel of amplitude `signal` and `length_scales` (in the
    /// inputs' units), drawn from `rng`.
    pub(super) fn new(
        count: usize,
        length_scales: &Input,
        signal: f64,
        rng: &mut impl Rng,
    ) -> Features {
        let mut frequencies = Vec::with_capacity(count);
        let mut phases = Vec::with_capacity(count);
        for _ in 0..count {
            let omega = Input::from_fn(|_, _| rng.sample::<f64, _>(StandardNormal));
            frequencies.push(omega.component_div(length_scales));
            phases.push(rng.random_range(0.0..std::f64::consts::TAU));
        }
        Features {
            frequencies,
            phases,
            amplitude: signal * (2.0 / count as f64).sqrt(),
        }
    }

    /// D.
    pub(super) fn len(&self) -> usize {
        self.phases.len()
    }

    /// Writes φ(u) into `out` (D long).
    pub(super) fn write(&self, u: &Input, out: &mut DVector<f64>) {
        for ((o, omega), b) in out.iter_mut().zip(&self.frequencies).zip(&self.phases) {
            *o = self.amplitude * (omega.dot(u) + b).cos();
        }
    }
}
