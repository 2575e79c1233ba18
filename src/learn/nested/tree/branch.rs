//! Branch numbers: how a point finds its path down the tree and its bin.
//!
//! A node has up to [`BRANCHES`] children. The child at branch b = Σ βⱼ·2ʲ covers, in every
//! dimension j, the upper half of its parent's box when βⱼ = 1 and the lower half when
//! βⱼ = 0. A bin is named by the branch numbers ⟨b₁ … b_D⟩ of the finest boxes, packed into a
//! [`BinKey`]. How a point gets its branch numbers is a [`BranchRule`], so learners whose
//! boxes do not simply halve (lin8 narrows its extra dimensions) plug in their own.

use super::Region;
use nalgebra::SVector;

/// Children a node can have: every one of 5 dimensions halved.
pub(crate) const BRANCHES: usize = 32;
/// The deepest tree a [`BinKey`] can name.
pub(crate) const MAX_DEPTH: usize = 12;

const BRANCH_BITS: u32 = 5;
const REACH_BITS: u32 = 4;
const _: () = assert!(REACH_BITS + BRANCH_BITS * MAX_DEPTH as u32 <= u64::BITS);
const _: () = assert!(MAX_DEPTH < 1 << REACH_BITS);

/// `SPREAD[n]`: bit b of the 4-bit `n` moved to bit `BRANCH_BITS · b` — one dimension's
/// bits of four successive depths, where a [`BinKey`] keeps them.
const SPREAD: [u64; 16] = {
    let mut table = [0; 16];
    let mut n = 0;
    while n < 16 {
        let mut b = 0;
        while b < 4 {
            table[n] |= ((n as u64 >> b) & 1) << (BRANCH_BITS * b);
            b += 1;
        }
        n += 1;
    }
    table
};

/// A bin's name: the branch numbers of its path from the root, one per depth, for as many
/// depths as the point has a box (its *reach*; a rule may stop a path early).
///
/// Bits 0–3 hold the reach, then 5 bits per depth, depth 1 first.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Hash)]
pub(crate) struct BinKey(u64);

impl BinKey {
    /// Appends the branch number of the next depth (the tests' way of making keys).
    #[cfg(test)]
    pub(crate) fn push(&mut self, branch: u8) {
        debug_assert!((branch as usize) < BRANCHES && self.reach() < MAX_DEPTH);
        let shift = REACH_BITS + BRANCH_BITS * self.reach() as u32;
        self.0 = (self.0 | u64::from(branch) << shift) + 1;
    }

    /// The key of the path down to `depth` through the finest cells `cells` (one per
    /// dimension, at most 5; each below 2^[`MAX_DEPTH`]): depth d's branch number has, as
    /// its bit j, bit `MAX_DEPTH − d` of `cells[j]`. The same key as pushing each depth's
    /// branch number in turn, packed a dimension at a time (a few table look-ups instead
    /// of a loop over depths).
    pub(crate) fn of_cells(cells: &[u64], depth: usize) -> BinKey {
        debug_assert!(cells.len() <= BRANCH_BITS as usize && depth <= MAX_DEPTH);
        let mut packed = 0;
        for (j, &cell) in cells.iter().enumerate() {
            // Bit d − 1 of `levels` is the cell's bit of depth d.
            let levels = (cell as u16).reverse_bits() >> (u16::BITS as usize - MAX_DEPTH);
            let levels = u64::from(levels) & ((1 << depth) - 1);
            let spread = (0..MAX_DEPTH.div_ceil(4)).fold(0, |spread, nibble| {
                let bits = (levels >> (4 * nibble)) & 0xf;
                spread | SPREAD[bits as usize] << (4 * BRANCH_BITS * nibble as u32)
            });
            packed |= spread << j;
        }
        BinKey(packed << REACH_BITS | depth as u64)
    }

    /// Depths the path goes down.
    pub(crate) fn reach(self) -> usize {
        (self.0 & ((1 << REACH_BITS) - 1)) as usize
    }

    /// The branch number at `depth` (1-based), `None` beyond the reach.
    pub(crate) fn branch(self, depth: usize) -> Option<u8> {
        (depth >= 1 && depth <= self.reach()).then(|| {
            let shift = REACH_BITS + BRANCH_BITS * (depth as u32 - 1);
            ((self.0 >> shift) & ((1 << BRANCH_BITS) - 1)) as u8
        })
    }
}

/// How points and boxes branch: the root box, a point's bin key, a child's box.
pub(crate) trait BranchRule<const N: usize>: std::fmt::Debug {
    /// The box of the root node.
    fn root(&self) -> &Region<N>;

    /// The bin key of `x` down to `depth`. A point outside the root box belongs to the
    /// nearest box, so every point has a path.
    fn key(&self, x: &SVector<f64, N>, depth: usize) -> BinKey;

    /// The box of the child at `branch` of a node with box `parent`; the child is at
    /// `child_depth`.
    fn child(&self, parent: &Region<N>, child_depth: usize, branch: u8) -> Region<N>;
}

/// The plain rule: every dimension halved at every depth (lin5, nnw: 5 inputs, 32 branches).
#[derive(Debug, Clone)]
pub struct Halving<const N: usize> {
    root: Region<N>,
    low: SVector<f64, N>,
    /// Finest cells per unit of input, per dimension, at [`MAX_DEPTH`].
    cells_per_unit: SVector<f64, N>,
}

impl<const N: usize> Halving<N> {
    const FITS: () = assert!(N <= BRANCH_BITS as usize, "a branch number has 5 bits");

    /// Halving boxes from `root` down.
    pub(crate) fn new(root: Region<N>) -> Self {
        let () = Self::FITS;
        let cells = f64::from(1u32 << MAX_DEPTH);
        Halving {
            root,
            low: root.low(),
            cells_per_unit: (root.high() - root.low()).map(|w| cells / w),
        }
    }
}

impl<const N: usize> BranchRule<N> for Halving<N> {
    fn root(&self) -> &Region<N> {
        &self.root
    }

    fn key(&self, x: &SVector<f64, N>, depth: usize) -> BinKey {
        debug_assert!(depth <= MAX_DEPTH);
        // The point's finest cell per dimension; its binary digits are the β's of each depth.
        let last = (1u64 << MAX_DEPTH) - 1;
        let cell: [u64; N] = std::array::from_fn(|j| {
            let c = (x[j] - self.low[j]) * self.cells_per_unit[j];
            // NaN and points below the box go to cell 0; `as` saturates above, and
            // truncates toward zero, which is the floor for c ≥ 0 (no libm call).
            if c >= 0.0 {
                (c as u64).min(last)
            } else {
                0
            }
        });
        BinKey::of_cells(&cell, depth)
    }

    fn child(&self, parent: &Region<N>, _child_depth: usize, branch: u8) -> Region<N> {
        parent.half_at(branch)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::{Rng, SeedableRng};
    use rand_chacha::ChaCha8Rng;

    fn cube(low: f64, high: f64) -> Halving<5> {
        Halving::new(Region::from_bounds(
            SVector::repeat(low),
            SVector::repeat(high),
        ))
    }

    #[test]
    fn keys_pack_and_unpack_every_depth() {
        let mut key = BinKey::default();
        let branches = [31, 0, 17, 5, 31, 1, 2, 30, 9, 11, 12, 31];
        for b in branches {
            key.push(b);
        }
        assert_eq!(key.reach(), MAX_DEPTH);
        for (d, b) in branches.into_iter().enumerate() {
            assert_eq!(key.branch(d + 1), Some(b));
        }
        assert_eq!(key.branch(0), None);
        assert_eq!(key.branch(MAX_DEPTH + 1), None);
    }

    #[test]
    fn keys_of_cells_are_the_keys_pushed_depth_by_depth() {
        let mut rng = ChaCha8Rng::seed_from_u64(3);
        for _ in 0..2000 {
            let cells: [u64; 5] = std::array::from_fn(|_| rng.random_range(0..1 << MAX_DEPTH));
            for depth in 0..=MAX_DEPTH {
                let mut pushed = BinKey::default();
                for d in 1..=depth {
                    let shift = MAX_DEPTH - d;
                    let branch =
                        (0..5).fold(0u8, |b, j| b | (((cells[j] >> shift) & 1) as u8) << j);
                    pushed.push(branch);
                }
                assert_eq!(BinKey::of_cells(&cells, depth), pushed);
            }
        }
    }

    #[test]
    fn branch_numbers_of_a_point_at_each_depth() {
        // Cells of width 1 at depth 3 in [0, 8): the cell indices' bits are the β's.
        let rule = cube(0.0, 8.0);
        let x = SVector::<f64, 5>::from([1.5, 5.2, 7.9, 0.5, 4.0]);
        // cells (1, 5, 7, 0, 4) = binary (001, 101, 111, 000, 100)
        let key = rule.key(&x, 3);
        assert_eq!(key.reach(), 3);
        assert_eq!(key.branch(1), Some(0b10110));
        assert_eq!(key.branch(2), Some(0b00100));
        assert_eq!(key.branch(3), Some(0b00111));
        // The point lies in the box the branches lead to, at every depth.
        let mut region = *rule.root();
        for d in 1..=3 {
            region = rule.child(&region, d, key.branch(d).unwrap());
            assert!(x.iter().zip(region.low().iter()).all(|(x, l)| x >= l));
            assert!(x.iter().zip(region.high().iter()).all(|(x, h)| x < h));
        }
    }

    #[test]
    fn points_outside_the_root_go_to_the_nearest_box() {
        let rule = cube(-1.0, 1.0);
        let x = SVector::<f64, 5>::from([-5.0, 5.0, f64::NAN, f64::INFINITY, 0.1]);
        let key = rule.key(&x, 4);
        // dim 0 lowest cell, dim 1 highest, NaN lowest, +∞ highest, 0.1 upper then lower.
        assert_eq!(key.branch(1), Some(0b11010));
        assert_eq!(key.branch(2), Some(0b01010));
        assert_eq!(key.branch(4), Some(0b01010));
    }
}
