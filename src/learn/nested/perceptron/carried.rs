//! A least-squares fit carried from pattern to pattern by rank-one updates (recursive least
//! squares), so that a set which only gains patterns needs no new factorisation.
//!
//! With P = (Σ z zᵀ)⁻¹ of the current sum-set and W its least-squares weights, a new pattern
//! (z, t) gives the fit of the set with it added exactly (Sherman–Morrison):
//! g = P z, d = 1 + zᵀ g, W ← W + (t − W z) gᵀ / d, P ← P − g gᵀ / d. That is O(M²) work
//! against a full solve's equilibration, LU and three triangular solves.
//!
//! How the perceptron uses it (see [`Perceptron`](super::Perceptron)):
//! - A full solve ([`NormalSums::solve`](super::sums::NormalSums::solve), with its
//!   equilibration, pivot-ratio condition test and idle inputs) establishes the fit: at the
//!   first refit that answers after a clear, a switch of the current set or a start-over,
//!   and at every refit while the last full solve gave no answer. P comes from the same LU
//!   (the equilibrated inverse, unscaled and made symmetric).
//! - Adding patterns to a least-squares problem never lowers the smallest eigenvalue of
//!   Σ z zᵀ, so an established fit stays solvable and its weights never become more
//!   sensitive to rounding (‖P‖ = 1/λ_min only falls). The condition test therefore speaks
//!   for the set at its establishment: its first solvable state carried at least about six
//!   correct digits. The equilibrated pivot ratio may still fall as the inputs' spreads
//!   grow unevenly; that is rechecked at the next full solve (the next set switch).
//! - While the established fit leaves an idle input out (lin8's readings after the move,
//!   before they vary), nothing is carried: every refit is a full solve, which is exact.
//! - Known patterns go through the same update as any other.
//! - Drift: each update rounds, and nothing corrects it until the next full solve, at the
//!   next set switch (at most `set_size / sum_sets` patterns later, 200 by default). The
//!   unit tests bound the carried weights' distance from a fresh solve's over long streams.
//! - An update whose numbers are not finite, or whose d falls below 1 (P has lost its
//!   positive definiteness to rounding), is not made: the carried fit is dropped and the
//!   next refit solves afresh.

use nalgebra::{SMatrix, SVector, Vector3};

/// The inverse normal matrix P = (Σ z zᵀ)⁻¹ of the set a fit is carried for.
#[derive(Debug, Clone)]
pub(super) struct CarriedFit<const M: usize> {
    /// P, symmetric; `inverse[i][j]` is its entry at row i, column j.
    inverse: [[f64; M]; M],
}

impl<const M: usize> CarriedFit<M> {
    /// A fit carried from the inverse of its set's Σ z zᵀ (symmetric).
    pub(super) fn new(inverse: &SMatrix<f64, M, M>) -> Self {
        CarriedFit {
            inverse: std::array::from_fn(|i| std::array::from_fn(|j| inverse[(i, j)])),
        }
    }

    /// The leverage zᵀ P z of an input z (with its trailing 1): how strongly a pattern
    /// there would pull the fit. Every pattern of the set has a leverage of at most 1.
    pub(super) fn leverage(&self, z: &SVector<f64, M>) -> f64 {
        let z = &z.data.0[0];
        let mut sum = 0.0;
        for (i, row) in self.inverse.iter().enumerate() {
            let pz: f64 = row.iter().zip(z).map(|(p, zj)| p * zj).sum();
            sum += z[i] * pz;
        }
        sum
    }

    /// Takes pattern (z, t) into `weights`, the least-squares fit of the set before it;
    /// afterwards they are the fit of the set with it. False, and nothing changed, when the
    /// update's numbers are not trustworthy (see the module doc): the fit must be solved
    /// afresh.
    #[must_use]
    #[inline]
    pub(super) fn take(
        &mut self,
        weights: &mut SMatrix<f64, 3, M>,
        z: &SVector<f64, M>,
        target: &Vector3<f64>,
    ) -> bool {
        let z = &z.data.0[0];
        // g = P z as a sum of P's columns (its rows: P is symmetric), which vectorises.
        let mut g = [0.0; M];
        for (column, zj) in self.inverse.iter().zip(z) {
            for (gi, pij) in g.iter_mut().zip(column) {
                *gi += pij * zj;
            }
        }
        let d = 1.0 + z.iter().zip(&g).map(|(x, y)| x * y).sum::<f64>();
        // (d ≥ 1 while P is positive definite; NaN fails too.)
        if !(1.0..f64::INFINITY).contains(&d) {
            return false;
        }
        let shrink = d.sqrt().recip();
        // P − h hᵀ with h = g / √d stays exactly symmetric; the gain is g / d.
        let h = g.map(|v| v * shrink);
        let gain = h.map(|v| v * shrink);
        let columns = &mut weights.data.0;
        let mut miss = *target;
        for (column, zj) in columns.iter().zip(z) {
            for k in 0..3 {
                miss[k] -= column[k] * zj;
            }
        }
        let updated: [[f64; 3]; M] =
            std::array::from_fn(|j| std::array::from_fn(|k| columns[j][k] + miss[k] * gain[j]));
        // (A NaN or an infinity among the terms makes the sum one too.)
        if !updated.iter().flatten().sum::<f64>().is_finite() {
            return false;
        }
        *columns = updated;
        for (row, hi) in self.inverse.iter_mut().zip(h) {
            for (value, hj) in row.iter_mut().zip(h) {
                *value -= hi * hj;
            }
        }
        true
    }
}

#[cfg(test)]
mod tests {
    use super::super::{Perceptron, PerceptronSettings};
    use crate::learn::nested::tree::Approximator;
    use nalgebra::{SMatrix, SVector, Vector3};
    use rand::{Rng, SeedableRng};
    use rand_chacha::ChaCha8Rng;

    type P5 = Perceptron<5, 6>;

    /// Where a stretch of the stream draws its inputs: per input an offset and a width
    /// (uniform in offset ± width), so a stretch may fill the box or a sliver near a corner.
    struct Stretch {
        offsets: [f64; 5],
        widths: [f64; 5],
        noise: f64,
    }

    impl Stretch {
        fn draw(rng: &mut ChaCha8Rng, awkward: bool) -> Self {
            if !awkward {
                return Stretch {
                    offsets: [0.0; 5],
                    widths: [1.0; 5],
                    noise: 0.01,
                };
            }
            let widths = std::array::from_fn(|_| 10f64.powi(-rng.random_range(0..8)));
            Stretch {
                offsets: std::array::from_fn(|i| rng.random_range(-1.0..1.0) * (1.0 - widths[i])),
                widths,
                noise: 10f64.powi(rng.random_range(-4..2)),
            }
        }

        fn input(&self, rng: &mut ChaCha8Rng) -> SVector<f64, 5> {
            SVector::from_fn(|i, _| self.offsets[i] + self.widths[i] * rng.random_range(-1.0..1.0))
        }
    }

    /// A curved target with noise, so fits have residuals to balance.
    fn target(
        map: &SMatrix<f64, 3, 6>,
        u: &SVector<f64, 5>,
        noise: f64,
        rng: &mut ChaCha8Rng,
    ) -> Vector3<f64> {
        let z = SVector::<f64, 6>::from_fn(|i, _| if i < 5 { u[i] } else { 1.0 });
        map * z
            + Vector3::repeat(2.0 * u[0] * u[1] - u[3].powi(3))
            + Vector3::from_fn(|_, _| noise * rng.random_range(-1.0..1.0))
    }

    /// How far the carried fit is from a fresh solve of the same set: the largest weight
    /// difference relative to the largest fresh weight, and the root mean square difference
    /// of the two fits' answers over the set's own patterns relative to that of the fresh
    /// answers (√tr(ΔW Σzzᵀ ΔWᵀ) / √tr(W Σzzᵀ Wᵀ)). `None` while nothing is carried or the
    /// fresh solve gives no answer.
    fn drift(p: &P5) -> Option<(f64, f64)> {
        p.carried.as_ref()?;
        let carried = p.weights.expect("a carried fit has weights");
        let set = &p.current_set();
        let fresh = set.solve(&p.may_idle)?.weights;
        let spread =
            |w: SMatrix<f64, 3, 6>| (w * set.normal_matrix() * w.transpose()).trace().sqrt();
        Some((
            (carried - fresh).amax() / fresh.amax(),
            spread(carried - fresh) / spread(fresh),
        ))
    }

    /// Streams stretches of patterns (awkward ones if `awkward`) through a perceptron with a
    /// refit after each; the largest drifts seen and how many carried fits were compared.
    fn worst_drift(seed: u64, awkward: bool) -> (f64, f64, usize) {
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        let map = SMatrix::<f64, 3, 6>::from_fn(|_, _| rng.random_range(-10.0..10.0));
        let mut p = P5::new(PerceptronSettings::default());
        let (mut weights, mut answers, mut compared) = (0.0f64, 0.0f64, 0);
        for stretch in 0..12 {
            let place = Stretch::draw(&mut rng, awkward && stretch % 3 != 0);
            for _ in 0..rng.random_range(200..2000) {
                let u = place.input(&mut rng);
                p.add(&u, &target(&map, &u, place.noise, &mut rng), 0);
                p.refit();
                if let Some((w, a)) = drift(&p) {
                    (weights, answers) = (weights.max(w), answers.max(a));
                    compared += 1;
                }
            }
        }
        (weights, answers, compared)
    }

    #[test]
    fn carried_weights_stay_close_to_a_fresh_solve() {
        // Patterns filling the box: rounding level.
        let (weights, answers, compared) = worst_drift(21, false);
        assert!(compared > 5000, "{compared} carried fits compared");
        assert!(
            weights < 1e-12 && answers < 1e-12,
            "{weights:e} {answers:e}"
        );
        // Stretches in slivers down to 1e-7 of the box near its corners, whose sets come
        // near the condition limit: carried weights differ by up to 2e-5, answers 6e-7 (seeds
        // 22–25), the size of a fresh solve's own rounding there.
        let (weights, answers, compared) = worst_drift(22, true);
        assert!(compared > 5000, "{compared} carried fits compared");
        assert!(weights < 1e-4 && answers < 1e-5, "{weights:e} {answers:e}");
    }

    #[test]
    fn a_singular_start_never_answers_nan() {
        let mut rng = ChaCha8Rng::seed_from_u64(22);
        let map = SMatrix::<f64, 3, 6>::from_fn(|_, _| rng.random_range(-10.0..10.0));
        let mut p = P5::new(PerceptronSettings::default());
        let probe = SVector::<f64, 5>::repeat(0.3);
        for n in 0..600 {
            let mut u = SVector::<f64, 5>::from_fn(|_, _| rng.random_range(-1.0..1.0));
            // Input 2 stands still for the first 300 patterns: a singular set.
            if n < 300 {
                u[2] = 0.25;
            }
            p.add(&u, &target(&map, &u, 0.01, &mut rng), 0);
            p.refit();
            let answer = p.answer(&probe);
            assert_eq!(answer.is_some(), n >= 300, "pattern {n}");
            assert!(answer.is_none_or(|a| a.iter().all(|v| v.is_finite())));
            assert_eq!(p.carried.is_some(), n >= 300, "pattern {n}");
        }
    }

    #[test]
    fn a_fit_with_an_idle_input_is_solved_afresh_each_time() {
        let mut rng = ChaCha8Rng::seed_from_u64(23);
        let map = SMatrix::<f64, 3, 9>::from_fn(|_, _| rng.random_range(-10.0..10.0));
        let mut p = Perceptron::<8, 9>::new(PerceptronSettings::default()).asked_at_zero(5..8);
        for n in 0..100 {
            let mut u = SVector::<f64, 8>::from_fn(|_, _| rng.random_range(-1.0..1.0));
            // lin8's readings after the move stay at 0 for the first 50 patterns.
            if n < 50 {
                u.fixed_rows_mut::<3>(5).fill(0.0);
            }
            let z = SVector::<f64, 9>::from_fn(|i, _| if i < 8 { u[i] } else { 1.0 });
            p.add(&u, &(map * z), 0);
            p.refit();
            // Answered from 6 patterns on (6 active unknowns), never carried while d is
            // idle; carried once d has varied enough to be solved for.
            if n < 50 {
                assert_eq!(p.weights.is_some(), n >= 5, "pattern {n}");
                assert!(p.carried.is_none(), "pattern {n}");
            } else if n >= 60 {
                assert!(p.weights.is_some() && p.carried.is_some(), "pattern {n}");
            }
        }
    }
}
