//! LU decomposition with partial pivoting of a small square matrix, in plain arrays.
//!
//! The arithmetic is nalgebra's `LU` step for step — the same pivot choice (the first
//! largest magnitude in the column), the same multiplications by the pivot's reciprocal,
//! the same order of updates in the elimination and in the two triangular solves — so the
//! results are the same to the last bit; only the generic matrix views are gone, which
//! made a node's refit cost several times what its arithmetic does.

use nalgebra::SMatrix;

/// The factors L (unit lower, below the diagonal) and U of P·A, column by column, and the
/// row swaps P in the order they were made.
#[derive(Debug, Clone, Copy)]
pub(super) struct SmallLu<const M: usize> {
    /// `columns[c][r]` is the factor's entry at row r, column c.
    columns: [[f64; M]; M],
    /// Row swaps (i, pivot row), `swaps` of them.
    swapped: [(usize, usize); M],
    swaps: usize,
}

impl<const M: usize> SmallLu<M> {
    /// Factors `matrix`. A column whose candidates are all zero is left as it is (its
    /// pivot is zero, and [`solve`](Self::solve) fails).
    pub(super) fn new(matrix: &SMatrix<f64, M, M>) -> Self {
        let mut columns = [[0.0; M]; M];
        for (c, column) in columns.iter_mut().enumerate() {
            for (r, value) in column.iter_mut().enumerate() {
                *value = matrix[(r, c)];
            }
        }
        let mut lu = SmallLu {
            columns,
            swapped: [(0, 0); M],
            swaps: 0,
        };
        for i in 0..M {
            lu.eliminate(i);
        }
        lu
    }

    /// Step `i` of the elimination: pivot, scale the column below it, update the rest.
    fn eliminate(&mut self, i: usize) {
        let column = &self.columns[i];
        let mut pivot = i;
        let mut largest = column[i].abs();
        for (r, value) in column.iter().enumerate().skip(i + 1) {
            if value.abs() > largest {
                largest = value.abs();
                pivot = r;
            }
        }
        let diagonal = column[pivot];
        if diagonal == 0.0 {
            return;
        }
        if pivot != i {
            self.swapped[self.swaps] = (i, pivot);
            self.swaps += 1;
            for column in &mut self.columns {
                column.swap(i, pivot);
            }
        }
        let inverse = 1.0 / diagonal;
        for value in &mut self.columns[i][i + 1..] {
            *value *= inverse;
        }
        let (left, right) = self.columns.split_at_mut(i + 1);
        let factors = &left[i];
        for column in right {
            let head = column[i];
            // (x + (−h·f) is nalgebra's (−h·f) + x: addition commutes exactly.)
            for (value, factor) in column[i + 1..].iter_mut().zip(&factors[i + 1..]) {
                *value += -head * factor;
            }
        }
    }

    /// |U|'s diagonal: the pivots.
    pub(super) fn pivot_magnitudes(&self) -> [f64; M] {
        std::array::from_fn(|i| self.columns[i][i].abs())
    }

    /// Solves A·X = B for `K` right-hand sides; `None` when a pivot is zero.
    pub(super) fn solve<const K: usize>(
        &self,
        rhs: &SMatrix<f64, M, K>,
    ) -> Option<SMatrix<f64, M, K>> {
        let mut x = *rhs;
        for &(i, pivot) in &self.swapped[..self.swaps] {
            x.swap_rows(i, pivot);
        }
        for k in 0..K {
            let mut b: [f64; M] = std::array::from_fn(|r| x[(r, k)]);
            // L y = P b, unit diagonal.
            for i in 0..M.saturating_sub(1) {
                let (done, rest) = b.split_at_mut(i + 1);
                let coefficient = done[i];
                for (value, l) in rest.iter_mut().zip(&self.columns[i][i + 1..]) {
                    *value += -coefficient * l;
                }
            }
            // U x = y.
            for i in (0..M).rev() {
                let diagonal = self.columns[i][i];
                if diagonal == 0.0 {
                    return None;
                }
                let coefficient = b[i] / diagonal;
                b[i] = coefficient;
                for (value, u) in b[..i].iter_mut().zip(&self.columns[i][..i]) {
                    *value += -coefficient * u;
                }
            }
            for (r, value) in b.iter().enumerate() {
                x[(r, k)] = *value;
            }
        }
        Some(x)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::{Matrix6, Matrix6x3};
    use rand::{Rng, SeedableRng};
    use rand_chacha::ChaCha8Rng;

    /// A random matrix whose rows and columns span many orders of magnitude, with some
    /// rows nearly alike, so pivoting and rounding both matter.
    fn awkward(rng: &mut ChaCha8Rng) -> Matrix6<f64> {
        let mut m = Matrix6::from_fn(|_, _| rng.random_range(-1.0..1.0));
        for i in 0..6 {
            let scale = 10f64.powi(rng.random_range(-6..6));
            m.row_mut(i).scale_mut(scale);
        }
        if rng.random_bool(0.3) {
            let copy = m.row(1) * (1.0 + 1e-9);
            m.set_row(4, &copy);
        }
        m
    }

    #[test]
    fn factors_and_solutions_are_nalgebras_to_the_last_bit() {
        let mut rng = ChaCha8Rng::seed_from_u64(5);
        for _ in 0..2000 {
            let a = awkward(&mut rng);
            let b = Matrix6x3::from_fn(|_, _| rng.random_range(-100.0..100.0));
            let ours = SmallLu::new(&a);
            let theirs = a.lu();
            let pivots = theirs.u().diagonal().map(f64::abs);
            assert_eq!(
                ours.pivot_magnitudes().map(f64::to_bits),
                pivots.data.0[0].map(f64::to_bits)
            );
            let (x, y) = (ours.solve(&b), theirs.solve(&b));
            assert_eq!(x.is_some(), y.is_some());
            if let (Some(x), Some(y)) = (x, y) {
                assert!(x
                    .iter()
                    .zip(y.iter())
                    .all(|(p, q)| p.to_bits() == q.to_bits()));
            }
        }
    }

    #[test]
    fn a_zero_column_gives_no_solution() {
        let mut a = Matrix6::<f64>::identity();
        a[(3, 3)] = 0.0;
        let lu = SmallLu::new(&a);
        assert_eq!(lu.pivot_magnitudes()[3], 0.0);
        assert_eq!(lu.solve(&Matrix6x3::from_element(1.0)), None);
    }
}
