//! The joint servos' law of the `rk4` engine, one tick at a time: a stiff spring and
//! damper on each joint toward its set-point, the set-point's acceleration fed forward,
//! made joint torques through the arm's mass matrix (so one gain pair suits a 25 kg column
//! and a 0.8 kg flange), plus the whole bias of the equations of motion at the set-point
//! (weight, Coriolis and centrifugal torques, the joints' damping) fed forward, all within
//! each joint's URDF effort. The torques are held over the tick, as a digital servo holds
//! its output; the law is simple enough for another engine to replay exactly
//! (tools/mujoco_reference.py).

use super::builder::Arm;
use super::dry_friction::dry_friction_torques;
use super::joint_space::JointSpace;
use super::settings::DynamicSettings;
use crate::robot::{ArmModel, Joints};

/// Where the servos are sent over one tick: the set-point at the tick's end, its speed and
/// its acceleration there.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct SetPoint {
    /// Every joint's angle (rad).
    pub(super) angles: Joints,
    /// Their speeds (rad/s).
    pub(super) speeds: Joints,
    /// Their accelerations (rad/s²).
    pub(super) accelerations: Joints,
}

impl SetPoint {
    /// Held still at `angles`.
    pub(super) fn at_rest(angles: Joints) -> SetPoint {
        let still = Joints::zeros(angles.len());
        SetPoint {
            angles,
            speeds: still,
            accelerations: still,
        }
    }

    /// This set-point, which a tick of `dt` ends at, `t` into that tick (at `t` = `dt`
    /// itself), along the path of constant acceleration its angles, speeds and
    /// accelerations at the tick's end give.
    pub(super) fn at(&self, t: f64, dt: f64) -> SetPoint {
        let back = dt - t;
        SetPoint {
            angles: self.angles - self.speeds * back + self.accelerations * (0.5 * back * back),
            speeds: self.speeds - self.accelerations * back,
            accelerations: self.accelerations,
        }
    }

    /// The middle one of three set-points `dt` apart (`last`, `next`, `after`): its speed
    /// and acceleration by central differences.
    pub(super) fn between(last: &Joints, next: &Joints, after: &Joints, dt: f64) -> SetPoint {
        SetPoint {
            angles: *next,
            speeds: (*after - *last) / (2.0 * dt),
            accelerations: (*after - 2.0 * *next + *last) / (dt * dt),
        }
    }
}

impl DynamicSettings {
    /// The accelerations (rad/s²) the servos ask of joints at angles `q` turning at `v`
    /// over one tick toward `set_point`: the spring (stiffness k) and damper (c) taken at
    /// the tick's end, which keeps the stiff default gains stable at k·dt² = 10:
    /// s = [a* + k·(x* − x − dt·v) + c·(v* − v)] / (1 + k·dt²/2 + c·dt). With the bias fed
    /// forward at the set-point, an arm that follows its set-point exactly gets exactly
    /// the set-point's acceleration.
    pub(super) fn servo_accelerations(
        &self,
        set_point: &SetPoint,
        q: &Joints,
        v: &Joints,
    ) -> Joints {
        let (k, c, dt) = (self.motor_stiffness, self.motor_damping, self.dt);
        let lag = set_point.angles - *q - *v * dt;
        let slow = set_point.speeds - *v;
        (set_point.accelerations + lag * k + slow * c) / (1.0 + 0.5 * k * dt * dt + c * dt)
    }
}

impl Arm {
    /// The joint torques (N·m) of one tick toward `set_point` for the arm at angles `q`
    /// and speeds `v`, whose equations of motion there are `space`: the bias at the
    /// set-point's angles and speeds (each within its joint's effort), and the servo's M·s,
    /// scaled down as a whole where a joint's share would exceed the effort that leaves it.
    pub(super) fn servo_torques(
        &self,
        model: &ArmModel,
        space: &JointSpace,
        set_point: &SetPoint,
        q: &Joints,
        v: &Joints,
        settings: &DynamicSettings,
    ) -> Joints {
        let mut bias = self.placement(model, &set_point.angles).driving_torques(
            model,
            &set_point.speeds,
            &Joints::zeros(self.dof),
        );
        let wanted = settings.servo_accelerations(set_point, q, v);
        if self.dry_friction {
            bias = bias + dry_friction_torques(model, &(*v + wanted * settings.dt));
        }
        let servo = space.inertial_torques(&wanted);
        let joints = model.joints();
        let held = Joints::from_fn(self.dof, |i| {
            bias[i].clamp(-joints[i].effort, joints[i].effort)
        });
        // The servo's accelerations scaled as a whole into the effort each joint has left,
        // so that a joint that cannot give its share does not leave the others pushing
        // for an acceleration the arm will not have.
        let scale = (0..self.dof).fold(1.0f64, |scale, i| {
            let left = joints[i].effort - held[i].abs();
            if servo[i].abs() > left {
                scale.min(left / servo[i].abs())
            } else {
                scale
            }
        });
        held + servo * scale
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// An arm on its set-point's path gets the path's acceleration; one behind it is
    /// pulled toward it.
    #[test]
    fn the_law_follows_the_path_and_pulls_toward_it() {
        let settings = DynamicSettings::default();
        let dt = settings.dt;
        let path = |t: f64| Joints::from_slice(&[0.5 * 3.0 * t * t, -0.2 * t]);
        let speed = |t: f64| Joints::from_slice(&[3.0 * t, -0.2]);
        let t = 0.1;
        let set_point = SetPoint::between(&path(t), &path(t + dt), &path(t + 2.0 * dt), dt);
        let on_path = settings.servo_accelerations(&set_point, &path(t), &speed(t));
        assert!(
            (on_path - Joints::from_slice(&[3.0, 0.0])).amax() < 1e-9,
            "{on_path:?}"
        );
        let behind = path(t) - Joints::from_slice(&[0.01, 0.01]);
        let pulled = settings.servo_accelerations(&set_point, &behind, &speed(t));
        assert!(
            pulled.iter().zip(on_path.iter()).all(|(p, o)| p > o),
            "{pulled:?}"
        );
    }
}
