//! Inverse kinematics of the camera centre: the pose (θ1, θ2, θ3) that puts the camera at
//! a point with its optical axis vertical — elbow up on the OSCAR-6 form, on the branch of
//! its solutions the arm keeps to ([`Branch`](super::Branch)) on any other. A closed-form
//! guess from the model's link vectors is polished by Newton steps on the full forward
//! kinematics, so the answer is exact for whatever the model is now (stretched links
//! included). The link lengths the
//! guess needs are worked out once per change of the model ([`GuessGeometry`]), and each
//! Newton step walks the chain once per pose it evaluates.

use super::{ArmModel, ArmPose, Controlled, Frames, Wrist};
use crate::robot::RobotError;
use nalgebra::{Matrix3, Point3, Vector3};
use std::f64::consts::TAU;

/// Position error (m) at which a solution is accepted.
const TOLERANCE_M: f64 = 1e-11;
const MAX_NEWTON_STEPS: usize = 30;
const JACOBIAN_STEP: f64 = 1e-7;
/// Where in each learned joint's range the starting poses of a general arm lie, and the
/// poses the OSCAR-6 form's closed-form path is checked at.
const SEED_FRACTIONS: [f64; 3] = [0.5, 0.25, 0.75];
/// How close (rad) the closed-form path must give back a pose it is checked at.
const FORM_CHECK_RAD: f64 = 1e-6;

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
        let [_, s, e] = model.learned();
        let w = wrist_joint(model);
        let frames = model.link_frames(&model.rest());
        let shoulder = frames[s].translation.vector;
        let upper = (frames[e].translation.vector - shoulder).norm();
        let fore = (frames[w].translation.vector - frames[e].translation.vector).norm();
        let posed = model.full_pose(&model.controlled_of(&model.rest()));
        let camera_offset =
            model.camera_position(&posed).coords - model.link_frames(&posed)[w].translation.vector;
        GuessGeometry {
            shoulder,
            upper,
            fore,
            camera_offset,
        }
    }
}

impl ArmModel {
    /// The pose that puts the camera centre at `target` (world, m), inside the joint
    /// limits, elbow up on the OSCAR-6 form and on the arm's branch on any other (a
    /// shoulder or elbow that turns all the way round at its angle in the branch's turn),
    /// or why there is none.
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
        let mut failure: Option<String> = None;
        let tabled = (!self.is_oscar6_form())
            .then(|| self.ik_seeds().nearest(self, target))
            .flatten();
        let starts = tabled
            .into_iter()
            .chain(self.closed_form_guess(target))
            .chain(
                (!self.is_oscar6_form())
                    .then(|| self.seeds(target))
                    .into_iter()
                    .flatten(),
            );
        for start in starts {
            match self.newton_from(start, target) {
                Ok(theta) => return Ok(theta),
                Err(why) => {
                    if failure
                        .as_ref()
                        .is_none_or(|f| failure_rank(&why) > failure_rank(f))
                    {
                        failure = Some(why);
                    }
                }
            }
        }
        Err(unreachable(
            failure.as_deref().unwrap_or("out of the arm's reach"),
        ))
    }

    /// Newton steps on the camera centre from `theta`: the pose that reaches `target`
    /// elbow up inside the limits, or why there is none from this start.
    fn newton_from(
        &self,
        mut theta: Controlled,
        target: &Point3<f64>,
    ) -> Result<Controlled, String> {
        for _ in 0..MAX_NEWTON_STEPS {
            // The wrist solved from rest, as `place` solves it: the same pose for the
            // same angles whatever came before.
            let pose = self.pose_of(&theta);
            if !pose.wrist_found {
                return Err("no wrist pose keeps the camera looking down on the way".into());
            }
            let near = pose.joints;
            let here = camera_centre(&pose);
            let residual = here - target;
            if residual.norm() < TOLERANCE_M {
                if self.is_oscar6_form() {
                    if !self.elbow_up_in(&pose.level_frames, theta.x) {
                        return Err("only an elbow-down pose reaches it".into());
                    }
                    self.check_joint_limits(&pose.joints)
                        .map_err(|e| e.to_string())?;
                    return Ok(theta);
                }
                return self.on_branch(theta, &pose);
            }
            let jacobian = self
                .followed_jacobian(&pose.joints)
                .unwrap_or_else(|| self.position_jacobian(&theta, &here.coords, &near));
            let step = jacobian
                .lu()
                .solve(&residual)
                .ok_or("the arm is singular there")?;
            theta -= step;
            if !theta.iter().all(|v| v.is_finite()) {
                return Err("inverse kinematics did not converge".into());
            }
        }
        Err("inverse kinematics did not converge".into())
    }

    /// True when the closed-form guess and the elbow-up rule give back every elbow-up pose
    /// whose wrist fits of a 3×3×3 grid inside the learned joints' limits, and there is
    /// at least one such pose: the check an arm of the OSCAR-6 shape passes to be solved
    /// as the OSCAR-6 is (asked while the model takes itself to be of that form).
    pub(super) fn closed_form_answers(&self) -> bool {
        let at = |j: usize, f: f64| {
            let (lower, upper) = self.joints[j].one_turn();
            lower + (upper - lower) * f
        };
        let mut checked = 0;
        for fy in SEED_FRACTIONS {
            for fs in SEED_FRACTIONS {
                for fe in SEED_FRACTIONS {
                    let [y, s, e] = self.learned;
                    let theta = Controlled::new(at(y, fy), at(s, fs), at(e, fe));
                    let pose = self.pose_of(&theta);
                    if !self.wrist_fits(&pose) || !self.is_elbow_up(&theta) {
                        continue;
                    }
                    let back = self.solve_camera_position(&camera_centre(&pose));
                    if !back.is_ok_and(|found| (found - theta).amax() < FORM_CHECK_RAD) {
                        return false;
                    }
                    checked += 1;
                }
            }
        }
        checked > 0
    }

    /// Starting poses for an arm that is not of the OSCAR-6 form: the learned joints at a
    /// grid of points inside their limits, the base turned towards the target.
    fn seeds(&self, target: &Point3<f64>) -> impl Iterator<Item = Controlled> + '_ {
        let [yaw_joint, s, e] = self.learned().map(|j| &self.joints()[j]);
        let within = |joint: &super::RevoluteJoint, f: f64| {
            let (lower, upper) = joint.one_turn();
            lower + (upper - lower) * f
        };
        let bearing = target.y.atan2(target.x);
        let sense = super::ik_seeds::yaw_sense(self);
        let yaw_limits = (yaw_joint.lower, yaw_joint.upper);
        SEED_FRACTIONS.iter().flat_map(move |&fs| {
            SEED_FRACTIONS.iter().filter_map(move |&fe| {
                let theta = Controlled::new(0.0, within(s, fs), within(e, fe));
                let pose = self.pose_of(&theta);
                let p = camera_centre(&pose);
                let mut yaw = (bearing - p.y.atan2(p.x)) * sense;
                for turn in [0.0, TAU, -TAU] {
                    if (yaw_limits.0..=yaw_limits.1).contains(&(yaw + turn)) {
                        yaw += turn;
                        break;
                    }
                }
                pose.wrist_found
                    .then_some(Controlled::new(yaw, theta.y, theta.z))
            })
        })
    }

    /// ∂(camera centre)/∂(θ1, θ2, θ3), the wrist following the vertical constraint, by
    /// forward differences from `base`, the camera centre at `theta` (wrist at `near`).
    fn position_jacobian(
        &self,
        theta: &Controlled,
        base: &Vector3<f64>,
        near: &super::Joints,
    ) -> Matrix3<f64> {
        let mut jacobian = Matrix3::zeros();
        for i in 0..3 {
            let mut shifted = *theta;
            shifted[i] += JACOBIAN_STEP;
            let moved = camera_centre(&self.pose_near(&shifted, near)).coords;
            jacobian.set_column(i, &((moved - base) / JACOBIAN_STEP));
        }
        jacobian
    }

    /// True when the elbow lies above the shoulder–wrist line (the OSCAR-6's rule; the arm's
    /// plane turns with the base yaw).
    pub fn is_elbow_up(&self, theta: &Controlled) -> bool {
        let frames = self.link_frames(&self.with_learned(theta));
        self.elbow_up_in(&frames, theta.x)
    }

    /// True when the elbow lies above the shoulder–wrist line, from the joint frames with
    /// the wrist at rest, the arm's plane turned with the base yaw: the OSCAR-6's rule.
    fn elbow_up_in(&self, frames: &Frames, yaw: f64) -> bool {
        let [_, s, e] = self.learned();
        let (shoulder, elbow, wrist) = (
            frames[s].translation.vector,
            frames[e].translation.vector,
            frames[wrist_joint(self)].translation.vector,
        );
        elbow_up(shoulder, elbow, wrist, yaw)
    }

    /// True when `theta` is a pose the inverse kinematics answers with: elbow up on the
    /// OSCAR-6 form; on any other, on the arm's branch of its solutions, with its wrist
    /// found.
    pub fn is_on_branch(&self, theta: &Controlled) -> bool {
        if self.is_oscar6_form() {
            return self.is_elbow_up(theta);
        }
        let pose = self.pose_of(theta);
        pose.wrist_found && self.branch_holds(theta, &pose)
    }

    /// `theta`, which reaches its target at `pose`, as the answer on an arm not of the
    /// OSCAR-6 form: its base yaw within half a turn of the one that faces the tabled poses
    /// to the base's x axis where the limits allow, its
    /// shoulder and elbow taken into the branch's turn, inside the limits and on the
    /// branch; or why not.
    fn on_branch(&self, mut theta: Controlled, pose: &ArmPose) -> Result<Controlled, String> {
        let mut joints = pose.joints;
        let yaw = self.learned()[0];
        let low = self.ik_seeds().yaw_middle() - std::f64::consts::PI;
        let turned = low + (theta.x - low).rem_euclid(TAU);
        for shifted in [turned, turned - TAU, turned + TAU] {
            if self.joints()[yaw].admits(shifted) {
                theta.x = shifted;
                joints[yaw] = shifted;
                break;
            }
        }
        if let Some(branch) = &self.branch {
            let [_, s, e] = self.learned();
            for (i, j) in [(1, s), (2, e)] {
                let wrapped = branch.wrapped(i - 1, theta[i]);
                if self.joints()[j].admits(wrapped) {
                    theta[i] = wrapped;
                    joints[j] = wrapped;
                }
            }
        }
        self.check_joint_limits(&joints)
            .map_err(|e| e.to_string())?;
        if !self.branch_holds(&theta, pose) {
            return Err("only a pose on another branch of the arm's solutions reaches it".into());
        }
        Ok(theta)
    }

    /// True when `theta` (its pose `pose`) lies on the arm's branch: its shoulder and elbow
    /// in the branch's cells, and ∂(r, z)/∂(θ2, θ3) of the sign it has there.
    fn branch_holds(&self, theta: &Controlled, pose: &ArmPose) -> bool {
        let Some(branch) = &self.branch else {
            return false;
        };
        let here = camera_centre(pose).coords;
        let jacobian = self
            .followed_jacobian(&pose.joints)
            .unwrap_or_else(|| self.position_jacobian(theta, &here, &pose.joints));
        let radius = here.x.hypot(here.y);
        if radius == 0.0 {
            return false;
        }
        let out = Vector3::new(here.x / radius, here.y / radius, 0.0);
        let (dr2, dr3) = (out.dot(&jacobian.column(1)), out.dot(&jacobian.column(2)));
        let det = dr2 * jacobian[(2, 2)] - jacobian[(2, 1)] * dr3;
        branch.holds_with(theta.y, theta.z, det, super::side_of(self, pose))
    }

    /// A closed-form guess for a Puma-like arm: yaw towards the target, then the
    /// shoulder–elbow–wrist triangle in the vertical plane.
    fn closed_form_guess(&self, target: &Point3<f64>) -> Option<Controlled> {
        let GuessGeometry {
            shoulder,
            upper,
            fore,
            camera_offset,
            ..
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

/// The joint whose origin is the wrist centre: the one-joint wrist's joint, else the first
/// solved wrist joint, else the last joint.
fn wrist_joint(model: &ArmModel) -> usize {
    match *model.wrist() {
        Wrist::OneJoint(j) => j,
        Wrist::Numerical { joints, .. } => joints[0],
        Wrist::None => model.dof() - 1,
    }
}

/// How telling a reason for failing is: a pose found but refused beats none found.
fn failure_rank(why: &str) -> u8 {
    u8::from(why.contains("elbow-down") || why.contains("branch") || why.contains("limits"))
}

/// True when the elbow lies above the shoulder–wrist line (world points, the arm's plane
/// turned by `yaw`).
fn elbow_up(shoulder: Vector3<f64>, elbow: Vector3<f64>, wrist: Vector3<f64>, yaw: f64) -> bool {
    let heading = Vector3::new(yaw.cos(), yaw.sin(), 0.0);
    let planar = |v: Vector3<f64>| (v.dot(&heading), v.z);
    let (wr, wz) = planar(wrist - shoulder);
    let (er, ez) = planar(elbow - shoulder);
    wr * ez - wz * er > 0.0
}
