//! Normal-equation sums of a least-squares fit, and their solution.

use super::lu::SmallLu;
use nalgebra::{SMatrix, SVector, Vector3};

/// Below this reciprocal condition estimate a fit counts as singular: its coefficients
/// would carry less than about six correct digits.
const MIN_RCOND: f64 = 1e-10;
/// An input whose root mean square (in the node's local coordinates, where the box is
/// [−1, 1]) stays below this carries no information: it never left the box's middle.
const IDLE: f64 = 1e-9;

/// What a full solve answers: the weights and, when no input was left out as idle, the
/// inverse of Σ z zᵀ, from which the fit can be carried (see [`super::carried`]).
#[derive(Debug, Clone, PartialEq)]
pub(super) struct Solution<const M: usize> {
    /// The least-squares coefficients, one row per joint.
    pub(super) weights: SMatrix<f64, 3, M>,
    /// (Σ z zᵀ)⁻¹, made exactly symmetric; `None` when an input was idle.
    pub(super) inverse: Option<SMatrix<f64, M, M>>,
}

/// Σ z zᵀ and Σ z tᵀ over the patterns (z the input with a trailing 1, t the target) of
/// one sum-set: the normal equations (Σ z zᵀ) W = Σ z tᵀ of the least-squares fit
/// t ≈ Wᵀ z for the three joints at once. The set also knows the sequence number of the
/// oldest pattern in it, so patterns from before a change of the mapping can be told apart.
#[derive(Debug, Clone, PartialEq)]
pub(super) struct NormalSums<const M: usize> {
    zz: SMatrix<f64, M, M>,
    zt: SMatrix<f64, M, 3>,
    /// The lowest sequence number added since the last clear; `u64::MAX` when empty.
    oldest: u64,
}

impl<const M: usize> NormalSums<M> {
    /// No patterns.
    pub(super) fn new() -> Self {
        NormalSums {
            zz: SMatrix::zeros(),
            zt: SMatrix::zeros(),
            oldest: u64::MAX,
        }
    }

    /// Adds pattern number `seq`, input z (with its trailing 1) and target t: z zᵀ and
    /// z tᵀ, each product added where it is made.
    #[inline]
    pub(super) fn add(&mut self, z: &SVector<f64, M>, t: &Vector3<f64>, seq: u64) {
        for (j, zj) in z.iter().enumerate() {
            for (i, zi) in z.iter().enumerate() {
                self.zz[(i, j)] += zi * zj;
            }
        }
        for (k, tk) in t.iter().enumerate() {
            for (i, zi) in z.iter().enumerate() {
                self.zt[(i, k)] += zi * tk;
            }
        }
        self.oldest = self.oldest.min(seq);
    }

    /// Adds the patterns of `other`.
    pub(super) fn absorb(&mut self, other: &Self) {
        self.zz += other.zz;
        self.zt += other.zt;
        self.oldest = self.oldest.min(other.oldest);
    }

    /// Forgets every pattern.
    pub(super) fn clear(&mut self) {
        self.zz.fill(0.0);
        self.zt.fill(0.0);
        self.oldest = u64::MAX;
    }

    /// The sequence number of the oldest pattern in the set, `None` when it holds none.
    pub(super) fn oldest(&self) -> Option<u64> {
        (self.oldest != u64::MAX).then_some(self.oldest)
    }

    /// The least-squares coefficients (one row per joint) and the inverse normal matrix,
    /// or `None` when the system is singular or ill-conditioned, or holds no pattern.
    ///
    /// An input that `may_idle` and never left the middle of the box (its root mean square
    /// is below [`IDLE`]) is idle: its coefficient is undetermined and set to 0, the
    /// least-norm choice, which answers exactly wherever that input is 0 again. The matrix
    /// of the other inputs is equilibrated to a unit diagonal; an LU decomposition with
    /// partial pivoting is made once and solved for the three joints. The ratio of its
    /// smallest to largest pivot estimates the reciprocal condition number. Without idle
    /// inputs the same LU gives the equilibrated inverse, which unscaled is (Σ z zᵀ)⁻¹.
    pub(super) fn solve(&self, may_idle: &[bool; M]) -> Option<Solution<M>> {
        // The constant's diagonal counts the patterns.
        let count = self.zz[(M - 1, M - 1)];
        let mut idle = [false; M];
        // A zero scale drops an idle input's row and column.
        let mut scale = [0.0; M];
        for i in 0..M {
            let diagonal = self.zz[(i, i)];
            idle[i] = may_idle[i] && diagonal <= IDLE * IDLE * count;
            if !idle[i] {
                // (Positive and finite; NaN fails both tests.)
                if !(diagonal > 0.0 && diagonal < f64::INFINITY) {
                    return None;
                }
                scale[i] = diagonal.sqrt().recip();
            }
        }
        let mut equilibrated = [[0.0; M]; M];
        for (c, column) in equilibrated.iter_mut().enumerate() {
            for (r, value) in column.iter_mut().enumerate() {
                *value = self.zz[(r, c)] * (scale[r] * scale[c]);
            }
        }
        for i in (0..M).filter(|&i| idle[i]) {
            equilibrated[i][i] = 1.0;
        }
        let lu = SmallLu::from_columns(equilibrated);
        if !well_conditioned(&lu.pivot_magnitudes()) {
            return None;
        }
        let mut rhs = [[0.0; 3]; M];
        for (r, row) in rhs.iter_mut().enumerate() {
            for (k, value) in row.iter_mut().enumerate() {
                *value = self.zt[(r, k)] * scale[r];
            }
        }
        let y = lu.solve(&rhs)?;
        let weights = SMatrix::<f64, 3, M>::from_fn(|k, r| y[r][k] * scale[r]);
        if !weights.iter().all(|v| v.is_finite()) {
            return None;
        }
        let inverse = if idle.contains(&true) {
            None
        } else {
            unscaled_inverse(&lu, &scale)
        };
        Some(Solution { weights, inverse })
    }
}

/// (Σ z zᵀ)⁻¹ = S E⁻¹ S from the LU of the equilibrated E = S (Σ z zᵀ) S, S = diag(`scale`),
/// averaged with its transpose; `None` if it is not finite.
fn unscaled_inverse<const M: usize>(
    lu: &SmallLu<M>,
    scale: &[f64; M],
) -> Option<SMatrix<f64, M, M>> {
    let identity: [[f64; M]; M] =
        std::array::from_fn(|r| std::array::from_fn(|c| f64::from(r == c)));
    let x = lu.solve(&identity)?;
    let inverse = SMatrix::<f64, M, M>::from_fn(|r, c| {
        let mean = 0.5 * (x[r][c] + x[c][r]);
        mean * (scale[r] * scale[c])
    });
    inverse.iter().all(|v| v.is_finite()).then_some(inverse)
}

impl<const M: usize> NormalSums<M> {
    /// Σ z zᵀ (tests of the carried fit measure answers over the set's patterns with it).
    #[cfg(test)]
    pub(super) fn normal_matrix(&self) -> &SMatrix<f64, M, M> {
        &self.zz
    }
}

/// Whether the smallest pivot is above [`MIN_RCOND`] times the largest (false for NaN
/// pivots too), the two found by nalgebra's `min` and `max` folds.
fn well_conditioned<const M: usize>(pivots: &[f64; M]) -> bool {
    let (mut least, mut most) = (pivots[0], pivots[0]);
    for &pivot in &pivots[1..] {
        least = if least <= pivot { least } else { pivot };
        most = if most >= pivot { most } else { pivot };
    }
    least > MIN_RCOND * most
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::{Matrix6x3, SVector, Vector6};
    use rand::{Rng, SeedableRng};
    use rand_chacha::ChaCha8Rng;

    /// The fit as nalgebra writes it: the same equilibration, nalgebra's own LU and its
    /// `min`/`max`, one solve for the three joints.
    fn nalgebra_fit(sums: &NormalSums<6>, may_idle: &[bool; 6]) -> Option<SMatrix<f64, 3, 6>> {
        let diagonal = sums.zz.diagonal();
        let count = diagonal[5];
        let idle: [bool; 6] =
            std::array::from_fn(|i| may_idle[i] && diagonal[i] <= IDLE * IDLE * count);
        let usable = |i: usize| idle[i] || (diagonal[i] > 0.0 && diagonal[i].is_finite());
        if !(0..6).all(usable) {
            return None;
        }
        let scale = Vector6::from_fn(|i, _| {
            if idle[i] {
                0.0
            } else {
                diagonal[i].sqrt().recip()
            }
        });
        let mut equilibrated = sums.zz.component_mul(&(scale * scale.transpose()));
        for i in (0..6).filter(|&i| idle[i]) {
            equilibrated[(i, i)] = 1.0;
        }
        let lu = equilibrated.lu();
        let pivots = lu.u().diagonal().map(f64::abs);
        let well_conditioned = pivots.min() > MIN_RCOND * pivots.max();
        if !well_conditioned {
            return None;
        }
        let rhs = Matrix6x3::from_fn(|i, j| sums.zt[(i, j)] * scale[i]);
        let y = lu.solve(&rhs)?;
        let w = Matrix6x3::from_fn(|i, j| y[(i, j)] * scale[i]);
        w.iter().all(|v| v.is_finite()).then(|| w.transpose())
    }

    /// Sums of a few to a few hundred patterns whose inputs span many orders of magnitude;
    /// some inputs stay at 0 (idle), some nearly copy another (ill-conditioned).
    fn awkward_sums(rng: &mut ChaCha8Rng) -> NormalSums<6> {
        let mut sums = NormalSums::new();
        let widths: [f64; 5] = std::array::from_fn(|_| 10f64.powi(rng.random_range(-8..3)));
        let still = rng.random_range(0..8usize);
        let twin = rng.random_bool(0.2);
        for seq in 0..rng.random_range(1..300) {
            let mut z = SVector::<f64, 6>::from_fn(|i, _| match i {
                5 => 1.0,
                _ if i == still => 0.0,
                _ => widths[i] * rng.random_range(-1.0..1.0),
            });
            if twin {
                z[3] = z[1] * (1.0 + 1e-9);
            }
            let t = SVector::<f64, 3>::from_fn(|_, _| rng.random_range(-50.0..50.0));
            sums.add(&z, &t, seq);
        }
        sums
    }

    #[test]
    fn the_fit_is_nalgebras_to_the_last_bit() {
        let mut rng = ChaCha8Rng::seed_from_u64(11);
        let mut answered = 0;
        for _ in 0..3000 {
            let sums = awkward_sums(&mut rng);
            let may_idle = std::array::from_fn(|i| i < 5 && rng.random_bool(0.5));
            let ours = sums.solve(&may_idle).map(|s| s.weights);
            let theirs = nalgebra_fit(&sums, &may_idle);
            assert_eq!(ours.is_some(), theirs.is_some());
            if let (Some(ours), Some(theirs)) = (ours, theirs) {
                answered += 1;
                assert_eq!(ours.map(f64::to_bits), theirs.map(f64::to_bits));
            }
        }
        // Both outcomes are exercised.
        assert!((500..2900).contains(&answered), "{answered} fits answered");
    }
}
