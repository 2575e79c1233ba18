//! The arm's bodies placed in the world at one pose: each joint's axis and origin, each
//! body's centre of mass, mass and inertia tensor, in world axes — what the Newton–Euler
//! pass and the mass matrix both need, worked out once per pose.

use super::builder::Arm;
use crate::robot::{ArmModel, Joints, MAX_JOINTS};
use nalgebra::{Matrix3, Point3, Vector3};

/// The bodies of an arm at one pose, in world axes (body k is joint k's).
#[derive(Debug, Clone)]
pub(super) struct Placement {
    /// How many joints (and bodies).
    pub(super) dof: usize,
    /// Each joint's axis.
    pub(super) axes: [Vector3<f64>; MAX_JOINTS],
    /// Each joint's origin (m).
    pub(super) origins: [Vector3<f64>; MAX_JOINTS],
    /// Each body's centre of mass (m).
    pub(super) coms: [Vector3<f64>; MAX_JOINTS],
    /// Each body's mass (kg).
    pub(super) masses: [f64; MAX_JOINTS],
    /// Each body's inertia tensor about its centre of mass (kg·m²).
    pub(super) tensors: [Matrix3<f64>; MAX_JOINTS],
}

impl Arm {
    /// The bodies of the arm of `model` placed at joint angles `q` (rad).
    pub(super) fn placement(&self, model: &ArmModel, q: &Joints) -> Placement {
        let frames = model.link_frames(q);
        let joints = model.joints();
        let n = self.dof;
        let mut placed = Placement {
            dof: n,
            axes: [Vector3::zeros(); MAX_JOINTS],
            origins: [Vector3::zeros(); MAX_JOINTS],
            coms: [Vector3::zeros(); MAX_JOINTS],
            masses: [0.0; MAX_JOINTS],
            tensors: [Matrix3::zeros(); MAX_JOINTS],
        };
        for k in 0..n {
            let inertial = &self.inertials[k];
            let rotation = frames[k].rotation.to_rotation_matrix();
            placed.axes[k] = rotation * joints[k].axis.into_inner();
            placed.origins[k] = frames[k].translation.vector;
            placed.coms[k] = (frames[k] * Point3::from(inertial.com)).coords;
            placed.masses[k] = inertial.mass;
            placed.tensors[k] = rotation * inertial.tensor * rotation.transpose();
        }
        placed
    }
}
