//! Newton steps on a numerical wrist's joints until the optical axis points straight down.

use super::look_down::{tilt, tilting};
use super::singular::{near_singular, NearSingular};
use super::{Wrist, TOLERANCE_RAD};
use crate::robot::model::{ArmModel, Joints};
use nalgebra::{Isometry3, Matrix3, Vector3};

/// Newton steps before a start is given up.
const MAX_STEPS: usize = 30;
/// The largest change of a wrist angle in one Newton step (rad).
const MAX_STEP_RAD: f64 = 0.5;
/// The damping of the wrist's least-squares steps.
const DAMPING: f64 = 1e-12;

/// Newton steps on the solved wrist joints of `q` until the optical axis points straight
/// down (near a two-joint wrist's singularity, unless `exact`: as far as it turns it well,
/// singular.rs); the flange's pose when it does. `prefix` is the frame before the first solved
/// joint, which the wrist does not move.
pub(super) fn newton(
    model: &ArmModel,
    wrist: &Wrist,
    prefix: &Isometry3<f64>,
    q: &mut Joints,
    exact: bool,
) -> Option<Isometry3<f64>> {
    let Wrist::Numerical { joints, count } = *wrist else {
        return None;
    };
    for _ in 0..MAX_STEPS {
        let mut pose = *prefix;
        let mut axes = [Vector3::zeros(); 3];
        for (k, joint) in model.joints.iter().enumerate().skip(joints[0]) {
            pose *= joint.transform(q[k]);
            if let Some(s) = joints[..count].iter().position(|&j| j == k) {
                axes[s] = pose.rotation * joint.axis.into_inner();
            }
        }
        let camera = pose * model.unturned_mount();
        let error = tilt(&camera);
        if !error.iter().all(|e| e.is_finite()) {
            return None;
        }
        if error.norm() < TOLERANCE_RAD {
            return Some(pose);
        }
        // d(tilt)/d(angle): the part of each joint's turn across the optical axis.
        let optical = camera.rotation * Vector3::z();
        let mut jacobian = Matrix3::zeros();
        for (s, axis) in axes.iter().enumerate().take(count) {
            jacobian.set_column(s, &tilting(axis, &optical));
        }
        if count == 2 && !exact {
            match near_singular(&jacobian, &optical, &error) {
                Some(NearSingular::Done) => return Some(pose),
                Some(NearSingular::Step(step)) => {
                    let scale = (MAX_STEP_RAD / step.amax()).min(1.0);
                    for s in 0..2 {
                        q[joints[s]] += step[s] * scale;
                    }
                    continue;
                }
                None => {}
            }
        }
        // Damped least squares (unused columns are 0 and held by the damping).
        let normal = jacobian.transpose() * jacobian
            + Matrix3::from_diagonal(&Vector3::from_fn(
                |i, _| {
                    if i < count {
                        DAMPING
                    } else {
                        1.0
                    }
                },
            ));
        let step = normal.lu().solve(&(jacobian.transpose() * error))?;
        let scale = (MAX_STEP_RAD / step.amax()).min(1.0);
        for s in 0..count {
            q[joints[s]] += step[s] * scale;
        }
    }
    None
}

/// Moves solved angles outside their limits by whole turns when that brings them inside.
pub(super) fn wrap_into_limits(model: &ArmModel, wrist: &Wrist, q: &mut Joints) {
    let turn = std::f64::consts::TAU;
    for j in wrist.solved() {
        let joint = &model.joints[j];
        for shifted in [q[j] - turn, q[j] + turn] {
            if !joint.admits(q[j]) && joint.admits(shifted) {
                q[j] = shifted;
            }
        }
    }
}
