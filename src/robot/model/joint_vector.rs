//! The joint positions of a chain of any length up to [`MAX_JOINTS`], kept in a fixed-size
//! array so that a pose is a plain `Copy` value and hot loops allocate nothing.

use std::ops::{Add, Div, Index, IndexMut, Mul, Sub};

/// The most moving joints a chain may have.
pub const MAX_JOINTS: usize = 10;

/// Every joint position of the chain, joint 1 first (rad). Positions past
/// [`len`](Self::len) are always 0; the default is the empty vector.
#[derive(Clone, Copy, PartialEq, Default)]
pub struct Joints {
    values: [f64; MAX_JOINTS],
    len: usize,
}

impl Joints {
    /// `len` zeros.
    ///
    /// # Panics
    /// When `len` exceeds [`MAX_JOINTS`] (chains are checked against it when built).
    pub fn zeros(len: usize) -> Joints {
        assert!(len <= MAX_JOINTS, "{len} joints: at most {MAX_JOINTS}");
        Joints {
            values: [0.0; MAX_JOINTS],
            len,
        }
    }

    /// The positions in `values`, joint 1 first.
    ///
    /// # Panics
    /// When there are more than [`MAX_JOINTS`].
    pub fn from_slice(values: &[f64]) -> Joints {
        let mut joints = Joints::zeros(values.len());
        joints.values[..values.len()].copy_from_slice(values);
        joints
    }

    /// `len` positions, position i being `f(i)`.
    pub fn from_fn(len: usize, mut f: impl FnMut(usize) -> f64) -> Joints {
        let mut joints = Joints::zeros(len);
        for (i, v) in joints.values[..len].iter_mut().enumerate() {
            *v = f(i);
        }
        joints
    }

    /// How many joints.
    pub fn len(&self) -> usize {
        self.len
    }

    /// True for a chain without joints.
    pub fn is_empty(&self) -> bool {
        self.len == 0
    }

    /// The positions as a slice.
    pub fn as_slice(&self) -> &[f64] {
        &self.values[..self.len]
    }

    /// The positions as a mutable slice.
    pub fn as_mut_slice(&mut self) -> &mut [f64] {
        &mut self.values[..self.len]
    }

    /// The positions in order.
    pub fn iter(&self) -> std::slice::Iter<'_, f64> {
        self.as_slice().iter()
    }

    /// Each position mapped by `f`.
    pub fn map(&self, mut f: impl FnMut(f64) -> f64) -> Joints {
        Joints::from_fn(self.len, |i| f(self.values[i]))
    }

    /// The largest absolute position (0 for no joints).
    pub fn amax(&self) -> f64 {
        self.iter().fold(0.0, |m, v| m.max(v.abs()))
    }
}

impl std::fmt::Debug for Joints {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_list().entries(self.iter()).finish()
    }
}

impl std::fmt::Display for Joints {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        std::fmt::Debug::fmt(self, f)
    }
}

impl Index<usize> for Joints {
    type Output = f64;
    fn index(&self, i: usize) -> &f64 {
        &self.as_slice()[i]
    }
}

impl IndexMut<usize> for Joints {
    fn index_mut(&mut self, i: usize) -> &mut f64 {
        &mut self.as_mut_slice()[i]
    }
}

impl Sub for Joints {
    type Output = Joints;
    /// Position by position; both must have the same length.
    fn sub(self, other: Joints) -> Joints {
        debug_assert_eq!(self.len, other.len, "joint vectors of different lengths");
        Joints::from_fn(self.len, |i| self.values[i] - other.values[i])
    }
}

impl Sub<&Joints> for Joints {
    type Output = Joints;
    fn sub(self, other: &Joints) -> Joints {
        self - *other
    }
}

impl Add for Joints {
    type Output = Joints;
    /// Position by position; both must have the same length.
    fn add(self, other: Joints) -> Joints {
        debug_assert_eq!(self.len, other.len, "joint vectors of different lengths");
        Joints::from_fn(self.len, |i| self.values[i] + other.values[i])
    }
}

impl Mul<f64> for Joints {
    type Output = Joints;
    fn mul(self, factor: f64) -> Joints {
        self.map(|v| v * factor)
    }
}

impl Mul<Joints> for f64 {
    type Output = Joints;
    fn mul(self, joints: Joints) -> Joints {
        joints.map(|v| self * v)
    }
}

impl Div<f64> for Joints {
    type Output = Joints;
    fn div(self, divisor: f64) -> Joints {
        self.map(|v| v / divisor)
    }
}

impl<const N: usize> From<[f64; N]> for Joints {
    fn from(values: [f64; N]) -> Joints {
        Joints::from_slice(&values)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_joint_vector_keeps_its_length_and_values() {
        let q = Joints::from([0.5, -1.0, 2.0]);
        assert_eq!(q.len(), 3);
        assert_eq!(q.as_slice(), &[0.5, -1.0, 2.0]);
        assert_eq!((q - Joints::zeros(3)).amax(), 2.0);
        assert_eq!(q.map(|v| v * 2.0)[1], -2.0);
        assert_ne!(q, Joints::from([0.5, -1.0, 2.0, 0.0]));
        assert_eq!(format!("{q:?}"), "[0.5, -1.0, 2.0]");
    }
}
