//! The arm's mechanical energy at a pose and speed: each body's kinetic energy (its centre
//! of mass's speed and its spin, from the joints' axes and speeds) and its weight's
//! potential energy, from the model's kinematics and the masses as simulated — apart from
//! the physics engine, so it can hold the engine's integration to account.

use super::builder::{Arm, GRAVITY};
use crate::robot::{ArmModel, Joints};
use nalgebra::{Point3, Vector3};

/// Mechanical energy of the arm (J).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Energy {
    /// Kinetic energy of the moving bodies.
    pub kinetic: f64,
    /// Potential energy of their weight, zero at the world's z = 0.
    pub potential: f64,
}

impl Energy {
    /// Kinetic and potential energy together.
    pub fn total(&self) -> f64 {
        self.kinetic + self.potential
    }
}

impl Arm {
    /// The energy of the arm of `model` at joint angles `q` (rad) turning at `v` (rad/s).
    pub(super) fn energy(&self, model: &ArmModel, q: &Joints, v: &Joints) -> Energy {
        let frames = model.link_frames(q);
        let joints = model.joints();
        let n = self.dof;
        let mut energy = Energy {
            kinetic: 0.0,
            potential: 0.0,
        };
        // The spin of body k and, to reach its centre of mass, the joints' axes and origins.
        let mut spin = Vector3::zeros();
        for k in 0..n {
            let axis = frames[k].rotation * joints[k].axis.into_inner();
            spin += axis * v[k];
            let inertial = &self.inertials[k];
            let com = frames[k] * Point3::from(inertial.com);
            let speed: Vector3<f64> = (0..=k)
                .map(|j| {
                    let axis_j = frames[j].rotation * joints[j].axis.into_inner();
                    axis_j.cross(&(com.coords - frames[j].translation.vector)) * v[j]
                })
                .sum();
            let rotation = frames[k].rotation.to_rotation_matrix();
            let tensor = rotation * inertial.tensor * rotation.transpose();
            energy.kinetic +=
                0.5 * inertial.mass * speed.norm_squared() + 0.5 * spin.dot(&(tensor * spin));
            energy.potential += inertial.mass * GRAVITY * com.z;
        }
        energy
    }
}
