//! The rank-one update of a Cholesky factor: from L with LLᵀ = A to the factor of
//! A + xxᵀ, in O(D²) by one Givens rotation per column.

use nalgebra::{DMatrix, DVector};

/// Replaces the lower-triangular `factor` L (LLᵀ = A) by that of A + xxᵀ; `x` is used up
/// as scratch. Column k of L is contiguous (column-major), so the inner loop streams it.
pub(super) fn rank_one_update(factor: &mut DMatrix<f64>, x: &mut DVector<f64>) {
    let n = factor.nrows();
    let (l, x) = (factor.as_mut_slice(), x.as_mut_slice());
    for k in 0..n {
        let column = &mut l[k * n + k..(k + 1) * n];
        let (diagonal, below) = column.split_first_mut().expect("k < n");
        // (No overflow to guard against: both are far below 1e150 here.)
        let r = (*diagonal * *diagonal + x[k] * x[k]).sqrt();
        if r == 0.0 {
            continue;
        }
        let (c, s) = (r / *diagonal, x[k] / *diagonal);
        let inverse_c = 1.0 / c;
        *diagonal = r;
        for (lik, xi) in below.iter_mut().zip(&mut x[k + 1..]) {
            *lik = (*lik + s * *xi) * inverse_c;
            *xi = c * *xi - s * *lik;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_update_factors_the_updated_matrix() {
        let a = DMatrix::from_fn(6, 6, |i, j| if i == j { 2.0 + i as f64 } else { 0.3 });
        let x = DVector::from_fn(6, |i, _| (i as f64 * 0.7).sin());
        let mut factor = a.clone().cholesky().unwrap().l();
        rank_one_update(&mut factor, &mut x.clone());
        let expected = a + &x * x.transpose();
        assert!((&factor * factor.transpose() - expected).amax() < 1e-12);
        assert!((0..6).all(|j| (0..j).all(|i| factor[(i, j)] == 0.0)));
    }
}
