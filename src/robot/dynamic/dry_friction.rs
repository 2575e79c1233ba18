//! The joints' dry (Coulomb) friction on the `rk4` engine, and the servos' feed-forward of
//! it. Each joint's URDF `friction` (N·m) resists its motion with at most that torque; over
//! a tick it is an impulse on the joint, bounded by friction × tick, that brings the joint
//! to rest where it can and takes the bound off its speed where it cannot. The impulses of
//! all joints act together through the mass matrix (one joint's friction moves the others)
//! and are found together, exactly: the end speeds of least kinetic energy the bounded
//! impulses allow (MuJoCo's `frictionloss`, solved for the whole chain).

use super::joint_space::{JointSpace, Square};
use crate::robot::{ArmModel, Joints};

/// Sweeps of the projected Gauss–Seidel solve, at most.
const SWEEPS: usize = 200;
/// A sweep that changes no joint's friction by more than this share of its bound ends
/// the solve.
const CONVERGED: f64 = 1e-14;

/// The joints' dry friction fed forward (N·m): each joint's URDF `friction` in the
/// direction `turning` (rad/s) says it turns at the end of the tick, none where it stays
/// still. The friction then takes exactly as much off the joint as the feed-forward puts on
/// (its whole bound, against the motion), and the arm moves as a frictionless one would;
/// without it the servos' spring stalls against the friction short of the set-point (by
/// friction / stiffness, spread over every joint the friction's joint couples to through
/// the mass matrix).
pub(super) fn dry_friction_torques(model: &ArmModel, turning: &Joints) -> Joints {
    Joints::from_fn(turning.len(), |i| {
        let friction = model.joints()[i].friction;
        match turning[i] {
            speed if speed > 0.0 => friction,
            speed if speed < 0.0 => -friction,
            _ => 0.0,
        }
    })
}

impl JointSpace {
    /// The joints' dry friction (N·m) over a tick of `dt` (integrated in `steps` equal
    /// steps) at whose end they turn at `end` under friction `guess`: a torque f held over
    /// the tick, each joint's within ± its `friction`, which changes the end's speeds by
    /// G·(f − guess) to first order (G: [`JointSpace::torque_response`]). f is Coulomb's: a
    /// joint it can hold ends at rest, one it cannot is braked by the whole bound against
    /// its motion — found for all joints together by projected Gauss–Seidel.
    pub(super) fn dry_friction(
        &self,
        model: &ArmModel,
        guess: &Joints,
        end: &Joints,
        dt: f64,
        steps: usize,
    ) -> Joints {
        let n = end.len();
        let bound = Joints::from_fn(n, |i| model.joints()[i].friction);
        let response = self.torque_response(model, dt, steps);
        let column = |i: usize| Joints::from_fn(n, |j| response[(j, i)]);
        let mut friction = *guess;
        let mut end = *end;
        for _ in 0..SWEEPS {
            let mut largest = 0.0f64;
            for i in (0..n).filter(|&i| bound[i] > 0.0) {
                let stopped = friction[i] - end[i] / response[(i, i)];
                let next = stopped.clamp(-bound[i], bound[i]);
                let step = next - friction[i];
                if step != 0.0 {
                    friction[i] = next;
                    end = end + column(i) * step;
                    largest = largest.max(step.abs() / bound[i]);
                }
            }
            if largest <= CONVERGED {
                break;
            }
        }
        friction
    }

    /// How a joint torque held over a tick of `dt` changes the joints' speeds at its end
    /// (G: column j per N·m on joint j), for the equations of motion here with the joints'
    /// damping D: v̇ = M⁻¹·(τ − D·v) from rest, by `steps` equal classical Runge–Kutta
    /// steps (the steps the tick's own integration takes).
    fn torque_response(&self, model: &ArmModel, dt: f64, steps: usize) -> Square {
        let n = self.dof();
        let mut inverse = Square::zeros();
        for i in 0..n {
            let column = self.solve(Joints::from_fn(n, |j| if i == j { 1.0 } else { 0.0 }));
            for j in 0..n {
                inverse[(j, i)] = column[j];
            }
        }
        let mut damped = inverse;
        for (i, joint) in model.joints().iter().enumerate().take(n) {
            damped.column_mut(i).scale_mut(joint.damping);
        }
        let slope = |turned: &Square| inverse - damped * turned;
        let h = dt / steps as f64;
        let mut turned = Square::zeros();
        for _ in 0..steps {
            let a1 = slope(&turned);
            let a2 = slope(&(turned + a1 * (0.5 * h)));
            let a3 = slope(&(turned + a2 * (0.5 * h)));
            let a4 = slope(&(turned + a3 * h));
            turned += (a1 + (a2 + a3) * 2.0 + a4) * (h / 6.0);
        }
        turned
    }
}

#[cfg(test)]
mod tests {
    use super::super::builder::Arm;
    use super::*;
    use crate::robot::{Drive, DynamicSettings, FreeArm};

    /// The OSCAR-6 with dry friction `friction` (N·m) and damping `damping` (N·m·s/rad) on
    /// every joint.
    fn rough_oscar6(friction: f64, damping: f64) -> ArmModel {
        let oscar6 = ArmModel::oscar6();
        let mut joints = oscar6.joints().to_vec();
        for joint in &mut joints {
            joint.friction = friction;
            joint.damping = damping;
        }
        ArmModel::from_parts(
            oscar6.name().to_string(),
            joints,
            oscar6.learned(),
            oscar6.camera_mount(),
            oscar6.links().to_vec(),
        )
        .unwrap()
    }

    /// A slow arm stops; a fast one is braked by every joint's whole friction against its
    /// motion (on an undamped arm G = dt·M⁻¹); what the feed-forward put on, the friction
    /// takes off.
    #[test]
    fn friction_stops_slow_joints_and_brakes_fast_ones() {
        let model = rough_oscar6(0.5, 0.0);
        let arm = Arm::build(&model, &DynamicSettings::default());
        let q = Joints::from_slice(&[0.3, 0.6, 1.2, 0.4, 0.5, 0.2]);
        let still = Joints::zeros(6);
        let space = arm.joint_space(&model, &q, &still).unwrap();
        let dt = 0.005;
        // The speed change a torque held over the tick makes.
        let turned =
            |torque: &Joints| (space.accelerations(torque) - space.accelerations(&still)) * dt;
        let slow = Joints::from_slice(&[1e-4, -2e-4, 1e-4, 3e-4, -1e-4, 2e-4]);
        let held = space.dry_friction(&model, &still, &slow, dt, 1);
        assert!((slow + turned(&held)).amax() < 1e-12, "{held:?}");
        let fast = Joints::from_slice(&[3.0, -3.0, 4.0, 8.0, -8.0, 10.0]);
        let braking = space.dry_friction(&model, &still, &fast, dt, 1);
        for i in 0..6 {
            assert!(
                (braking[i] + 0.5 * fast[i].signum()).abs() < 1e-12,
                "{braking:?}"
            );
        }
        let pushed = fast + turned(&dry_friction_torques(&model, &fast));
        let back = space.dry_friction(&model, &still, &pushed, dt, 1);
        assert!((pushed + turned(&back) - fast).amax() < 1e-9, "{back:?}");
    }

    /// Friction above every torque holds a heavily damped arm where it is (its light wrist
    /// links relax within a fraction of a tick, so the held torque's effect is not that of
    /// a constant acceleration).
    #[test]
    fn friction_holds_a_damped_arm_still() {
        let model = rough_oscar6(1e4, 20.0);
        let q = Joints::from_slice(&[0.3, 0.6, 1.2, 0.4, 0.5, 0.2]);
        let settings = DynamicSettings::default();
        let mut arm = FreeArm::new(model, &q, settings, Drive::Passive, false, false).unwrap();
        while arm.time() < 0.2 {
            arm.step();
        }
        assert!((arm.joints() - q).amax() < 1e-9, "{:?}", arm.joints() - q);
    }
}
