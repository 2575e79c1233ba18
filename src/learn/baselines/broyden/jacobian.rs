//! The image Jacobian J ≈ ∂c/∂θ (reading units per degree), its update after a move and the
//! damped least-squares step it gives.

use super::{BroydenSettings, BroydenUpdate};
use nalgebra::{Matrix3, Vector3};

/// Moves shorter than this (degrees) update nothing: what they did to the reading is
/// mostly rounding.
const MIN_MOVE_DEG: f64 = 1e-6;

/// The estimated image Jacobian and, for the recursive least-squares update, its
/// covariance P (per squared degree).
#[derive(Debug, Clone, PartialEq)]
pub struct ImageJacobian {
    j: Matrix3<f64>,
    p: Matrix3<f64>,
    /// P's trace is kept at most this (its trace after the probes).
    p_trace_cap: f64,
}

impl ImageJacobian {
    /// The Jacobian the moves `moves` (columns, degrees) and the reading changes `changes`
    /// (columns) they caused give: J = ΔC·ΔΘ⁻¹, P = (ΔΘΔΘᵀ)⁻¹. `None` when the moves do not
    /// span every joint.
    pub fn from_probes(moves: &Matrix3<f64>, changes: &Matrix3<f64>) -> Option<ImageJacobian> {
        let inverse = moves.try_inverse()?;
        let p = (moves * moves.transpose()).try_inverse()?;
        let j = changes * inverse;
        (j.iter().chain(p.iter()).all(|v| v.is_finite())).then(|| ImageJacobian {
            j,
            p,
            p_trace_cap: p.trace(),
        })
    }

    /// The Jacobian `j` with covariance `p`.
    pub fn new(j: Matrix3<f64>, p: Matrix3<f64>) -> ImageJacobian {
        ImageJacobian {
            j,
            p,
            p_trace_cap: p.trace(),
        }
    }

    /// J.
    pub fn matrix(&self) -> &Matrix3<f64> {
        &self.j
    }

    /// Learns from a move of `moved` degrees that changed the reading by `changed`, by
    /// `settings.update`. A move too short, or a change not finite, updates nothing.
    pub fn update(
        &mut self,
        moved: &Vector3<f64>,
        changed: &Vector3<f64>,
        settings: &BroydenSettings,
    ) {
        let length2 = moved.norm_squared();
        if length2 < MIN_MOVE_DEG * MIN_MOVE_DEG || !changed.iter().all(|v| v.is_finite()) {
            return;
        }
        let miss = changed - self.j * moved;
        match settings.update {
            BroydenUpdate::Broyden => {
                self.j += settings.rate * miss * moved.transpose() / length2;
            }
            BroydenUpdate::Rls => self.rls(moved, &miss, settings.forgetting),
        }
    }

    /// The recursive least-squares update with forgetting `lambda`.
    fn rls(&mut self, moved: &Vector3<f64>, miss: &Vector3<f64>, lambda: f64) {
        let p_moved = self.p * moved;
        let denominator = lambda + moved.dot(&p_moved);
        if denominator.partial_cmp(&0.0) != Some(std::cmp::Ordering::Greater) {
            return;
        }
        self.j += miss * p_moved.transpose() / denominator;
        self.p = (self.p - p_moved * p_moved.transpose() / denominator) / lambda;
        self.p = 0.5 * (self.p + self.p.transpose());
        let trace = self.p.trace();
        if trace > self.p_trace_cap {
            self.p *= self.p_trace_cap / trace;
        }
    }

    /// The damped least-squares move (degrees) toward `c` = 0: −(JᵀJ + μ²I)⁻¹Jᵀc with μ² the
    /// `damping` share of JᵀJ's mean diagonal, scaled down so no joint turns more than
    /// `max_step_deg`. No move when J carries nothing.
    pub fn step(&self, c: &Vector3<f64>, damping: f64, max_step_deg: f64) -> Vector3<f64> {
        let normal = self.j.transpose() * self.j;
        let mu2 = damping * normal.trace() / 3.0;
        let damped = normal + Matrix3::identity() * mu2;
        let Some(step) = damped
            .cholesky()
            .map(|ch| -ch.solve(&(self.j.transpose() * c)))
        else {
            return Vector3::zeros();
        };
        let largest = step.amax();
        if !largest.is_finite() {
            return Vector3::zeros();
        }
        if largest > max_step_deg {
            step * (max_step_deg / largest)
        } else {
            step
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The linear "camera" the tests move in: c = M θ.
    fn map() -> Matrix3<f64> {
        Matrix3::new(12.0, -3.0, 0.5, 2.0, 9.0, -4.0, -1.0, 0.7, 6.0)
    }

    fn moves() -> Vec<Vector3<f64>> {
        (0..12)
            .map(|i| {
                let f = i as f64;
                Vector3::new(
                    (0.7 * f).sin(),
                    (1.3 * f + 0.4).cos(),
                    0.5 * (0.31 * f).sin() + 0.1,
                )
            })
            .collect()
    }

    fn settings(update: BroydenUpdate) -> BroydenSettings {
        BroydenSettings {
            update,
            forgetting: 0.8,
            ..BroydenSettings::default()
        }
    }

    #[test]
    fn broydens_update_is_its_closed_form_on_a_linear_map() {
        let start = Matrix3::new(10.0, 0.0, 0.0, 0.0, 10.0, 0.0, 0.0, 0.0, 10.0);
        let mut jacobian = ImageJacobian::new(start, Matrix3::identity());
        let mut expected = start;
        for moved in moves() {
            let changed = map() * moved;
            // J⁺ = J + (Δc − JΔθ)Δθᵀ / ΔθᵀΔθ: it meets the secant condition J⁺Δθ = Δc and
            // leaves J unchanged on every direction normal to Δθ.
            let before = expected;
            expected += (changed - before * moved) * moved.transpose() / moved.norm_squared();
            jacobian.update(&moved, &changed, &settings(BroydenUpdate::Broyden));
            assert!((jacobian.matrix() - expected).amax() < 1e-12);
            assert!((jacobian.matrix() * moved - changed).amax() < 1e-12);
            let normal = moved.cross(&Vector3::new(0.3, -0.2, 1.0));
            assert!((jacobian.matrix() * normal - before * normal).amax() < 1e-9);
        }
    }

    #[test]
    fn three_orthogonal_broyden_moves_recover_a_linear_map() {
        let mut jacobian = ImageJacobian::new(Matrix3::zeros(), Matrix3::identity());
        for axis in 0..3 {
            let moved = Vector3::ith(axis, 2.0);
            jacobian.update(&moved, &(map() * moved), &settings(BroydenUpdate::Broyden));
        }
        assert!((jacobian.matrix() - map()).amax() < 1e-12);
    }

    #[test]
    fn the_rls_update_is_the_weighted_least_squares_fit_of_its_moves() {
        // With forgetting λ the estimate after k moves minimises
        // Σ λ^(k−i) ‖Δcᵢ − JΔθᵢ‖² + λ^k tr((J − J₀)P₀⁻¹(J − J₀)ᵀ):
        // J = (λ^k J₀P₀⁻¹ + Σ λ^(k−i) ΔcᵢΔθᵢᵀ)(λ^k P₀⁻¹ + Σ λ^(k−i) ΔθᵢΔθᵢᵀ)⁻¹.
        let lambda: f64 = 0.8;
        let start = Matrix3::new(8.0, 1.0, 0.0, 0.0, 7.0, 1.0, 1.0, 0.0, 9.0);
        let p0 = Matrix3::identity() * 4.0;
        let mut jacobian = ImageJacobian::new(start, p0);
        jacobian.p_trace_cap = f64::INFINITY;
        let all = moves();
        for (k, moved) in all.iter().enumerate() {
            // A map that drifts, so that forgetting matters.
            let truth = map() + Matrix3::identity() * (0.3 * k as f64);
            jacobian.update(moved, &(truth * moved), &settings(BroydenUpdate::Rls));
            let n = k + 1;
            let weight = |i: usize| lambda.powi((n - 1 - i) as i32);
            let prior = lambda.powi(n as i32) * p0.try_inverse().unwrap();
            let (mut left, mut right) = (start * prior, prior);
            for (i, m) in all[..n].iter().enumerate() {
                let truth = map() + Matrix3::identity() * (0.3 * i as f64);
                left += weight(i) * (truth * m) * m.transpose();
                right += weight(i) * m * m.transpose();
            }
            let expected = left * right.try_inverse().unwrap();
            assert!(
                (jacobian.matrix() - expected).amax() < 1e-9,
                "move {n}: {} against {expected}",
                jacobian.matrix()
            );
        }
    }

    #[test]
    fn probes_give_the_map_and_its_covariance() {
        let moves = Matrix3::identity() * 1.5;
        let jacobian = ImageJacobian::from_probes(&moves, &(map() * moves)).expect("spanning");
        assert!((jacobian.matrix() - map()).amax() < 1e-12);
        assert!(ImageJacobian::from_probes(&Matrix3::zeros(), &map()).is_none());
    }

    #[test]
    fn the_step_solves_a_linear_map_and_keeps_to_the_size_limit() {
        let jacobian = ImageJacobian::new(map(), Matrix3::identity());
        let theta = Vector3::new(1.0, -2.0, 0.5);
        let step = jacobian.step(&(map() * theta), 0.0, 100.0);
        assert!((step + theta).amax() < 1e-9);
        let limited = jacobian.step(&(map() * theta * 50.0), 0.0, 10.0);
        assert!((limited.amax() - 10.0).abs() < 1e-9);
        assert!((limited.normalize() + theta.normalize()).amax() < 1e-9);
        let none = ImageJacobian::new(Matrix3::zeros(), Matrix3::identity());
        assert_eq!(
            none.step(&Vector3::new(1.0, 2.0, 3.0), 0.001, 10.0),
            Vector3::zeros()
        );
    }
}
