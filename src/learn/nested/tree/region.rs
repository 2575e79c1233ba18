//! Boxes of the input space: a node's region, its local coordinates and its halves.

use nalgebra::SVector;

/// The inputs that are joint angles; the others (camera readings and, for lin8, the
/// readings after the move) are zero in a known pattern.
pub(crate) const JOINT_INPUTS: usize = 2;

/// An axis-aligned box of the `N`-dimensional input space, kept as centre and half-widths.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Region<const N: usize> {
    centre: SVector<f64, N>,
    half: SVector<f64, N>,
    inv_half: SVector<f64, N>,
}

impl<const N: usize> Region<N> {
    /// The box `low ≤ x ≤ high`; every `high` must be above its `low`.
    pub(crate) fn from_bounds(low: SVector<f64, N>, high: SVector<f64, N>) -> Self {
        debug_assert!(low.iter().zip(high.iter()).all(|(l, h)| l < h));
        Self::from_centre(0.5 * (low + high), 0.5 * (high - low))
    }

    fn from_centre(centre: SVector<f64, N>, half: SVector<f64, N>) -> Self {
        Region {
            centre,
            half,
            inv_half: half.map(f64::recip),
        }
    }

    /// The lower corner.
    pub(crate) fn low(&self) -> SVector<f64, N> {
        self.centre - self.half
    }

    /// The upper corner.
    pub(crate) fn high(&self) -> SVector<f64, N> {
        self.centre + self.half
    }

    /// `x` in this box's local coordinates: the box maps to [−1, 1] in every dimension.
    /// Models fitted in local coordinates stay well conditioned however small the box.
    pub(crate) fn local(&self, x: &SVector<f64, N>) -> SVector<f64, N> {
        (x - self.centre).component_mul(&self.inv_half)
    }

    /// The half of this box at `branch` (bit j set: upper half of dimension j).
    pub(crate) fn half_at(&self, branch: u8) -> Self {
        let quarter = 0.5 * self.half;
        let centre = SVector::<f64, N>::from_fn(|j, _| {
            let sign = if branch >> j & 1 == 1 { 1.0 } else { -1.0 };
            self.centre[j] + sign * quarter[j]
        });
        Self::from_centre(centre, quarter)
    }

    /// This box with dimension `j` spanning `low ≤ x ≤ high` instead (`low < high`).
    pub(crate) fn with_range(&self, j: usize, low: f64, high: f64) -> Self {
        debug_assert!(low < high);
        let mut centre = self.centre;
        let mut half = self.half;
        centre[j] = 0.5 * (low + high);
        half[j] = 0.5 * (high - low);
        Self::from_centre(centre, half)
    }

    /// Where a known pattern lies in local coordinates — joint inputs still to be drawn
    /// (left at 0), every other input at 0 in global terms — or `None` when that point is
    /// outside this box, so that known patterns would make the node extrapolate.
    pub(crate) fn known_anchor(&self) -> Option<SVector<f64, N>> {
        let mut anchor = self.local(&SVector::zeros());
        anchor.rows_mut(0, JOINT_INPUTS).fill(0.0);
        anchor.iter().all(|u| u.abs() <= 1.0).then_some(anchor)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::Vector2;

    #[test]
    fn local_coordinates_map_the_box_to_the_unit_box() {
        let r = Region::from_bounds(Vector2::new(-2.0, 10.0), Vector2::new(6.0, 12.0));
        assert_eq!(r.local(&Vector2::new(-2.0, 10.0)), Vector2::new(-1.0, -1.0));
        assert_eq!(r.local(&Vector2::new(6.0, 12.0)), Vector2::new(1.0, 1.0));
        assert_eq!(r.local(&Vector2::new(2.0, 11.5)), Vector2::new(0.0, 0.5));
    }

    #[test]
    fn halves_split_every_dimension_in_the_middle() {
        let r = Region::from_bounds(Vector2::new(0.0, 0.0), Vector2::new(8.0, 4.0));
        let upper_x = r.half_at(0b01);
        assert_eq!(upper_x.low(), Vector2::new(4.0, 0.0));
        assert_eq!(upper_x.high(), Vector2::new(8.0, 2.0));
        let upper_y = r.half_at(0b10);
        assert_eq!(upper_y.low(), Vector2::new(0.0, 2.0));
        assert_eq!(upper_y.high(), Vector2::new(4.0, 4.0));
    }

    #[test]
    fn known_anchor_exists_only_where_the_camera_zero_is_inside() {
        let low = SVector::<f64, 3>::new(0.0, 0.0, -200.0);
        let high = SVector::<f64, 3>::new(10.0, 10.0, 100.0);
        let root = Region::from_bounds(low, high);
        let anchor = root.known_anchor().expect("0 is inside the root");
        assert_eq!(anchor[0], 0.0);
        assert!((anchor[2] - (200.0 / 150.0 - 1.0)).abs() < 1e-12);
        // The lower camera half is [−200, −50]: zero is outside.
        assert_eq!(root.half_at(0b000).known_anchor(), None);
        assert!(root.half_at(0b100).known_anchor().is_some());
    }
}
