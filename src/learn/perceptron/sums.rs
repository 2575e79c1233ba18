//! Normal-equation sums of a least-squares fit, and their solution.

use super::lu::SmallLu;
use nalgebra::{SMatrix, SVector};

/// Below this reciprocal condition estimate a fit counts as singular: its coefficients
/// would carry less than about six correct digits.
const MIN_RCOND: f64 = 1e-10;
/// An input whose root mean square (in the node's local coordinates, where the box is
/// [−1, 1]) stays below this carries no information: it never left the box's middle.
const IDLE: f64 = 1e-9;

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

    /// Adds pattern number `seq`, given as its products z zᵀ and z tᵀ.
    #[inline]
    pub(super) fn add(&mut self, zz: &SMatrix<f64, M, M>, zt: &SMatrix<f64, M, 3>, seq: u64) {
        self.zz += zz;
        self.zt += zt;
        self.oldest = self.oldest.min(seq);
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

    /// The least-squares coefficients (one row per joint), or `None` when the system is
    /// singular or ill-conditioned, or holds no pattern.
    ///
    /// An input that `may_idle` and never left the middle of the box (its root mean square
    /// is below [`IDLE`]) is idle: its coefficient is undetermined and set to 0, the
    /// least-norm choice, which answers exactly wherever that input is 0 again. The matrix
    /// of the other inputs is equilibrated to a unit diagonal; an LU decomposition with
    /// partial pivoting is made once and solved for the three joints. The ratio of its
    /// smallest to largest pivot estimates the reciprocal condition number.
    pub(super) fn solve(&self, may_idle: &[bool; M]) -> Option<SMatrix<f64, 3, M>> {
        let diagonal = self.zz.diagonal();
        // The constant's diagonal counts the patterns.
        let count = diagonal[M - 1];
        let idle: [bool; M] =
            std::array::from_fn(|i| may_idle[i] && diagonal[i] <= IDLE * IDLE * count);
        let usable = |i: usize| idle[i] || (diagonal[i] > 0.0 && diagonal[i].is_finite());
        if !(0..M).all(usable) {
            return None;
        }
        // A zero scale drops an idle input's row and column.
        let scale = SVector::<f64, M>::from_fn(|i, _| {
            if idle[i] {
                0.0
            } else {
                diagonal[i].sqrt().recip()
            }
        });
        let mut equilibrated = self.zz.component_mul(&(scale * scale.transpose()));
        for i in (0..M).filter(|&i| idle[i]) {
            equilibrated[(i, i)] = 1.0;
        }
        let lu = SmallLu::new(&equilibrated);
        let pivots = SVector::<f64, M>::from(lu.pivot_magnitudes());
        // (False for NaN pivots too.)
        let well_conditioned = pivots.min() > MIN_RCOND * pivots.max();
        if !well_conditioned {
            return None;
        }
        let rhs = SMatrix::<f64, M, 3>::from_fn(|i, j| self.zt[(i, j)] * scale[i]);
        let y = lu.solve(&rhs)?;
        let w = SMatrix::<f64, M, 3>::from_fn(|i, j| y[(i, j)] * scale[i]);
        w.iter().all(|v| v.is_finite()).then(|| w.transpose())
    }
}
