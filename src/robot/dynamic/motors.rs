//! The `rapier` engine's tick: Rapier's multibody integrator steps the arm, each joint
//! driven by a Rapier joint motor (acceleration-based, so one gain pair suits every joint:
//! `motor_stiffness` and `motor_damping` toward a position target and a target speed taken
//! from the set-point), its force bounded by the joint's URDF effort less the feed-forward;
//! the set-point's inverse dynamics (weight, Coriolis and centrifugal torques, the joints'
//! damping, the path's acceleration) fed forward as joint torques. Rapier's joint limits,
//! contacts and joint friction act in its step. A tick is `rapier_substeps` Rapier steps,
//! the motors' targets moved along the set-point's path at each; a tick that begins with a
//! link near something takes steps of at most 1 ms with at least 4 solver iterations, the
//! motors holding the arm where it is for the rest of the tick once a contact holds it back
//! from its set-point.

use super::builder::Arm;
use super::integrator::{contact_substeps, CONTACT_ITERATIONS};
use super::servo_law::SetPoint;
use super::settings::DynamicSettings;
use crate::robot::{ArmModel, Joints};
use rapier3d_f64::prelude::{JointAxesMask, JointAxis};

impl SetPoint {
    /// Where the set-point is at the start of the tick of `dt` it ends (rad) and its mean
    /// speed over the tick (rad/s): for set-points sampled along a path every `dt`
    /// (central differences) these are exactly the last sample and the chord to this one.
    fn tick_start(&self, dt: f64) -> (Joints, Joints) {
        let start = self.at(0.0, dt).angles;
        (start, (self.angles - start) / dt)
    }
}

impl Arm {
    /// Steps the arm one tick of `settings.dt` with Rapier, its motors sent to `set_point`
    /// (none: motors off, the arm left to its weight).
    pub(super) fn step_rapier(
        &mut self,
        model: &ArmModel,
        set_point: Option<&SetPoint>,
        settings: &DynamicSettings,
    ) {
        let dt = settings.dt;
        let touching = self.near_contact(dt);
        let substeps = match touching {
            true => settings.rapier_substeps.max(contact_substeps(dt)),
            false => settings.rapier_substeps.max(1),
        };
        let h = dt / substeps as f64;
        self.world.integration_parameters.dt = h;
        if touching {
            self.world.integration_parameters.num_solver_iterations =
                settings.solver_iterations.max(CONTACT_ITERATIONS);
        }
        let path = set_point.map(|set_point| (set_point.tick_start(dt), set_point.accelerations));
        let mut held: Option<SetPoint> = None;
        for j in 0..substeps {
            let aim = match (&path, held) {
                (_, Some(held)) => Some((held.angles, held.speeds, held.accelerations)),
                (Some(((start, speed), accel)), None) => {
                    Some((*start + *speed * (j as f64 * h), *speed, *accel))
                }
                (None, None) => None,
            };
            let tau = match &aim {
                Some((target, speed, accel)) => {
                    let fed = self.feed_forward(model, target, speed, accel);
                    self.drive_motors(model, target, speed, &fed, settings);
                    fed
                }
                None => {
                    self.motors_off();
                    Joints::zeros(self.dof)
                }
            };
            self.apply_joint_torques(model, &tau);
            self.world.step();
            self.depth = self.deepest_contact();
            let along = aim.map(|(angles, ..)| SetPoint::at_rest(angles));
            held = held.or_else(|| self.hold_if_held_back(along.as_ref()));
        }
        self.world.integration_parameters.dt = dt;
        self.world.integration_parameters.num_solver_iterations = settings.solver_iterations;
    }

    /// The torques (N·m) that move the arm along its set-point's path at angles `q`,
    /// speeds `v` and accelerations `a`, each within its joint's URDF effort.
    fn feed_forward(&self, model: &ArmModel, q: &Joints, v: &Joints, a: &Joints) -> Joints {
        let torques = self.placement(model, q).driving_torques(model, v, a);
        let joints = model.joints();
        Joints::from_fn(self.dof, |i| {
            torques[i].clamp(-joints[i].effort, joints[i].effort)
        })
    }

    /// Sends every joint's motor to angle `q` at speed `v`, with the servo gains of
    /// `settings`, its force bounded by the joint's effort less the feed-forward `held`.
    fn drive_motors(
        &mut self,
        model: &ArmModel,
        q: &Joints,
        v: &Joints,
        held: &Joints,
        settings: &DynamicSettings,
    ) {
        let (ids, n) = (self.link_ids, self.dof);
        let (k, c) = (settings.motor_stiffness, settings.motor_damping);
        let mb = self.multibody_mut();
        for (i, joint) in model.joints().iter().enumerate().take(n) {
            if let Some(link) = mb.link_mut(ids[i]) {
                let left = (joint.effort - held[i].abs()).max(0.0);
                link.joint
                    .data
                    .set_motor(JointAxis::AngX, q[i], v[i], k, c)
                    .set_motor_max_force(JointAxis::AngX, left);
            }
        }
    }

    /// Turns every joint's motor off.
    fn motors_off(&mut self) {
        let (ids, n) = (self.link_ids, self.dof);
        let mb = self.multibody_mut();
        for &id in &ids[..n] {
            if let Some(link) = mb.link_mut(id) {
                link.joint.data.motor_axes.remove(JointAxesMask::ANG_X);
            }
        }
    }
}
