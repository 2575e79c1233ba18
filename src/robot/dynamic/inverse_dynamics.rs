//! The joint torques that give the arm a motion: recursive Newton–Euler over the chain,
//! from the model's kinematics and the simulated masses — apart from the physics engine,
//! so the torques a tick's motion took can be read off its change of speed.

use super::builder::{Arm, GRAVITY};
use crate::robot::{ArmModel, Joints};
use nalgebra::{Point3, Vector3};

impl Arm {
    /// The torque about each joint's axis (N·m) that turns the arm of `model` at joint
    /// angles `q` (rad) and speeds `v` (rad/s) with accelerations `a` (rad/s²) under
    /// gravity: everything acting on the joints together (servos, gravity feed-forward,
    /// damping and friction).
    pub(super) fn joint_torques(
        &self,
        model: &ArmModel,
        q: &Joints,
        v: &Joints,
        a: &Joints,
    ) -> Joints {
        let frames = model.link_frames(q);
        let joints = model.joints();
        let n = self.dof;
        let axis = |k: usize| frames[k].rotation * joints[k].axis.into_inner();
        let origin = |k: usize| frames[k].translation.vector;
        // Outwards: each body's spin, angular acceleration and its joint origin's
        // acceleration, gravity as the base accelerating upwards.
        let (mut spin, mut turn) = (Vector3::zeros(), Vector3::<f64>::zeros());
        let mut at_origin = Vector3::new(0.0, 0.0, GRAVITY);
        let mut previous = Vector3::zeros();
        let mut forces = Vec::with_capacity(n);
        for k in 0..n {
            let lever = origin(k) - previous;
            at_origin += turn.cross(&lever) + spin.cross(&spin.cross(&lever));
            let joint_spin = axis(k) * v[k];
            turn += axis(k) * a[k] + spin.cross(&joint_spin);
            spin += joint_spin;
            previous = origin(k);
            let inertial = &self.inertials[k];
            let com = (frames[k] * Point3::from(inertial.com)).coords - origin(k);
            let at_com = at_origin + turn.cross(&com) + spin.cross(&spin.cross(&com));
            let rotation = frames[k].rotation.to_rotation_matrix();
            let tensor = rotation * inertial.tensor * rotation.transpose();
            let force = at_com * inertial.mass;
            let moment = tensor * turn + spin.cross(&(tensor * spin));
            forces.push((force, moment + com.cross(&force)));
        }
        // Inwards: what each joint carries of the bodies beyond it, about its origin.
        let mut torques = Joints::zeros(n);
        let (mut carried, mut carried_moment) = (Vector3::zeros(), Vector3::zeros());
        for k in (0..n).rev() {
            if k + 1 < n {
                carried_moment += (origin(k + 1) - origin(k)).cross(&carried);
            }
            let (force, moment) = forces[k];
            carried += force;
            carried_moment += moment;
            torques[k] = axis(k).dot(&carried_moment);
        }
        torques
    }
}
