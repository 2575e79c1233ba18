//! lin8's branch rule: (θ2, θ3, c) halve, the reading after the move narrows around zero.
//!
//! lin8's inputs are (θ2, θ3, cx, cy, cz, dx, dy, dz), d being the camera reading after the
//! move. A query always asks for d = 0, so a node only needs the sub-boxes that hold d = 0:
//! the five (θ2, θ3, c) dimensions are halved as in lin5 (32 branches), and the three d
//! dimensions are never split but narrowed towards zero: at depth k a node's d box is the
//! root's d boundaries times `error_area_shrink`ᵏ (study §4.3.2). Deeper nodes answer for
//! moves that ended nearer the target, which is what the later feedback steps make.
//!
//! A pattern whose d lies outside the d box of depth k + 1 has no child box under its node
//! at depth k: the study gives it branch number 32 ("no child applies") from there on
//! (§4.3.3). Here its [`BinKey`] simply stops at depth k (its reach), so it is trained to
//! the nodes down to depth k, kept in one bin per such node and never sinks deeper. The
//! root covers every d, however far out.

use super::{BinKey, BranchRule, Halving, Region, MAX_DEPTH};
use nalgebra::{SVector, Vector3};

/// The inputs that halve: θ2, θ3, cx, cy, cz.
const HALVED: usize = 5;
/// Where d starts in the input vector.
const D: usize = HALVED;

/// How lin8's 8-input boxes branch: halving the first five inputs, narrowing d by depth.
#[derive(Debug, Clone)]
pub struct Narrowing {
    root: Region<8>,
    halving: Halving<HALVED>,
    /// The d box of each depth, lower and upper corner.
    d_boxes: [(Vector3<f64>, Vector3<f64>); MAX_DEPTH + 1],
}

impl Narrowing {
    /// The rule for root box `root`, the d box shrinking by `shrink` (0 < shrink ≤ 1) per
    /// depth. The root's d boundaries should hold 0, or queries (d = 0) stay at the root.
    pub(crate) fn new(root: Region<8>, shrink: f64) -> Self {
        let (low, high) = (root.low(), root.high());
        let halving = Halving::new(Region::from_bounds(
            low.fixed_rows::<HALVED>(0).into_owned(),
            high.fixed_rows::<HALVED>(0).into_owned(),
        ));
        let d_boxes = std::array::from_fn(|depth| {
            let factor = shrink.powi(depth as i32);
            (
                low.fixed_rows::<3>(D) * factor,
                high.fixed_rows::<3>(D) * factor,
            )
        });
        Narrowing {
            root,
            halving,
            d_boxes,
        }
    }

    /// Whether the d part of `x` lies in the d box of `depth` (edges included).
    fn d_inside(&self, depth: usize, x: &SVector<f64, 8>) -> bool {
        let (low, high) = &self.d_boxes[depth];
        (0..3).all(|j| low[j] <= x[D + j] && x[D + j] <= high[j])
    }
}

impl BranchRule<8> for Narrowing {
    fn root(&self) -> &Region<8> {
        &self.root
    }

    fn key(&self, x: &SVector<f64, 8>, depth: usize) -> BinKey {
        let reach = (1..=depth).take_while(|&k| self.d_inside(k, x)).count();
        self.halving
            .key(&x.fixed_rows::<HALVED>(0).into_owned(), reach)
    }

    fn child(&self, parent: &Region<8>, child_depth: usize, branch: u8) -> Region<8> {
        let (low, high) = &self.d_boxes[child_depth];
        (0..3).fold(parent.half_at(branch), |region, j| {
            region.with_range(D + j, low[j], high[j])
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The study's branch number for "no child applies".
    const NO_CHILD: u8 = 32;

    /// (θ2, θ3, c) in [0, 8)⁵, d in [−100, 100]³ halving per depth.
    fn rule() -> Narrowing {
        let low = SVector::<f64, 8>::from([0.0, 0.0, 0.0, 0.0, 0.0, -100.0, -100.0, -100.0]);
        let high = SVector::<f64, 8>::from([8.0, 8.0, 8.0, 8.0, 8.0, 100.0, 100.0, 100.0]);
        Narrowing::new(Region::from_bounds(low, high), 0.5)
    }

    /// The study's branch numbers ⟨b₁ … b_D⟩ of `x`: 32 once no child box applies.
    fn numbers(rule: &Narrowing, x: &SVector<f64, 8>, depth: usize) -> Vec<u8> {
        let key = rule.key(x, depth);
        (1..=depth)
            .map(|d| key.branch(d).unwrap_or(NO_CHILD))
            .collect()
    }

    /// A point whose (θ2, θ3, c) lead to branches 22, 4, 7, 13 (0b10110, 0b00100, 0b00111, 0b01101)
    fn point(d: [f64; 3]) -> SVector<f64, 8> {
        SVector::from([1.5, 5.2, 7.9, 0.5, 4.0, d[0], d[1], d[2]])
    }

    #[test]
    fn d_inside_every_narrowed_box_goes_all_the_way_down() {
        let r = rule();
        assert_eq!(numbers(&r, &point([0.0; 3]), 4), [22, 4, 7, 13]);
        // d boxes: ±50 at depth 1, ±25 at 2, ±12.5 at 3, ±6.25 at 4; edges belong to them.
        assert_eq!(numbers(&r, &point([6.25, -6.25, 3.0]), 4), [22, 4, 7, 13]);
    }

    #[test]
    fn a_d_outside_the_next_depths_box_gets_branch_32_from_there_on() {
        let r = rule();
        assert_eq!(numbers(&r, &point([30.0, 0.0, 0.0]), 4), [22, 32, 32, 32]);
        assert_eq!(numbers(&r, &point([0.0, -13.0, 0.0]), 4), [22, 4, 32, 32]);
        assert_eq!(numbers(&r, &point([0.0, 0.0, 6.3]), 4), [22, 4, 7, 32]);
        assert_eq!(numbers(&r, &point([0.0, 0.0, 6.3]), 3), [22, 4, 7]);
        assert_eq!(r.key(&point([0.0, 0.0, 6.3]), 4).reach(), 3);
    }

    #[test]
    fn a_d_outside_the_depth_1_box_has_the_all_32_path() {
        let r = rule();
        for d in [[50.1, 0.0, 0.0], [0.0, 0.0, -99.0], [500.0, 500.0, 500.0]] {
            assert_eq!(numbers(&r, &point(d), 8), [NO_CHILD; 8], "{d:?}");
            assert_eq!(r.key(&point(d), 8).reach(), 0);
        }
        assert_eq!(r.key(&point([f64::NAN, 0.0, 0.0]), 8).reach(), 0);
    }

    #[test]
    fn child_boxes_halve_the_first_five_inputs_and_narrow_d() {
        let r = rule();
        let x = point([1.0, -2.0, 3.0]);
        let key = r.key(&x, 3);
        let mut region = *r.root();
        for depth in 1..=3 {
            region = r.child(&region, depth, key.branch(depth).unwrap());
            let width = 8.0 / f64::from(1 << depth);
            let d_half = 100.0 * 0.5_f64.powi(depth as i32);
            for j in 0..8 {
                let (low, high) = (region.low()[j], region.high()[j]);
                assert!(low <= x[j] && x[j] <= high, "depth {depth}, input {j}");
                let expected = if j < 5 { width } else { 2.0 * d_half };
                assert!(
                    (high - low - expected).abs() < 1e-12,
                    "depth {depth}, input {j}"
                );
            }
            // d = 0 sits in the middle of every d box.
            assert!(region
                .local(&point([0.0; 3]))
                .rows(5, 3)
                .iter()
                .all(|&u| u == 0.0));
        }
    }
}
