//! How the camera centre moves with the learned joints while a two-joint numerical wrist
//! keeps the optical axis straight down.

use super::look_down::tilting;
use super::Wrist;
use crate::robot::model::{ArmModel, Joints, MAX_JOINTS};
use nalgebra::{Isometry3, Matrix2, Matrix2x3, Matrix3, Vector3};

impl ArmModel {
    /// ∂(camera centre)/∂(θ1, θ2, θ3) at `q` with a two-joint numerical wrist keeping the
    /// optical axis down (by the implicit function theorem, from one pass down the chain);
    /// `None` for other wrists or where the wrist is singular.
    pub(crate) fn followed_jacobian(&self, q: &Joints) -> Option<Matrix3<f64>> {
        let Wrist::Numerical { joints, count: 2 } = self.wrist else {
            return None;
        };
        let mut pose = Isometry3::identity();
        let mut axes = [Vector3::zeros(); MAX_JOINTS];
        let mut origins = [Vector3::zeros(); MAX_JOINTS];
        for (k, joint) in self.joints.iter().enumerate() {
            pose *= joint.transform(q[k]);
            axes[k] = pose.rotation * joint.axis.into_inner();
            origins[k] = pose.translation.vector;
        }
        let camera = pose * self.unturned_mount();
        let p = camera.translation.vector;
        let optical = camera.rotation * Vector3::z();
        // For joint k: how it moves the camera centre, and how it tilts the optical axis
        // (its horizontal part: the axis is vertical here).
        let moves = |k: usize| axes[k].cross(&(p - origins[k]));
        let tilts = |k: usize| tilting(&axes[k], &optical);
        let wrist_tilts = Matrix2::from_fn(|r, c| tilts(joints[c])[r]);
        let learned_tilts = Matrix2x3::from_fn(|r, c| tilts(self.learned[c])[r]);
        let follow = wrist_tilts.lu().solve(&learned_tilts)?;
        let wrist_moves = Matrix3::from_fn(|r, c| if c < 2 { moves(joints[c])[r] } else { 0.0 });
        let learned_moves = Matrix3::from_fn(|r, c| moves(self.learned[c])[r]);
        let follow = Matrix3::from_fn(|r, c| if r < 2 { follow[(r, c)] } else { 0.0 });
        Some(learned_moves - wrist_moves * follow)
    }
}
