//! Looking down: how far the optical axis is tilted from straight down, and the turn that
//! would bring it there. The roll about the axis is not part of the goal: it is whatever
//! the wrist gives.

use nalgebra::{Isometry3, Vector3};

/// The turn (rotation vector, rad) that brings the optical axis of `camera` (its z axis)
/// straight down by the shortest way; perpendicular to the axis. An axis pointing straight
/// up is turned about the camera's x axis.
pub(super) fn tilt(camera: &Isometry3<f64>) -> Vector3<f64> {
    let optical = camera.rotation * Vector3::z();
    let down = -Vector3::z();
    let cross = optical.cross(&down);
    let sine = cross.norm();
    let angle = sine.atan2(optical.dot(&down));
    if sine > 0.0 {
        cross * (angle / sine)
    } else if angle > 0.0 {
        camera.rotation * Vector3::x() * angle
    } else {
        Vector3::zeros()
    }
}

/// The angle (rad) between the optical axis of `camera` and straight down.
pub(crate) fn tilt_angle(camera: &Isometry3<f64>) -> f64 {
    let optical = camera.rotation * Vector3::z();
    let down = -Vector3::z();
    optical.cross(&down).norm().atan2(optical.dot(&down))
}

/// The part of a joint's turn about `axis` that tilts the optical axis `optical`.
pub(crate) fn tilting(axis: &Vector3<f64>, optical: &Vector3<f64>) -> Vector3<f64> {
    axis - optical * optical.dot(axis)
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::UnitQuaternion;

    #[test]
    fn the_tilt_turns_the_axis_down_whatever_the_roll() {
        for roll in [0.0, 1.0, -2.5] {
            let rolled = UnitQuaternion::from_axis_angle(&Vector3::z_axis(), roll);
            for turn in [
                UnitQuaternion::from_euler_angles(0.3, -1.1, 0.2),
                UnitQuaternion::from_euler_angles(3.0, 0.1, 0.0),
                UnitQuaternion::from_euler_angles(std::f64::consts::PI, 0.0, 0.0),
                UnitQuaternion::identity(),
            ] {
                let camera = Isometry3::from_parts(Default::default(), turn * rolled);
                let turned = UnitQuaternion::from_scaled_axis(tilt(&camera)) * camera.rotation;
                assert!((turned * Vector3::z() + Vector3::z()).norm() < 1e-12);
                assert!((tilt(&camera).norm() - tilt_angle(&camera)).abs() < 1e-12);
            }
        }
    }
}
