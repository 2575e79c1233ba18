//! One tick of the arm on its engine; on `rk4` (motors.rs has `rapier`'s): its joint-space
//! equations integrated over the tick by the classical
//! fourth-order Runge–Kutta scheme under joint torques held over it (the servos', or none),
//! the joint limits as stops; the bodies are then placed where the model's kinematics puts
//! them (for the camera), and Rapier looks for contacts where a bounding box comes near
//! something (contacts.rs). Where a joint has dry friction, the tick is integrated again
//! under the friction the joints’ equations give it (dry_friction.rs); while a
//! link is near something (within 5 mm, on top of how far the joints' speeds could close
//! the gap in a tick: contacts.rs), Rapier steps it in sub-ticks of at most 1 ms with at least 4
//! solver iterations, the servo law run at each (its contact constraints act there), the
//! servos holding the arm where it is for the rest of the tick once a contact holds it
//! back from its set-point.

use super::builder::Arm;
use super::convert::to_vector;
use super::joint_space::JointSpace;
use super::servo_law::SetPoint;
use super::settings::{DynamicSettings, Engine};
use crate::robot::{ArmModel, Joints};

/// The largest rate × step a damped joint's relaxation may have in one Runge–Kutta step
/// (the scheme is stable below 2.78; this also keeps its decay close).
const STABLE_RATE_STEP: f64 = 1.5;
/// The longest step (s) Rapier takes while a link is near something: a tick is cut into
/// sub-ticks no longer than this.
const CONTACT_STEP: f64 = 1e-3;
/// How many times a tick with dry friction is integrated again under the friction found
/// from the last pass's end (integrator.rs `braked`).
const FRICTION_PASSES: usize = 2;
/// Rapier's constraint solver iterations, at least, while a link is near something: with
/// one, a struck link's contacts and the servos holding the arm against them do not
/// agree, and the arm chatters where it rests on something.
pub(super) const CONTACT_ITERATIONS: usize = 4;

/// Rapier steps in a tick of `dt` while a link is near something.
pub(super) fn contact_substeps(dt: f64) -> usize {
    (dt / CONTACT_STEP).ceil().max(1.0) as usize
}

/// The Runge–Kutta steps a tick of `dt` takes from equations of motion `start`: one, or as
/// many as the joints' damping needs to stay stable (a damped light link relaxes faster
/// than a tick: its rate d/I is bounded by the damping's share of M⁻¹).
fn runge_kutta_steps(model: &ArmModel, start: &JointSpace, dt: f64) -> usize {
    (start.damping_rate(model) * dt / STABLE_RATE_STEP)
        .ceil()
        .max(1.0) as usize
}

impl Arm {
    /// Steps the arm one tick of `settings.dt` on the settings' engine, its servos sent to
    /// `set_point` (none: the servos off, the arm left to its weight).
    pub(super) fn step(
        &mut self,
        model: &ArmModel,
        set_point: Option<&SetPoint>,
        settings: &DynamicSettings,
    ) {
        match settings.engine {
            Engine::Rk4 => self.step_rk4(model, set_point, settings),
            Engine::Rapier => self.step_rapier(model, set_point, settings),
        }
    }

    /// One tick of the `rk4` engine.
    fn step_rk4(
        &mut self,
        model: &ArmModel,
        set_point: Option<&SetPoint>,
        settings: &DynamicSettings,
    ) {
        if self.near_contact(settings.dt) {
            return self.step_in_contact(model, set_point, settings);
        }
        let (q, v) = (self.joints(), self.speeds());
        let space = self.joint_space(model, &q, &v);
        let tau = match (&space, set_point) {
            (Some(space), Some(set_point)) => {
                self.servo_torques(model, space, set_point, &q, &v, settings)
            }
            _ => Joints::zeros(self.dof),
        };
        let integrated = match space {
            Some(space) if self.depth < 0.0 => {
                let start = self.dry_friction.then(|| space.clone());
                let free = self.integrate(model, space, &q, &v, &tau, settings.dt);
                match (free, start) {
                    (Some(free), Some(start)) => {
                        self.braked(model, start, (&q, &v), &tau, free, settings.dt)
                    }
                    (free, _) => free,
                }
            }
            _ => None,
        };
        match integrated {
            Some((q, v)) => {
                self.set_coordinates(&q, &v);
                self.place_bodies(&model.link_frames(&q));
                if self.may_touch() {
                    self.world.detect_collisions(&(), &());
                    self.depth = self.deepest_contact();
                } else {
                    self.depth = f64::NEG_INFINITY;
                }
            }
            None => {
                self.refresh_bodies();
                self.apply_joint_torques(model, &tau);
                self.world.step();
                self.depth = self.deepest_contact();
            }
        }
    }

    /// A tick of the `rk4` engine while a link touches something: Rapier steps it in
    /// sub-ticks of at most [`CONTACT_STEP`], the servo law run at each toward the
    /// set-point's path there, so that a servo pushing against a contact cannot whip a
    /// light joint around within a tick.
    fn step_in_contact(
        &mut self,
        model: &ArmModel,
        set_point: Option<&SetPoint>,
        settings: &DynamicSettings,
    ) {
        let (dt, n) = (settings.dt, contact_substeps(settings.dt));
        let fine = DynamicSettings {
            dt: dt / n as f64,
            ..*settings
        };
        self.world.integration_parameters.dt = fine.dt;
        self.world.integration_parameters.num_solver_iterations =
            settings.solver_iterations.max(CONTACT_ITERATIONS);
        self.refresh_bodies();
        let mut held = None;
        for j in 1..=n {
            let (q, v) = (self.joints(), self.speeds());
            let along =
                set_point.map(|set_point| held.unwrap_or(set_point.at(j as f64 * fine.dt, dt)));
            let tau = match (self.joint_space(model, &q, &v), along) {
                (Some(space), Some(along)) => {
                    self.servo_torques(model, &space, &along, &q, &v, &fine)
                }
                _ => Joints::zeros(self.dof),
            };
            self.apply_joint_torques(model, &tau);
            self.world.step();
            self.depth = self.deepest_contact();
            held = held.or_else(|| self.hold_if_held_back(along.as_ref()));
        }
        self.world.integration_parameters.dt = dt;
        self.world.integration_parameters.num_solver_iterations = settings.solver_iterations;
    }

    /// Where the servos hold the arm for the rest of a tick once a contact holds it back
    /// from `set_point` within the tick ([`Arm::held_back`]): at rest where it is, so that
    /// they do not press it on into the contact; none while it is not held back.
    pub(super) fn hold_if_held_back(&self, set_point: Option<&SetPoint>) -> Option<SetPoint> {
        set_point
            .filter(|set_point| self.held_back(&set_point.angles))
            .map(|_| SetPoint::at_rest(self.joints()))
    }

    /// The angles and speeds after `dt` from `q`, `v` under torques `tau`, where the
    /// equations of motion are `start`: one Runge–Kutta step, or as many equal ones as
    /// the joints' damping needs to stay stable (a damped light link relaxes faster than
    /// a tick: its rate d/I is bounded by the damping's share of M⁻¹); none when the
    /// equations fail on the way.
    fn integrate(
        &self,
        model: &ArmModel,
        start: JointSpace,
        q: &Joints,
        v: &Joints,
        tau: &Joints,
        dt: f64,
    ) -> Option<(Joints, Joints)> {
        let steps = runge_kutta_steps(model, &start, dt);
        let h = dt / steps as f64;
        let mut state = self.runge_kutta(model, start, q, v, tau, h)?;
        for _ in 1..steps {
            let space = self.joint_space(model, &state.0, &state.1)?;
            state = self.runge_kutta(model, space, &state.0, &state.1, tau, h)?;
        }
        Some(state)
    }

    /// The angles and speeds after one classical Runge–Kutta step of `dt`; none when they
    /// are not finite (Rapier then steps the tick).
    fn runge_kutta(
        &self,
        model: &ArmModel,
        start: JointSpace,
        q: &Joints,
        v: &Joints,
        tau: &Joints,
        dt: f64,
    ) -> Option<(Joints, Joints)> {
        let accelerations = |q: &Joints, v: &Joints| {
            self.joint_space(model, q, v)
                .map(|space| space.accelerations(tau))
        };
        let (q, v) = (*q, *v);
        let a1 = start.accelerations(tau);
        let (q2, v2) = (q + v * (0.5 * dt), v + a1 * (0.5 * dt));
        let a2 = accelerations(&q2, &v2)?;
        let (q3, v3) = (q + v2 * (0.5 * dt), v + a2 * (0.5 * dt));
        let a3 = accelerations(&q3, &v3)?;
        let (q4, v4) = (q + v3 * dt, v + a3 * dt);
        let a4 = accelerations(&q4, &v4)?;
        let sixth = dt / 6.0;
        let q_end = q + (v + 2.0 * v2 + 2.0 * v3 + v4) * sixth;
        let v_end = v + (a1 + 2.0 * a2 + 2.0 * a3 + a4) * sixth;
        let finite = q_end.iter().chain(v_end.iter()).all(|x| x.is_finite());
        finite.then(|| self.stopped_at_limits(model, q_end, v_end))
    }

    /// The tick of `dt` from angles and speeds `from` under torques `tau`, whose equations
    /// of motion are `start`, with the joints' dry friction: `free` is where it ends
    /// without. The friction is found from the end's speeds (dry_friction.rs) and the tick
    /// integrated again under it, [`FRICTION_PASSES`] times: each pass corrects the last
    /// one's friction for what the first-order response missed (the free motion's own
    /// Coriolis torques, say), so that a joint the friction holds stays put.
    fn braked(
        &self,
        model: &ArmModel,
        start: JointSpace,
        from: (&Joints, &Joints),
        tau: &Joints,
        free: (Joints, Joints),
        dt: f64,
    ) -> Option<(Joints, Joints)> {
        let steps = runge_kutta_steps(model, &start, dt);
        let mut friction = Joints::zeros(self.dof);
        let mut state = free;
        for _ in 0..FRICTION_PASSES {
            friction = start.dry_friction(model, &friction, &state.1, dt, steps);
            let (q, v) = from;
            state = self.integrate(model, start.clone(), q, v, &(*tau + friction), dt)?;
        }
        Some(state)
    }

    /// `q`, `v` with every joint past a limit (while the limits apply) put on it, its
    /// speed out of the limit stopped.
    fn stopped_at_limits(
        &self,
        model: &ArmModel,
        mut q: Joints,
        mut v: Joints,
    ) -> (Joints, Joints) {
        if !self.limited {
            return (q, v);
        }
        for (i, joint) in model.joints().iter().enumerate() {
            if q[i] < joint.lower {
                q[i] = joint.lower;
                v[i] = v[i].max(0.0);
            } else if q[i] > joint.upper {
                q[i] = joint.upper;
                v[i] = v[i].min(0.0);
            }
        }
        (q, v)
    }

    /// Applies joint torques `tau` (N·m) to the bodies for Rapier's step: each acts on the
    /// two bodies its joint connects, equal and opposite.
    pub(super) fn apply_joint_torques(&mut self, model: &ArmModel, tau: &Joints) {
        let n = self.dof;
        let frames = model.link_frames(&self.joints());
        let axis = |k: usize| frames[k].rotation * model.joints()[k].axis.into_inner();
        for k in 0..n {
            let mut torque = axis(k) * tau[k];
            if k + 1 < n {
                torque -= axis(k + 1) * tau[k + 1];
            }
            if let Some(rb) = self.world.bodies.get_mut(self.bodies[k + 1]) {
                rb.reset_torques(false);
                rb.add_torque(to_vector(&torque), false);
            }
        }
    }
}
