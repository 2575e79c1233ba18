//! The world poses of a chain's joint frames, one per moving joint, in a fixed-size array.

use super::joint_vector::MAX_JOINTS;
use nalgebra::Isometry3;
use std::ops::Index;

/// The pose of every joint frame (the child link's frame) in the world, joint 1 first.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Frames {
    frames: [Isometry3<f64>; MAX_JOINTS],
    len: usize,
}

impl Frames {
    /// `len` identity frames.
    pub(crate) fn identities(len: usize) -> Frames {
        Frames {
            frames: [Isometry3::identity(); MAX_JOINTS],
            len,
        }
    }

    /// How many frames.
    pub fn len(&self) -> usize {
        self.len
    }

    /// True for a chain without joints.
    pub fn is_empty(&self) -> bool {
        self.len == 0
    }

    /// The frames in order.
    pub fn iter(&self) -> std::slice::Iter<'_, Isometry3<f64>> {
        self.frames[..self.len].iter()
    }

    /// The last frame (the flange), or the identity for a chain without joints.
    pub fn last(&self) -> Isometry3<f64> {
        self.iter()
            .last()
            .copied()
            .unwrap_or_else(Isometry3::identity)
    }

    pub(crate) fn set(&mut self, i: usize, frame: Isometry3<f64>) {
        self.frames[i] = frame;
    }
}

impl Index<usize> for Frames {
    type Output = Isometry3<f64>;
    fn index(&self, i: usize) -> &Isometry3<f64> {
        &self.frames[..self.len][i]
    }
}

impl<'a> IntoIterator for &'a Frames {
    type Item = &'a Isometry3<f64>;
    type IntoIter = std::slice::Iter<'a, Isometry3<f64>>;
    fn into_iter(self) -> Self::IntoIter {
        self.iter()
    }
}
