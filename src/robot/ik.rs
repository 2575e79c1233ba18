//! Inverse kinematics of the camera centre: the elbow-up pose (θ1, θ2, θ3) that puts the
//! camera at a point with its optical axis vertical. A closed-form guess from the model's
//! link vectors is polished by Newton steps on the full forward kinematics, so the answer
//! is exact for whatever the model is now (stretched links included). The link lengths the
//! guess needs are worked out once per change of the model ([`GuessGeometry`]), and each
//! Newton step walks the chain once per pose it evaluates.

use super::model::{ArmModel, ArmPose, Controlled, Joints};
use super::RobotError;
use nalgebra::{Isometry3, Matrix3, Point3, Vector3};

/// Position error (m) at which a solution is accepted.
const TOLERANCE_M: f64 = 1e-11;
const MAX_NEWTON_STEPS: usize = 30;
const JACOBIAN_STEP: f64 = 1e-7;

/// What the closed-form guess needs of the arm, from its zero pose: the shoulder's
/// position, the upper arm's and forearm's lengths and the camera's offset from the wrist
/// with the arm level (m).
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub(super) struct GuessGeometry {
    shoulder: Vector3<f64>,
    upper: f64,
    fore: f64,
    camera_offset: Vector3<f64>,
}

impl GuessGeometry {
    /// The guess's geometry of `model` as it is now.
    pub(super) fn of(model: &ArmModel) -> GuessGeometry {
        let frames = model.link_frames(&Joints::zeros());
        let shoulder = frames[1].translation.vector;
        let upper = (frames[2].translation.vector - shoulder).norm();
        let fore = (frames[4].translation.vector - frames[2].translation.vector).norm();
        let posed = model.full_pose(&Controlled::new(0.0, 0.0, 0.0));
        let camera_offset =
            model.camera_position(&posed).coords - model.link_frames(&posed)[4].translation.vector;
        GuessGeometry {
            shoulder,
            upper,
            fore,
            camera_offset,
        }
    }
}

impl ArmModel {
    /// The elbow-up pose that puts the camera centre at `target` (world, m), inside the
    /// joint limits, or why there is none.
    pub fn solve_camera_position(&self, target: &Point3<f64>) -> Result<Controlled, RobotError> {
        let unreachable = |why: &str| RobotError::Unreachable {
            x_cm: target.x * 100.0,
            y_cm: target.y * 100.0,
            z_cm: target.z * 100.0,
            why: why.to_string(),
        };
        if !target.coords.iter().all(|v| v.is_finite()) {
            return Err(unreachable("the target is not a finite point"));
        }
        let mut theta = self
            .closed_form_guess(target)
            .ok_or_else(|| unreachable("out of the arm's reach"))?;
        for _ in 0..MAX_NEWTON_STEPS {
            let pose = self.pose_of(&theta);
            let here = camera_centre(&pose);
            let residual = here - target;
            if residual.norm() < TOLERANCE_M {
                if !elbow_up(&pose.level_frames, theta.x) {
                    return Err(unreachable("only an elbow-down pose reaches it"));
                }
                self.check_joint_limits(&pose.joints)
                    .map_err(|e| unreachable(&e.to_string()))?;
                return Ok(theta);
            }
            let step = self
                .position_jacobian(&theta, &here.coords)
                .lu()
                .solve(&residual)
                .ok_or_else(|| unreachable("the arm is singular there"))?;
            theta -= step;
        }
        Err(unreachable("inverse kinematics did not converge"))
    }

    /// ∂(camera centre)/∂(θ1, θ2, θ3), the wrist following the vertical constraint, by
    /// forward differences from `base`, the camera centre at `theta`.
    fn position_jacobian(&self, theta: &Controlled, base: &Vector3<f64>) -> Matrix3<f64> {
        let mut jacobian = Matrix3::zeros();
        for i in 0..3 {
            let mut shifted = *theta;
            shifted[i] += JACOBIAN_STEP;
            let moved = camera_centre(&self.pose_of(&shifted)).coords;
            jacobian.set_column(i, &((moved - base) / JACOBIAN_STEP));
        }
        jacobian
    }

    /// True when the elbow lies above the shoulder–wrist line.
    pub fn is_elbow_up(&self, theta: &Controlled) -> bool {
        let frames = self.link_frames(&Joints::new(theta.x, theta.y, theta.z, 0.0, 0.0, 0.0));
        elbow_up(&frames, theta.x)
    }

    /// A closed-form guess for a Puma-like arm: yaw towards the target, then the
    /// shoulder–elbow–wrist triangle in the vertical plane.
    fn closed_form_guess(&self, target: &Point3<f64>) -> Option<Controlled> {
        let GuessGeometry {
            shoulder,
            upper,
            fore,
            camera_offset,
        } = *self.guess_geometry();
        let yaw = target.y.atan2(target.x);
        let wrist = target.coords
            - nalgebra::Rotation3::from_axis_angle(&Vector3::z_axis(), yaw) * camera_offset;
        let reach = (wrist.x * wrist.x + wrist.y * wrist.y).sqrt() - shoulder.x;
        let height = wrist.z - shoulder.z;
        let distance = reach.hypot(height);
        let cos_interior =
            (upper * upper + fore * fore - distance * distance) / (2.0 * upper * fore);
        let cos_shoulder =
            (upper * upper + distance * distance - fore * fore) / (2.0 * upper * distance);
        if !(-1.0..=1.0).contains(&cos_interior) || !(-1.0..=1.0).contains(&cos_shoulder) {
            return None;
        }
        let elevation = height.atan2(reach) + cos_shoulder.acos();
        let elbow = std::f64::consts::PI - cos_interior.acos();
        Some(Controlled::new(yaw, elevation, elbow))
    }
}

/// The camera centre of a worked-out pose.
fn camera_centre(pose: &ArmPose) -> Point3<f64> {
    pose.camera * Point3::origin()
}

/// True when the elbow lies above the shoulder–wrist line, from the joint frames of
/// (θ1, θ2, θ3, 0, 0, 0).
fn elbow_up(frames: &[Isometry3<f64>; 6], yaw: f64) -> bool {
    let (shoulder, elbow, wrist) = (
        frames[1].translation.vector,
        frames[2].translation.vector,
        frames[4].translation.vector,
    );
    let heading = Vector3::new(yaw.cos(), yaw.sin(), 0.0);
    let planar = |v: Vector3<f64>| (v.dot(&heading), v.z);
    let (wr, wz) = planar(wrist - shoulder);
    let (er, ez) = planar(elbow - shoulder);
    wr * ez - wz * er > 0.0
}
