//! The joint sensors of the simulated arm: angles and speeds out; the servos turned off,
//! and the arm put at a pose at once.

use super::builder::Arm;
use super::convert::to_pose;
use crate::robot::{Frames, Joints, MAX_JOINTS};
use rapier3d_f64::math::Vector;
use rapier3d_f64::prelude::{JointAxesMask, Multibody};

/// The most degrees of freedom of the arm's multibody: its joints', after the six of a
/// free root, which Rapier numbers first.
const MAX_DOFS: usize = MAX_JOINTS + 6;

/// Index of the revolute degree of freedom (`AngX`) in a joint's coordinates.
const ANGLE: usize = 3;

impl Arm {
    fn multibody(&self) -> &Multibody {
        self.world
            .multibody_joints
            .get_multibody(self.multibody)
            .expect("the arm's multibody is never removed")
    }

    pub(super) fn multibody_mut(&mut self) -> &mut Multibody {
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

    /// Turns the servos off (no torque left on the bodies); without `limits` the joints
    /// turn freely past their URDF limits.
    pub(super) fn release(&mut self, limits: bool) {
        self.set_limited(limits);
        for &body in &self.bodies[1..] {
            if let Some(rb) = self.world.bodies.get_mut(body) {
                rb.reset_torques(false);
            }
        }
    }

    /// Puts the arm at `q` at rest at once (no physics involved).
    pub(super) fn teleport(&mut self, q: &Joints) {
        self.set_coordinates(q, &Joints::zeros(self.dof));
        self.refresh_bodies();
        for &body in &self.bodies[1..] {
            if let Some(rb) = self.world.bodies.get_mut(body) {
                rb.set_linvel(Vector::ZERO, false);
                rb.set_angvel(Vector::ZERO, false);
            }
        }
    }

    /// Sets the multibody's joints to angles `q` turning at `v` (its bodies are placed by
    /// [`refresh_bodies`](Self::refresh_bodies) or [`place_bodies`](Self::place_bodies)).
    pub(super) fn set_coordinates(&mut self, q: &Joints, v: &Joints) {
        let now = self.joints();
        let (ids, n) = (self.link_ids, self.dof);
        let mb = self.multibody_mut();
        let mut displacement = [0.0; MAX_DOFS];
        let mut speeds = [0.0; MAX_DOFS];
        for (i, &id) in ids[..n].iter().enumerate() {
            if let Some(link) = mb.link(id) {
                displacement[link.assembly_id()] = q[i] - now[i];
                speeds[link.assembly_id()] = v[i];
            }
        }
        let dofs = mb.ndofs();
        mb.apply_displacements(&displacement[..dofs]);
        let mut velocity = mb.generalized_velocity_mut();
        for (at, speed) in speeds[..dofs].iter().enumerate() {
            velocity[at] = *speed;
        }
    }

    /// Lets the joints turn past their URDF limits (or not).
    pub(super) fn set_limited(&mut self, limited: bool) {
        self.limited = limited;
        if limited {
            return;
        }
        let (ids, n) = (self.link_ids, self.dof);
        let mb = self.multibody_mut();
        for &id in &ids[..n] {
            if let Some(link) = mb.link_mut(id) {
                link.joint.data.limit_axes.remove(JointAxesMask::ANG_X);
            }
        }
    }

    /// Moves the link bodies to where the multibody's joints put them (Rapier's own
    /// kinematics, which its step needs), and their colliders with them.
    pub(super) fn refresh_bodies(&mut self) {
        let world = &mut self.world;
        if let Some(mb) = world.multibody_joints.get_multibody_mut(self.multibody) {
            mb.forward_kinematics(&world.bodies, false);
            mb.update_rigid_bodies(&mut world.bodies, true);
        }
        self.move_colliders();
    }

    /// Puts each link body at its link's pose in `frames` (the model's kinematics at the
    /// multibody's angles), and its collider with it.
    pub(super) fn place_bodies(&mut self, frames: &Frames) {
        for (k, &body) in self.bodies.iter().enumerate().skip(1) {
            if let Some(rb) = self.world.bodies.get_mut(body) {
                rb.set_position(to_pose(&frames[k - 1]), false);
            }
        }
        self.move_colliders();
    }

    /// Puts every link's collider where its body is.
    fn move_colliders(&mut self) {
        let world = &mut self.world;
        for (&body, collider) in self.bodies.iter().zip(&self.colliders).skip(1) {
            let (Some(rb), Some(handle)) = (world.bodies.get(body), collider) else {
                continue;
            };
            let pose = *rb.position();
            if let Some(co) = world.colliders.get_mut(*handle) {
                let offset = co.position_wrt_parent().copied().unwrap_or_default();
                co.set_position(pose * offset);
            }
        }
    }
}
