//! Input scaling of a network: each input mapped from its box [low, high] onto [−1, 1].

use nalgebra::SVector;

/// Maps inputs from their boxes onto [−1, 1].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct InputScaling<const I: usize> {
    centre: SVector<f64, I>,
    inverse_half_width: SVector<f64, I>,
}

impl<const I: usize> InputScaling<I> {
    /// The scaling for inputs in the boxes `bounds[i] = (low, high)`, low < high.
    pub fn new(bounds: [(f64, f64); I]) -> Self {
        InputScaling {
            centre: SVector::from_fn(|i, _| 0.5 * (bounds[i].0 + bounds[i].1)),
            inverse_half_width: SVector::from_fn(|i, _| 2.0 / (bounds[i].1 - bounds[i].0)),
        }
    }

    /// `x` scaled.
    pub fn apply(&self, x: &SVector<f64, I>) -> SVector<f64, I> {
        (x - self.centre).component_mul(&self.inverse_half_width)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::Vector2;

    #[test]
    fn box_ends_map_to_plus_minus_one() {
        let s = InputScaling::new([(-10.0, 80.0), (40.0, 145.0)]);
        assert_eq!(
            s.apply(&Vector2::new(-10.0, 145.0)),
            Vector2::new(-1.0, 1.0)
        );
        assert_eq!(s.apply(&Vector2::new(35.0, 92.5)), Vector2::new(0.0, 0.0));
    }
}
