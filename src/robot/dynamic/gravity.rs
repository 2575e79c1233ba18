//! Gravity feed-forward: the joint torques that carry the arm's weight at the servo
//! set-point, computed from the model's kinematics and the links' URDF masses, as a
//! model-based industrial controller adds them to its servo output (servo_law.rs).

use super::builder::{Arm, GRAVITY};
use crate::robot::{ArmModel, Joints, RobotError};
use nalgebra::Vector3;

impl Arm {
    /// The torque about each joint's axis (N·m) that holds the links' weight at pose `q`.
    pub(super) fn weight_torques(&self, model: &ArmModel, q: &Joints) -> Joints {
        let frames = model.link_frames(q);
        let joints = model.joints();
        let n = self.dof;
        let mut torques = Joints::zeros(n);
        // Weight and its moment about the world origin of the bodies from i out, summed
        // from the tip.
        let (mut weight, mut moment) = (Vector3::zeros(), Vector3::zeros());
        for i in (0..n).rev() {
            let (mass, com) = (self.inertials[i].mass, self.inertials[i].com);
            let force = Vector3::new(0.0, 0.0, -GRAVITY * mass);
            weight += force;
            moment += (frames[i] * nalgebra::Point3::from(com))
                .coords
                .cross(&force);
            let at = frames[i].translation.vector;
            torques[i] = -(frames[i].rotation * joints[i].axis.into_inner())
                .dot(&(moment - at.cross(&weight)));
        }
        torques
    }
}

impl Arm {
    /// Fails when a joint's motor is too weak to hold the arm's weight at pose `q` (the
    /// torque it needs is above the joint's URDF effort, or not a number).
    pub(super) fn check_holds(&self, model: &ArmModel, q: &Joints) -> Result<(), RobotError> {
        let torques = self.weight_torques(model, q);
        let joints = model.joints();
        match (0..self.dof).find(|&i| torques[i].is_nan() || torques[i].abs() > joints[i].effort) {
            Some(i) => Err(RobotError::CannotHold {
                joint: i + 1,
                torque_nm: torques[i].abs(),
                effort_nm: joints[i].effort,
            }),
            None => Ok(()),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::robot::DynamicSettings;

    #[test]
    fn the_shoulder_carries_the_outstretched_arm() {
        let model = ArmModel::oscar6();
        let arm = Arm::build(&model, &DynamicSettings::default());
        let torques = arm.weight_torques(&model, &model.full_pose(&Vector3::zeros()));
        // Upper arm 17 kg at 0.3 m, forearm 8 kg at 0.875 m, wrist, flange and camera 3.3 kg
        // at (or straight below) the wrist centre 1.15 m out; joint 2 lifts about −y, so
        // holding takes +torque.
        let expected = 9.81 * (17.0 * 0.3 + 8.0 * 0.875 + 3.3 * 1.15);
        assert!(
            (torques[1] - expected).abs() < 1e-9,
            "{torques:?} vs {expected}"
        );
        assert!(torques[0].abs() < 1e-9, "joint 1 yaws: no load");
        // Joint 3 bends down about +y: holding the forearm (8 kg at 0.275 m) and the wrist
        // (3.3 kg at 0.55 m) up takes −torque.
        let elbow = -9.81 * (8.0 * 0.275 + 3.3 * 0.55);
        assert!((torques[2] - elbow).abs() < 1e-9, "{torques:?} vs {elbow}");
    }
}
