//! The rank-one update of a Cholesky factor: from L with LLᵀ = A to the factor of
//! A + xxᵀ, in O(D²) by one Givens rotation per column; and the downdate to that of
//! A − xxᵀ by one hyperbolic rotation per column, which takes a learned pattern out again.

use nalgebra::{DMatrix, DVector};

/// Replaces the lower-triangular `factor` L (LLᵀ = A) by that of A + xxᵀ; `x` is used up
/// as scratch. Column k of L is contiguous (column-major), so the inner loop streams it;
/// on a CPU with AVX2 it runs compiled for AVX2 (four lanes, the same operations in the
/// same order, so the same bits: no fused multiply-adds).
pub(super) fn rank_one_update(factor: &mut DMatrix<f64>, x: &mut DVector<f64>) {
    let n = factor.nrows();
    let (l, x) = (factor.as_mut_slice(), x.as_mut_slice());
    #[cfg(target_arch = "x86_64")]
    if std::arch::is_x86_feature_detected!("avx2") {
        // SAFETY: the CPU has AVX2.
        return unsafe { rotate_columns_avx2(l, x, n) };
    }
    rotate_columns(l, x, n);
}

/// [`rotate_columns`] compiled for AVX2.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
fn rotate_columns_avx2(l: &mut [f64], x: &mut [f64], n: usize) {
    rotate_columns(l, x, n);
}

/// The update on the column-major n × n factor `l`: one Givens rotation per column.
#[inline(always)]
fn rotate_columns(l: &mut [f64], x: &mut [f64], n: usize) {
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

/// Replaces the lower-triangular `factor` L (LLᵀ = A) by that of A − xxᵀ; `x` is used up
/// as scratch. Returns false, with `factor` left part-way, where A − xxᵀ is not positive
/// definite (in floating point). Called only to take patterns out after a detected change,
/// so it runs as plain code.
pub(super) fn rank_one_downdate(factor: &mut DMatrix<f64>, x: &mut DVector<f64>) -> bool {
    let n = factor.nrows();
    let (l, x) = (factor.as_mut_slice(), x.as_mut_slice());
    for k in 0..n {
        let column = &mut l[k * n + k..(k + 1) * n];
        let (diagonal, below) = column.split_first_mut().expect("k < n");
        let squared = (*diagonal - x[k]) * (*diagonal + x[k]);
        if squared.partial_cmp(&0.0) != Some(std::cmp::Ordering::Greater) {
            return false;
        }
        let r = squared.sqrt();
        let (c, s) = (r / *diagonal, x[k] / *diagonal);
        *diagonal = r;
        for (lik, xi) in below.iter_mut().zip(&mut x[k + 1..]) {
            *lik = (*lik - s * *xi) / c;
            *xi = c * *xi - s * *lik;
        }
    }
    true
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

    #[test]
    fn the_downdate_takes_an_update_out_again() {
        let a = DMatrix::from_fn(6, 6, |i, j| if i == j { 2.0 + i as f64 } else { 0.3 });
        let x = DVector::from_fn(6, |i, _| (i as f64 * 0.7).sin());
        let before = a.cholesky().unwrap().l();
        let mut factor = before.clone();
        rank_one_update(&mut factor, &mut x.clone());
        assert!(rank_one_downdate(&mut factor, &mut x.clone()));
        assert!((&factor - &before).amax() < 1e-12, "{factor}");
    }

    #[test]
    fn a_downdate_that_leaves_no_positive_definite_matrix_is_refused() {
        let mut factor = DMatrix::<f64>::identity(3, 3);
        assert!(!rank_one_downdate(
            &mut factor,
            &mut DVector::from_element(3, 1.0)
        ));
    }

    /// The AVX2 build gives the plain loop's bits (results must not change with the CPU).
    #[cfg(target_arch = "x86_64")]
    #[test]
    fn the_avx2_build_gives_the_plain_bits() {
        if !std::arch::is_x86_feature_detected!("avx2") {
            panic!("this test needs a CPU with AVX2");
        }
        let n = 37;
        let a = DMatrix::from_fn(n, n, |i, j| {
            if i == j {
                3.0 + (i as f64).cos()
            } else {
                0.1 * ((i * j) as f64).sin()
            }
        });
        let x = DVector::from_fn(n, |i, _| (i as f64 * 0.37).sin() * 2.0);
        let factor = a.cholesky().unwrap().l();
        let (mut plain, mut plain_x) = (factor.clone(), x.clone());
        rotate_columns(plain.as_mut_slice(), plain_x.as_mut_slice(), n);
        let (mut wide, mut wide_x) = (factor, x);
        // SAFETY: the CPU has AVX2 (checked above).
        unsafe { rotate_columns_avx2(wide.as_mut_slice(), wide_x.as_mut_slice(), n) };
        let bits = |m: &DMatrix<f64>| m.iter().map(|v| v.to_bits()).collect::<Vec<_>>();
        assert_eq!(bits(&plain), bits(&wide));
    }
}
