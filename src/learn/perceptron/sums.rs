//! Normal-equation sums of a least-squares fit, and their solution.

use nalgebra::{Const, DimMin, SMatrix, SVector};

/// Below this reciprocal condition estimate a fit counts as singular: its coefficients
/// would carry less than about six correct digits.
const MIN_RCOND: f64 = 1e-10;

/// Σ z zᵀ and Σ z tᵀ over the patterns (z the input with a trailing 1, t the target) of
/// one sum-set: the normal equations (Σ z zᵀ) W = Σ z tᵀ of the least-squares fit
/// t ≈ Wᵀ z for the three joints at once.
#[derive(Debug, Clone, PartialEq)]
pub(super) struct NormalSums<const M: usize> {
    zz: SMatrix<f64, M, M>,
    zt: SMatrix<f64, M, 3>,
}

impl<const M: usize> NormalSums<M> {
    /// No patterns.
    pub(super) fn new() -> Self {
        NormalSums {
            zz: SMatrix::zeros(),
            zt: SMatrix::zeros(),
        }
    }

    /// Adds one pattern, given as its products z zᵀ and z tᵀ.
    pub(super) fn add(&mut self, zz: &SMatrix<f64, M, M>, zt: &SMatrix<f64, M, 3>) {
        self.zz += zz;
        self.zt += zt;
    }

    /// Forgets every pattern.
    pub(super) fn clear(&mut self) {
        self.zz.fill(0.0);
        self.zt.fill(0.0);
    }

    /// The least-squares coefficients (one row per joint), or `None` when the system is
    /// singular or ill-conditioned.
    ///
    /// The matrix is first equilibrated to a unit diagonal; then an LU decomposition with
    /// partial pivoting is made once and solved for the three joints. The ratio of its
    /// smallest to largest pivot estimates the reciprocal condition number.
    pub(super) fn solve(&self) -> Option<SMatrix<f64, 3, M>>
    where
        Const<M>: DimMin<Const<M>, Output = Const<M>>,
    {
        let diagonal = self.zz.diagonal();
        if !diagonal.iter().all(|&d| d > 0.0 && d.is_finite()) {
            return None;
        }
        let scale: SVector<f64, M> = diagonal.map(|d| d.sqrt().recip());
        let lu = self.zz.component_mul(&(scale * scale.transpose())).lu();
        let pivots = lu.u().diagonal().map(f64::abs);
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
