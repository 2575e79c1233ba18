//! LU decomposition with partial pivoting of a small square matrix, in plain arrays.
//!
//! The arithmetic is nalgebra's `LU` step for step — the same pivot choice (the first
//! largest magnitude in the column), the same multiplications by the pivot's reciprocal,
//! the same order of updates in the elimination and in the two triangular solves — so the
//! results are the same to the last bit. Only the bookkeeping differs: fixed-size arrays
//! indexed by loops the compiler unrolls, every right-hand side carried through each
//! triangular sweep at once, and no copies or generic views, which made a node's refit
//! cost several times what its arithmetic does.

/// The largest matrix factored: lin8's 8 inputs and a constant.
const LARGEST: usize = 9;

/// Runs `step::<I, ..>(args)` for I = 0, 1, …, [`LARGEST`] − 1; a step with I ≥ M does
/// nothing. With I and M constants, each step's loops have fixed lengths, which the
/// compiler unrolls; a loop over I would leave them as loops of varying length.
macro_rules! each_step {
    ($step:ident::<I, $($generic:ident),*>($($arg:expr),*)) => {
        $step::<0, $($generic),*>($($arg),*);
        $step::<1, $($generic),*>($($arg),*);
        $step::<2, $($generic),*>($($arg),*);
        $step::<3, $($generic),*>($($arg),*);
        $step::<4, $($generic),*>($($arg),*);
        $step::<5, $($generic),*>($($arg),*);
        $step::<6, $($generic),*>($($arg),*);
        $step::<7, $($generic),*>($($arg),*);
        $step::<8, $($generic),*>($($arg),*);
    };
}

/// The factors L (unit lower, below the diagonal) and U of P·A, column by column, and the
/// row swap made at each step.
#[derive(Debug, Clone, Copy)]
pub(super) struct SmallLu<const M: usize> {
    /// `columns[c][r]` is the factor's entry at row r, column c.
    columns: [[f64; M]; M],
    /// The row swapped with row i at step i (i itself when none was).
    pivots: [usize; M],
}

impl<const M: usize> SmallLu<M> {
    const FITS: () = assert!(M <= LARGEST, "each_step! covers at most LARGEST steps");

    /// Factors the matrix whose column c is `columns[c]`. A column whose candidates are
    /// all zero is left as it is (its pivot is zero, and [`solve`](Self::solve) fails).
    #[inline(always)]
    pub(super) fn from_columns(mut columns: [[f64; M]; M]) -> Self {
        let () = Self::FITS;
        let mut pivots = [0; M];
        each_step!(eliminate::<I, M>(&mut columns, &mut pivots));
        SmallLu { columns, pivots }
    }

    /// |U|'s diagonal: the pivots.
    pub(super) fn pivot_magnitudes(&self) -> [f64; M] {
        std::array::from_fn(|i| self.columns[i][i].abs())
    }

    /// Solves A·X = B for the `K` columns of B, given row by row (`rhs[r][k]`); `None`
    /// when a pivot is zero.
    #[inline(always)]
    pub(super) fn solve<const K: usize>(&self, rhs: &[[f64; K]; M]) -> Option<[[f64; K]; M]> {
        if (0..M).any(|i| self.columns[i][i] == 0.0) {
            return None;
        }
        let mut b = *rhs;
        for (i, &pivot) in self.pivots.iter().enumerate() {
            b.swap(i, pivot);
        }
        // L y = P b, unit diagonal, then U x = y from the last row up.
        each_step!(forward::<I, M, K>(&self.columns, &mut b));
        each_step!(backward::<I, M, K>(&self.columns, &mut b));
        Some(b)
    }
}

/// Step `I` of the elimination: pivot, scale the column below it, update the columns
/// right of it; `pivots[I]` is the pivot's row.
#[inline(always)]
fn eliminate<const I: usize, const M: usize>(columns: &mut [[f64; M]; M], pivots: &mut [usize; M]) {
    if I >= M {
        return;
    }
    let mut pivot = I;
    let mut largest = columns[I][I].abs();
    for (r, value) in columns[I].iter().enumerate().skip(I + 1) {
        let magnitude = value.abs();
        if magnitude > largest {
            largest = magnitude;
            pivot = r;
        }
    }
    let diagonal = columns[I][pivot];
    pivots[I] = I;
    if diagonal == 0.0 {
        return;
    }
    if pivot != I {
        pivots[I] = pivot;
        for column in columns.iter_mut() {
            column.swap(I, pivot);
        }
    }
    let inverse = 1.0 / diagonal;
    for value in &mut columns[I][I + 1..] {
        *value *= inverse;
    }
    let factors = columns[I];
    for column in &mut columns[I + 1..] {
        let head = column[I];
        for r in I + 1..M {
            // (x + (−h·f) is nalgebra's (−h·f) + x: addition commutes exactly.)
            column[r] += -head * factors[r];
        }
    }
}

/// Step `I` of solving L y = P b: row I's value taken out of the rows below.
#[inline(always)]
fn forward<const I: usize, const M: usize, const K: usize>(
    columns: &[[f64; M]; M],
    b: &mut [[f64; K]; M],
) {
    if I >= M {
        return;
    }
    let head = b[I];
    for r in I + 1..M {
        let l = columns[I][r];
        for k in 0..K {
            b[r][k] += -head[k] * l;
        }
    }
}

/// Step `I` of solving U x = y, from the last row: row M − 1 − I divided by its pivot and
/// taken out of the rows above.
#[inline(always)]
fn backward<const I: usize, const M: usize, const K: usize>(
    columns: &[[f64; M]; M],
    b: &mut [[f64; K]; M],
) {
    if I >= M {
        return;
    }
    let i = M - 1 - I;
    let diagonal = columns[i][i];
    for value in &mut b[i] {
        *value /= diagonal;
    }
    let head = b[i];
    for r in 0..i {
        let u = columns[i][r];
        for k in 0..K {
            b[r][k] += -head[k] * u;
        }
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

    fn factored(a: &Matrix6<f64>) -> SmallLu<6> {
        SmallLu::from_columns(std::array::from_fn(|c| std::array::from_fn(|r| a[(r, c)])))
    }

    #[test]
    fn factors_and_solutions_are_nalgebras_to_the_last_bit() {
        let mut rng = ChaCha8Rng::seed_from_u64(5);
        for _ in 0..2000 {
            let a = awkward(&mut rng);
            let b = Matrix6x3::from_fn(|_, _| rng.random_range(-100.0..100.0));
            let ours = factored(&a);
            let theirs = a.lu();
            let pivots = theirs.u().diagonal().map(f64::abs);
            assert_eq!(
                ours.pivot_magnitudes().map(f64::to_bits),
                pivots.data.0[0].map(f64::to_bits)
            );
            let rows: [[f64; 3]; 6] = std::array::from_fn(|r| std::array::from_fn(|k| b[(r, k)]));
            let (x, y) = (ours.solve(&rows), theirs.solve(&b));
            assert_eq!(x.is_some(), y.is_some());
            if let (Some(x), Some(y)) = (x, y) {
                for (r, row) in x.iter().enumerate() {
                    for (k, value) in row.iter().enumerate() {
                        assert_eq!(value.to_bits(), y[(r, k)].to_bits());
                    }
                }
            }
        }
    }

    #[test]
    fn a_zero_column_gives_no_solution() {
        let mut a = Matrix6::<f64>::identity();
        a[(3, 3)] = 0.0;
        let lu = factored(&a);
        assert_eq!(lu.pivot_magnitudes()[3], 0.0);
        assert_eq!(lu.solve(&[[1.0; 3]; 6]), None);
    }
}
