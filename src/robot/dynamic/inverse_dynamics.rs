//! The joint torques that give the arm a motion: recursive Newton–Euler over the chain,
//! from the model's kinematics and the simulated masses — apart from the physics engine,
//! so the torques a tick's motion took can be read off its change of speed.

use super::builder::{Arm, GRAVITY};
use super::placement::Placement;
use crate::robot::{ArmModel, Joints, MAX_JOINTS};
use nalgebra::Vector3;

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
        self.placement(model, q).torques(v, a)
    }
}

impl Placement {
    /// The torques (N·m) a motion at speeds `v` (rad/s) and accelerations `a` (rad/s²) of
    /// the bodies placed here needs from the joints' drives: [`torques`](Self::torques)
    /// and what the joints' damping takes at `v`. At `a` zero it is the bias b(q, q̇) of
    /// the equations of motion, M(q)·q̈ + b(q, q̇) = τ.
    pub(super) fn driving_torques(&self, model: &ArmModel, v: &Joints, a: &Joints) -> Joints {
        let mut torques = self.torques(v, a);
        for (i, joint) in model.joints().iter().enumerate().take(self.dof) {
            torques[i] += joint.damping * v[i];
        }
        torques
    }

    /// [`Arm::joint_torques`] for the bodies placed here.
    pub(super) fn torques(&self, v: &Joints, a: &Joints) -> Joints {
        let n = self.dof;
        // Outwards: each body's spin, angular acceleration and its joint origin's
        // acceleration, gravity as the base accelerating upwards.
        let (mut spin, mut turn) = (Vector3::zeros(), Vector3::<f64>::zeros());
        let mut at_origin = Vector3::new(0.0, 0.0, GRAVITY);
        let mut previous = Vector3::zeros();
        let mut forces = [(Vector3::zeros(), Vector3::zeros()); MAX_JOINTS];
        for k in 0..n {
            let (axis, origin) = (self.axes[k], self.origins[k]);
            let lever = origin - previous;
            at_origin += turn.cross(&lever) + spin.cross(&spin.cross(&lever));
            let joint_spin = axis * v[k];
            turn += axis * a[k] + spin.cross(&joint_spin);
            spin += joint_spin;
            previous = origin;
            let com = self.coms[k] - origin;
            let at_com = at_origin + turn.cross(&com) + spin.cross(&spin.cross(&com));
            let tensor = &self.tensors[k];
            let force = at_com * self.masses[k];
            let moment = tensor * turn + spin.cross(&(tensor * spin));
            forces[k] = (force, moment + com.cross(&force));
        }
        // Inwards: what each joint carries of the bodies beyond it, about its origin.
        let mut torques = Joints::zeros(n);
        let (mut carried, mut carried_moment) = (Vector3::zeros(), Vector3::zeros());
        for k in (0..n).rev() {
            if k + 1 < n {
                carried_moment += (self.origins[k + 1] - self.origins[k]).cross(&carried);
            }
            let (force, moment) = forces[k];
            carried += force;
            carried_moment += moment;
            torques[k] = self.axes[k].dot(&carried_moment);
        }
        torques
    }
}
