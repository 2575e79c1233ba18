//! An arm built into a Rapier world: its bodies (the base and one per joint, each with the
//! links merged into it) become rigid bodies with their inertials and colliders, its
//! revolute joints one multibody (reduced coordinates) on a fixed base, each joint with its
//! limits, damping and dry friction; the servos' torques come from servo_law.rs. The camera
//! link rides on the last body.

use super::body_parts::body_parts;
use super::colliders::collider;
use super::contacts::ContactScope;
use super::convert::to_pose;
use super::inertia::Inertial;
use super::seen::compound;
use super::settings::DynamicSettings;
use crate::robot::{ArmModel, Joints, MAX_JOINTS};
use nalgebra::{Isometry3, Unit, UnitQuaternion, Vector3};
use rapier3d_f64::math::Vector;
use rapier3d_f64::prelude::{
    ColliderHandle, GenericJointBuilder, JointAxesMask, JointAxis, MultibodyIndex, PhysicsWorld,
    RigidBodyBuilder, RigidBodyHandle, SharedShape,
};

/// Standard gravity (m/s²), pulling along −z.
pub(super) const GRAVITY: f64 = 9.81;

/// The arm inside its Rapier world.
pub(super) struct Arm {
    /// Bodies, colliders and the multibody.
    pub(super) world: PhysicsWorld,
    /// The arm's multibody.
    pub(super) multibody: MultibodyIndex,
    /// How many joints (and moving bodies) the arm has.
    pub(super) dof: usize,
    /// Multibody link ids of the moving bodies, joint 1's first (the first `dof` are used).
    pub(super) link_ids: [usize; MAX_JOINTS],
    /// Rigid bodies of the base and of each joint's body.
    pub(super) bodies: Vec<RigidBodyHandle>,
    /// Each body's collider, base first (none for a body without collision elements).
    pub(super) colliders: Vec<Option<ColliderHandle>>,
    /// Each body's shape as the camera sees it (meshes as their triangles), base first,
    /// placed where the body's collider is (none for a body without collision elements).
    pub(super) seen: Vec<Option<SharedShape>>,
    /// Mass properties of the moving bodies as simulated (the camera in the last, a
    /// stretched link as stretched, a massless body given [`Inertial::MIN_MASS`]).
    pub(super) inertials: Vec<Inertial>,
    /// Whether the joints stop at their URDF limits.
    pub(super) limited: bool,
    /// Whether a joint has dry friction: the servos feed it forward and the `rk4` engine
    /// solves it with the joints' equations (dry_friction.rs).
    pub(super) dry_friction: bool,
    /// How deep (m) the deepest contact was at the last tick; negative infinity for none:
    /// Rapier steps the tick after a touch (0 or deeper).
    pub(super) depth: f64,
    /// What the links may touch, to look for contacts only near it.
    pub(super) scope: ContactScope,
}

impl std::fmt::Debug for Arm {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Arm")
            .field("link_ids", &&self.link_ids[..self.dof])
            .field("inertials", &self.inertials)
            .finish_non_exhaustive()
    }
}

impl Arm {
    /// The arm of `model` at the zero pose, stepped at `settings`' time step.
    pub(super) fn build(model: &ArmModel, settings: &DynamicSettings) -> Arm {
        let mut world = PhysicsWorld::new();
        world.gravity = Vector::new(0.0, 0.0, -GRAVITY);
        world.integration_parameters.dt = settings.dt;
        world.integration_parameters.num_solver_iterations = settings.solver_iterations;
        // Every contact found anew at every step: Rapier would otherwise keep a pair's
        // contact points, normal and distance while the pair moves less than 5 cm from where
        // they were found, and a link striking something at speed would be stopped at stale
        // points along a stale normal (it whipped the wrist of a camera struck on the base).
        world.integration_parameters.contact_recycling = false;
        let dof = model.dof();
        let frames = model.link_frames(&Joints::zeros(dof));
        let mut bodies = Vec::with_capacity(dof + 1);
        let mut colliders = Vec::with_capacity(dof + 1);
        let mut seen = Vec::with_capacity(dof + 1);
        let mut inertials = Vec::with_capacity(dof);
        for k in 0..=dof {
            let (inertial, elements) = body_parts(model, k);
            let (builder, frame) = match k {
                0 => (RigidBodyBuilder::fixed(), Isometry3::identity()),
                _ => (RigidBodyBuilder::dynamic(), frames[k - 1]),
            };
            let body = world.insert_body(
                builder
                    .pose(to_pose(&frame))
                    .can_sleep(false)
                    .additional_mass_properties(inertial.mass_properties()),
            );
            if k > 0 {
                inertials.push(inertial);
            }
            let own = (!elements.is_empty())
                .then(|| world.insert_collider(collider(&elements), Some(body)));
            bodies.push(body);
            colliders.push(own);
            seen.push((!elements.is_empty()).then(|| compound(&elements)));
        }
        for (i, joint) in model.joints().iter().enumerate() {
            let data = GenericJointBuilder::new(JointAxesMask::LOCKED_REVOLUTE_AXES)
                .local_frame1(to_pose(&joint_frame(&joint.origin, &joint.axis)))
                .local_frame2(to_pose(&joint_frame(&Isometry3::identity(), &joint.axis)))
                .limits(JointAxis::AngX, [joint.lower, joint.upper])
                .contacts_enabled(false);
            world
                .multibody_joints
                .insert(bodies[i], bodies[i + 1], data, true)
                .expect("a serial chain of new bodies has no cycle");
        }
        let link_of = |body| {
            *world
                .multibody_joints
                .rigid_body_link(body)
                .expect("every link body is in the multibody")
        };
        let multibody = link_of(bodies[1]).multibody;
        let mut link_ids = [0; MAX_JOINTS];
        for (i, id) in link_ids.iter_mut().enumerate().take(dof) {
            *id = link_of(bodies[i + 1]).id;
        }
        if let Some(mb) = world.multibody_joints.get_multibody_mut(multibody) {
            // Rapier gives every joint a damping of its own; the URDF's is the one to use,
            // with its dry friction (a torque bound on a zero-speed constraint, on the
            // ticks Rapier steps: every tick on `rapier`, near a contact on `rk4`).
            mb.damping_mut().fill(0.0);
            mb.frictions_mut().fill(0.0);
            for (joint, &id) in model.joints().iter().zip(&link_ids) {
                if let Some(at) = mb.link(id).map(|link| link.assembly_id()) {
                    mb.damping_mut()[at] = joint.damping;
                    mb.frictions_mut()[at] = joint.friction;
                }
            }
        }
        let mut arm = Arm {
            world,
            multibody,
            dof,
            link_ids,
            bodies,
            colliders,
            seen,
            inertials,
            limited: true,
            dry_friction: model.joints().iter().any(|joint| joint.friction > 0.0),
            depth: f64::NEG_INFINITY,
            scope: ContactScope::default(),
        };
        arm.add_world(model, settings.moves.floor_z);
        arm
    }
}

/// A joint's frame in its parent link: the joint origin turned so that its x axis is the
/// joint axis (Rapier's revolute degree of freedom turns about x).
pub(super) fn joint_frame(origin: &Isometry3<f64>, axis: &Unit<Vector3<f64>>) -> Isometry3<f64> {
    let x_to_axis = UnitQuaternion::rotation_between(&Vector3::x(), axis).unwrap_or_else(|| {
        UnitQuaternion::from_axis_angle(&Vector3::z_axis(), std::f64::consts::PI)
    });
    origin * x_to_axis
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn joint_frames_turn_x_onto_the_axis() {
        for axis in [
            Vector3::x_axis(),
            -Vector3::y_axis(),
            Vector3::z_axis(),
            -Vector3::x_axis(),
        ] {
            let frame = joint_frame(&Isometry3::identity(), &axis);
            assert!((frame.rotation * Vector3::x() - axis.into_inner()).norm() < 1e-15);
        }
    }

    #[test]
    fn the_camera_rides_on_link_6() {
        let model = ArmModel::oscar6();
        let arm = Arm::build(&model, &DynamicSettings::default());
        let masses: Vec<f64> = arm.inertials.iter().map(|i| i.mass).collect();
        assert_eq!(masses[..5], [25.0, 17.0, 8.0, 1.5, 1.0]);
        assert!(
            (masses[5] - 0.8).abs() < 1e-12,
            "link 6 and the camera: {masses:?}"
        );
        // The camera's 0.3 kg sits 0.07 m out along the flange (3 cm behind its lens, which
        // looks along the flange), link 6's 0.5 kg at 0.03 m.
        let com = arm.inertials[5].com;
        assert!(
            (com.x - (0.5 * 0.03 + 0.3 * 0.07) / 0.8).abs() < 1e-12,
            "{com}"
        );
        let flange = arm.colliders[6].map(|h| {
            arm.world.colliders[h]
                .shape()
                .as_compound()
                .map(|c| c.shapes().len())
        });
        assert_eq!(flange, Some(Some(2)), "link 6 and the camera collide");
    }
}
