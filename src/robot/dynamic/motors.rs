//! The joint servos and sensors of the simulated arm: set-points in, angles and speeds
//! out, and the arm put at a pose at once.

use super::builder::Arm;
use super::settings::DynamicSettings;
use crate::robot::Joints;
use rapier3d_f64::math::Vector;
use rapier3d_f64::prelude::{nalgebra::DVector, JointAxesMask, JointAxis, Multibody};

/// Index of the revolute degree of freedom (`AngX`) in a joint's coordinates.
const ANGLE: usize = 3;

impl Arm {
    fn multibody(&self) -> &Multibody {
        self.world
            .multibody_joints
            .get_multibody(self.multibody)
            .expect("the arm's multibody is never removed")
    }

    fn multibody_mut(&mut self) -> &mut Multibody {
        self.world
            .multibody_joints
            .get_multibody_mut(self.multibody)
            .expect("the arm's multibody is never removed")
    }

    /// The joint sensors: every joint's angle (rad).
    pub(super) fn joints(&self) -> Joints {
        let mb = self.multibody();
        Joints::from_fn(self.dof, |i| {
            mb.link(self.link_ids[i])
                .map_or(0.0, |link| link.joint().coords()[ANGLE])
        })
    }

    /// The joints' speeds (rad/s).
    pub(super) fn speeds(&self) -> Joints {
        let mb = self.multibody();
        Joints::from_fn(self.dof, |i| {
            mb.link(self.link_ids[i])
                .map_or(0.0, |link| mb.joint_velocity(link)[0])
        })
    }

    /// Sets every joint servo's target angle and speed, and the force it may use (N·m).
    pub(super) fn drive(
        &mut self,
        target: &Joints,
        speed: &Joints,
        max_force: &Joints,
        settings: &DynamicSettings,
    ) {
        let (ids, n) = (self.link_ids, self.dof);
        let mb = self.multibody_mut();
        for (i, &id) in ids[..n].iter().enumerate() {
            if let Some(link) = mb.link_mut(id) {
                link.joint
                    .data
                    .set_motor(
                        JointAxis::AngX,
                        target[i],
                        speed[i],
                        settings.motor_stiffness,
                        settings.motor_damping,
                    )
                    .set_motor_max_force(JointAxis::AngX, max_force[i]);
            }
        }
    }

    /// Turns every servo off (no force at all) and the gravity feed-forward with it;
    /// without `limits` the joints turn freely past their URDF limits.
    pub(super) fn release(&mut self, limits: bool) {
        let (ids, n) = (self.link_ids, self.dof);
        let mb = self.multibody_mut();
        for &id in &ids[..n] {
            if let Some(link) = mb.link_mut(id) {
                let joint = &mut link.joint.data;
                joint
                    .set_motor(JointAxis::AngX, 0.0, 0.0, 0.0, 0.0)
                    .set_motor_max_force(JointAxis::AngX, 0.0);
                if !limits {
                    joint.limit_axes.remove(JointAxesMask::ANG_X);
                }
            }
        }
        for &body in &self.bodies[1..] {
            if let Some(rb) = self.world.bodies.get_mut(body) {
                rb.reset_torques(false);
            }
        }
    }

    /// Puts the arm at `q` at rest at once (no physics involved).
    pub(super) fn teleport(&mut self, q: &Joints) {
        let now = self.joints();
        let (ids, n) = (self.link_ids, self.dof);
        let mb = self
            .world
            .multibody_joints
            .get_multibody_mut(self.multibody)
            .expect("the arm's multibody is never removed");
        let mut displacement = DVector::zeros(mb.ndofs());
        for (i, &id) in ids[..n].iter().enumerate() {
            if let Some(link) = mb.link(id) {
                displacement[link.assembly_id()] = q[i] - now[i];
            }
        }
        mb.apply_displacements(displacement.as_slice());
        mb.generalized_velocity_mut().fill(0.0);
        self.refresh_bodies();
        for &body in &self.bodies[1..] {
            if let Some(rb) = self.world.bodies.get_mut(body) {
                rb.set_linvel(Vector::ZERO, false);
                rb.set_angvel(Vector::ZERO, false);
            }
        }
    }

    /// Moves the link bodies to where the multibody's joints put them.
    pub(super) fn refresh_bodies(&mut self) {
        let world = &mut self.world;
        if let Some(mb) = world.multibody_joints.get_multibody_mut(self.multibody) {
            mb.forward_kinematics(&world.bodies, false);
            mb.update_rigid_bodies(&mut world.bodies, true);
        }
    }
}
