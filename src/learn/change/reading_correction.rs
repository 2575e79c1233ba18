//! A correction of the camera readings that carries a changed robot's readings back to
//! the ones the learner learned with, fitted from a few dozen patterns after a change.
//!
//! A nested learner's inputs are (θ2, θ3) followed by one or two camera readings (cx, cy,
//! cz): lin5 one adjusted reading, lin8 the readings before and after the move. A camera
//! turned about its axis turns every reading by the same angle, wherever the arm is; a
//! longer or shorter link changes how a joint move shows in the camera, smoothly and
//! mostly alike over the poses. Both are caught, exactly or on the whole, by a map of each
//! reading c to A·c with A = I + P: 9 numbers, the same at every pose. The learner then
//! answers N(A·c, θ) with N the tree it learned before the change. (A map that also varies
//! with θ2 and θ3 to first order brings lin5 and lin8 back no sooner after a link change:
//! docs/ADAPTATION.md, "A correction that varies with the pose".)
//!
//! The fit is Gauss–Newton on the patterns since the change: each pattern (x, Δθ) should be
//! answered as N(A x) = Δθ; N's change with its readings comes from finite differences of
//! its answers (a node's perceptron is linear in them, so a small step gives its slope
//! exactly). Misses are weighed relative to the size of each move (as the change watch
//! weighs them), so the small final moves of a trial, which set its precision, count as
//! much as its first long one. The fit is robust: each pattern's weight is further divided
//! by 1 + (r/s)², r its weighed miss and s the misses' spread (1.4826 × their median), and
//! the weights are made anew at every iteration. The patterns that come before the alarm
//! come from trials in which the old tree lost its way; some of them lie where the tree is
//! poor in any case, and their misses would pull a plain least-squares fit off the change
//! (docs/ADAPTATION.md).

use crate::learn::Pattern;
use nalgebra::{Matrix3, SMatrix, SVector, Vector3};

/// Numbers in the correction: one 3×3 matrix.
const PARAMETERS: usize = 9;
/// Gauss–Newton iterations per fit (with the robust weights made anew at each: ten let
/// them settle; three left some fits short of it).
const ITERATIONS: usize = 10;
/// Moves below this (degrees) are weighed as if they were this long.
const MIN_MOVE_DEG: f64 = 0.1;
/// The finite-difference step, as a share of a reading input's range.
const STEP_SHARE: f64 = 1e-6;
/// A miss of this many spreads halves its pattern's weight (the width of the Cauchy
/// weights of the robust fit).
const CAUCHY_WIDTH: f64 = 1.0;
/// The spread of normal misses per unit of their median (the median absolute deviation's
/// factor).
const SPREAD_PER_MEDIAN: f64 = 1.4826;
/// Ridge on the normal equations, as a share of their mean diagonal: keeps a fit from few
/// or alike patterns from wandering off along what they cannot tell apart.
const RIDGE_SHARE: f64 = 1e-6;

/// The correction of a learner with `N` inputs: (θ2, θ3) then (N − 2)/3 readings.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct ReadingCorrection<const N: usize> {
    /// P: A less the identity.
    term: Matrix3<f64>,
    /// The finite-difference step of each reading input.
    steps: SVector<f64, N>,
}

impl<const N: usize> ReadingCorrection<N> {
    /// No correction yet, for a learner whose input box is `low`..`high`.
    pub(crate) fn identity(low: &SVector<f64, N>, high: &SVector<f64, N>) -> Self {
        ReadingCorrection {
            term: Matrix3::zeros(),
            steps: SVector::from_fn(|i, _| STEP_SHARE * (high[i] - low[i]).abs().max(1e-9)),
        }
    }

    /// The readings of input `x` carried back by the correction.
    pub(crate) fn apply(&self, x: &SVector<f64, N>) -> SVector<f64, N> {
        let a = self.matrix();
        let mut out = *x;
        for start in reading_starts::<N>() {
            let c = Vector3::new(x[start], x[start + 1], x[start + 2]);
            out.fixed_rows_mut::<3>(start).copy_from(&(a * c));
        }
        out
    }

    /// The largest change of an entry of A from `other`'s.
    pub(crate) fn moved_from(&self, other: &Self) -> f64 {
        (self.term - other.term).amax()
    }

    /// A.
    fn matrix(&self) -> Matrix3<f64> {
        Matrix3::identity() + self.term
    }

    /// Fits the correction to `patterns` (starting from itself) so that `answer` of the
    /// corrected inputs meets their targets.
    pub(crate) fn fit(
        &mut self,
        patterns: &[Pattern<N>],
        mut answer: impl FnMut(&SVector<f64, N>) -> Vector3<f64>,
    ) {
        for _ in 0..ITERATIONS {
            let (normal, rhs) = self.normal_equations(patterns, &mut answer);
            let Some(step) = solve_with_ridge(normal, &rhs) else {
                break;
            };
            for (value, change) in self.term.iter_mut().zip(step.iter()) {
                *value += change;
            }
        }
    }

    /// The mean squared miss of `answer` at the corrected inputs of `patterns`, each
    /// relative to the size of its move.
    #[cfg(test)]
    fn miss(
        &self,
        patterns: &[Pattern<N>],
        answer: impl Fn(&SVector<f64, N>) -> Vector3<f64>,
    ) -> f64 {
        let total: f64 = patterns
            .iter()
            .map(|p| weight(p) * (p.target - answer(&self.apply(&p.input))).norm_squared())
            .sum();
        total / patterns.len().max(1) as f64
    }

    /// JᵀWJ and JᵀWr of the patterns at the current correction (J: the corrected answers'
    /// change with the 9 numbers, W: each move's weight, lowered for misses far beyond
    /// the spread of the others).
    fn normal_equations(
        &self,
        patterns: &[Pattern<N>],
        answer: &mut impl FnMut(&SVector<f64, N>) -> Vector3<f64>,
    ) -> (
        SMatrix<f64, PARAMETERS, PARAMETERS>,
        SVector<f64, PARAMETERS>,
    ) {
        let mut normal = SMatrix::<f64, PARAMETERS, PARAMETERS>::zeros();
        let mut rhs = SVector::<f64, PARAMETERS>::zeros();
        let answered: Vec<(SVector<f64, N>, Vector3<f64>, f64)> = patterns
            .iter()
            .map(|p| {
                let corrected = self.apply(&p.input);
                let answered = answer(&corrected);
                let miss = weight(p).sqrt() * (p.target - answered).norm();
                (corrected, answered, miss)
            })
            .collect();
        let width = CAUCHY_WIDTH * spread(answered.iter().map(|&(_, _, miss)| miss));
        for (pattern, (corrected, answered, miss)) in patterns.iter().zip(&answered) {
            let residual = pattern.target - answered;
            let jacobian = self.jacobian(pattern, corrected, answered, answer);
            let w = weight(pattern) / (1.0 + (miss / width).powi(2));
            normal += w * jacobian.transpose() * jacobian;
            rhs += w * jacobian.transpose() * residual;
        }
        (normal, rhs)
    }

    /// How the answer at the corrected input changes with each of the 9 numbers.
    fn jacobian(
        &self,
        pattern: &Pattern<N>,
        corrected: &SVector<f64, N>,
        answered: &Vector3<f64>,
        answer: &mut impl FnMut(&SVector<f64, N>) -> Vector3<f64>,
    ) -> SMatrix<f64, 3, PARAMETERS> {
        let mut jacobian = SMatrix::<f64, 3, PARAMETERS>::zeros();
        for start in reading_starts::<N>() {
            let raw = Vector3::new(
                pattern.input[start],
                pattern.input[start + 1],
                pattern.input[start + 2],
            );
            for row in 0..3 {
                let mut nudged = *corrected;
                let h = self.steps[start + row];
                nudged[start + row] += h;
                let slope = (answer(&nudged) - answered) / h;
                // ∂(A c)[row] / ∂P[row, col] = c[col].
                for col in 0..3 {
                    let mut column = jacobian.column_mut(row + 3 * col);
                    column += slope * raw[col];
                }
            }
        }
        jacobian
    }

    /// Whether the correction changes nothing.
    #[cfg(test)]
    fn is_identity(&self) -> bool {
        self.term.iter().all(|&v| v == 0.0)
    }
}

/// A pattern's weight: its miss counts relative to the size of its move.
fn weight<const N: usize>(pattern: &Pattern<N>) -> f64 {
    pattern.target.norm().max(MIN_MOVE_DEG).powi(-2)
}

/// The spread of `misses` (SPREAD_PER_MEDIAN × their median), kept above zero so that
/// patterns met exactly keep a finite weight.
fn spread(misses: impl Iterator<Item = f64>) -> f64 {
    let mut sorted: Vec<f64> = misses.collect();
    sorted.sort_by(f64::total_cmp);
    let median = sorted.get(sorted.len() / 2).copied().unwrap_or(0.0);
    (SPREAD_PER_MEDIAN * median).max(f64::MIN_POSITIVE)
}

/// The first input of each reading: 2, then 5 for a second one.
fn reading_starts<const N: usize>() -> impl Iterator<Item = usize> {
    (2..N.saturating_sub(2)).step_by(3)
}

/// Solves (A + ridge) x = b by Cholesky; `None` if even that is not positive definite.
fn solve_with_ridge(
    mut normal: SMatrix<f64, PARAMETERS, PARAMETERS>,
    rhs: &SVector<f64, PARAMETERS>,
) -> Option<SVector<f64, PARAMETERS>> {
    let ridge = RIDGE_SHARE * normal.trace() / PARAMETERS as f64 + f64::MIN_POSITIVE;
    for i in 0..PARAMETERS {
        normal[(i, i)] += ridge;
    }
    let step = normal.cholesky()?.solve(rhs);
    step.iter().all(|v| v.is_finite()).then_some(step)
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::Rotation2;

    /// A linear "tree": Δθ = W c + (θ-dependent) over lin5's inputs.
    fn learned(x: &SVector<f64, 5>) -> Vector3<f64> {
        let w = Matrix3::new(0.02, -0.01, 0.003, 0.015, 0.03, -0.002, 0.001, 0.004, 0.05);
        w * Vector3::new(x[2], x[3], x[4]) * (1.0 + 0.002 * x[0])
            + Vector3::new(0.0, 0.0, 0.01 * x[1])
    }

    fn box_corners() -> (SVector<f64, 5>, SVector<f64, 5>) {
        (
            SVector::from([-40.0, 0.0, -200.0, -200.0, -100.0]),
            SVector::from([40.0, 90.0, 200.0, 200.0, 100.0]),
        )
    }

    fn patterns(reading_of: impl Fn(Vector3<f64>, f64, f64) -> Vector3<f64>) -> Vec<Pattern<5>> {
        (0..60)
            .map(|i| {
                let f = i as f64;
                let (t2, t3) = (-30.0 + f, 10.0 + 1.3 * f);
                let old = Vector3::new(
                    150.0 * (0.37 * f).sin(),
                    120.0 * (0.61 * f).cos(),
                    40.0 * (0.23 * f).sin(),
                );
                let x_old = SVector::from([t2, t3, old.x, old.y, old.z]);
                let seen = reading_of(old, t2, t3);
                Pattern {
                    input: SVector::from([t2, t3, seen.x, seen.y, seen.z]),
                    target: learned(&x_old),
                }
            })
            .collect()
    }

    #[test]
    fn a_turned_camera_is_carried_back_exactly() {
        let turn = Rotation2::new(30f64.to_radians());
        let data = patterns(|c, _, _| {
            let xy = turn * nalgebra::Vector2::new(c.x, c.y);
            Vector3::new(xy.x, xy.y, c.z)
        });
        let (low, high) = box_corners();
        let mut correction = ReadingCorrection::identity(&low, &high);
        assert!(correction.is_identity());
        let before = correction.miss(&data, learned);
        correction.fit(&data, learned);
        let after = correction.miss(&data, learned);
        assert!(before > 1e-3, "the turn misses: {before}");
        assert!(after < 1e-12, "carried back: {after}");
        let back = correction.matrix();
        let expected = turn.inverse();
        assert!((back[(0, 0)] - expected[(0, 0)]).abs() < 1e-6);
        assert!((back[(0, 1)] - expected[(0, 1)]).abs() < 1e-6);
    }

    #[test]
    fn a_change_of_scale_and_turn_is_carried_back_exactly() {
        let turn = Rotation2::new(-4f64.to_radians());
        let data = patterns(|c, _, _| {
            let xy = turn * nalgebra::Vector2::new(c.x, c.y) * 0.9;
            Vector3::new(xy.x, xy.y, 1.05 * c.z)
        });
        let (low, high) = box_corners();
        let mut correction = ReadingCorrection::identity(&low, &high);
        let before = correction.miss(&data, learned);
        correction.fit(&data, learned);
        let after = correction.miss(&data, learned);
        assert!(after < 1e-12 * before, "{before} → {after}");
    }

    #[test]
    fn a_turned_camera_is_carried_back_past_patterns_the_tree_misses() {
        let turn = Rotation2::new(30f64.to_radians());
        let mut data = patterns(|c, _, _| {
            let xy = turn * nalgebra::Vector2::new(c.x, c.y);
            Vector3::new(xy.x, xy.y, c.z)
        });
        // One pattern in five lies where the tree is poor: its move is half again as long
        // as the tree would answer.
        for pattern in data.iter_mut().step_by(5) {
            pattern.target *= 1.5;
        }
        let (low, high) = box_corners();
        let mut correction = ReadingCorrection::identity(&low, &high);
        correction.fit(&data, learned);
        let back = correction.matrix();
        let expected = turn.inverse();
        let off = (back[(0, 0)] - expected[(0, 0)])
            .abs()
            .max((back[(0, 1)] - expected[(0, 1)]).abs());
        assert!(off < 0.01, "{back}");
    }

    #[test]
    fn a_pose_dependent_change_of_scale_is_carried_back_on_the_whole() {
        let data = patterns(|c, t2, _| c * (1.1 + 0.001 * t2));
        let (low, high) = box_corners();
        let mut correction = ReadingCorrection::identity(&low, &high);
        let before = correction.miss(&data, learned);
        correction.fit(&data, learned);
        let after = correction.miss(&data, learned);
        assert!(after < 0.05 * before, "{before} → {after}");
    }

    #[test]
    fn without_a_change_the_fit_stays_the_identity() {
        let data = patterns(|c, _, _| c);
        let (low, high) = box_corners();
        let mut correction = ReadingCorrection::identity(&low, &high);
        correction.fit(&data, learned);
        let a = correction.matrix();
        assert!((a - Matrix3::identity()).amax() < 1e-9, "{a}");
    }

    #[test]
    fn eight_inputs_have_two_readings() {
        assert_eq!(reading_starts::<5>().collect::<Vec<_>>(), [2]);
        assert_eq!(reading_starts::<8>().collect::<Vec<_>>(), [2, 5]);
    }
}
