//! The wrist: every joint that is not learned is set so that the optical axis points
//! straight down; the image's roll about it is whatever the wrist gives. One joint that can
//! do it alone (the OSCAR-6's θ5, whose roll leaves the image x axis pointing away from the
//! base) is solved in closed form; otherwise two joints (or one) are solved by Newton steps,
//! warm-started from the last pose, and every other joint is held at an angle chosen once
//! for the arm ([`choice`]).

mod choice;
mod follow;
mod look_down;
mod newton;
mod singular;

pub(crate) use look_down::{tilt_angle, tilting};

use super::{ArmModel, ArmPose, Controlled, Frames, Joints};
use nalgebra::{Isometry3, Vector3};
use newton::{newton, wrap_into_limits};

/// Tilt (rad) of the optical axis at which a numerical wrist solution is accepted.
const TOLERANCE_RAD: f64 = 1e-12;

/// How the joints that are not learned keep the camera looking down.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Wrist {
    /// No joint is left to solve (set while a model is being built).
    None,
    /// This joint alone (0-based), in closed form; the other wrist joints stay at rest.
    OneJoint(usize),
    /// These joints (0-based, `count` of them, at most two used) by Newton steps; the other
    /// wrist joints are held at their rest angles.
    Numerical {
        /// The solved joints, nearest the base first.
        joints: [usize; 3],
        /// How many of `joints` are used.
        count: usize,
    },
}

impl Wrist {
    /// The wrist angles at rest: for a numerical wrist, its solution at the middle of the
    /// learned joints' ranges (so that later solves start near a real solution).
    pub(super) fn settle_rest(&self, model: &mut ArmModel) {
        let Wrist::Numerical { .. } = *self else {
            return;
        };
        let theta = reference_angles(model);
        let level = model.with_learned(&theta);
        let pose = self.solve(model, &theta, model.link_frames(&level), &level);
        if pose.wrist_found {
            for j in self.solved() {
                model.rest[j] = pose.joints[j];
            }
        }
    }

    /// True when this wrist sets joint `joint` (0-based).
    pub fn sets(&self, joint: usize) -> bool {
        self.solved().any(|j| j == joint)
    }

    /// The joints this wrist sets, nearest the base first.
    pub(crate) fn solved(&self) -> impl Iterator<Item = usize> + '_ {
        let (slice, count): (&[usize], usize) = match self {
            Wrist::None => (&[], 0),
            Wrist::OneJoint(j) => (std::slice::from_ref(j), 1),
            Wrist::Numerical { joints, count } => (joints, *count),
        };
        slice.iter().copied().take(count)
    }

    /// The pose for learned angles `theta`, given the joint frames `level_frames` with
    /// every other joint at rest; a numerical wrist starts from the wrist angles of `near`
    /// (and, near a two-joint wrist's singularity, looks down as far as it turns well:
    /// singular.rs).
    pub(super) fn solve(
        &self,
        model: &ArmModel,
        theta: &Controlled,
        level_frames: Frames,
        near: &Joints,
    ) -> ArmPose {
        self.solve_as(model, theta, level_frames, near, false)
    }

    /// [`Wrist::solve`], a numerical wrist looking down within [`TOLERANCE_RAD`] even near
    /// its singularity when `exact` (as the wrist is chosen: a joint turning about the
    /// optical axis does not count as a wrist joint).
    fn solve_as(
        &self,
        model: &ArmModel,
        theta: &Controlled,
        level_frames: Frames,
        near: &Joints,
        exact: bool,
    ) -> ArmPose {
        let mut joints = model.with_learned(theta);
        match *self {
            Wrist::None => {
                let camera = level_frames.last() * model.camera_mount();
                ArmPose {
                    joints,
                    camera,
                    level_frames,
                    frames: level_frames,
                    wrist_found: tilt_angle(&camera) < TOLERANCE_RAD,
                }
            }
            Wrist::OneJoint(j) => {
                let angle = one_joint_angle(model, j, &level_frames);
                joints[j] = angle;
                wrap_into_limits(model, self, &mut joints);
                // The chain again from joint j on, as `link_frames` walks it.
                let mut frames = level_frames;
                let mut flange = if j == 0 {
                    Isometry3::identity()
                } else {
                    level_frames[j - 1]
                };
                for k in j..model.dof() {
                    flange *= model.joints[k].transform(joints[k]);
                    frames.set(k, flange);
                }
                ArmPose {
                    joints,
                    camera: flange * model.camera_mount(),
                    level_frames,
                    frames,
                    wrist_found: angle.is_finite(),
                }
            }
            Wrist::Numerical { joints: solved, .. } => {
                let first = solved[0];
                let prefix = if first == 0 {
                    Isometry3::identity()
                } else {
                    level_frames[first - 1]
                };
                for j in self.solved() {
                    joints[j] = near[j];
                }
                let mut flange = newton(model, self, &prefix, &mut joints, exact);
                if flange.is_none() && near != &model.rest {
                    joints = model.with_learned(theta);
                    flange = newton(model, self, &prefix, &mut joints, exact);
                }
                let found = flange.is_some();
                if found {
                    wrap_into_limits(model, self, &mut joints);
                }
                let frames = model.link_frames(&joints);
                let flange = flange.unwrap_or_else(|| frames.last());
                ArmPose {
                    joints,
                    camera: flange * model.camera_mount(),
                    level_frames,
                    frames,
                    wrist_found: found,
                }
            }
        }
    }
}

/// The learned angles the wrist is chosen and settled at: the middle of each learned
/// joint's limits (0 for a joint without).
fn reference_angles(model: &ArmModel) -> Controlled {
    Controlled::from_fn(|i, _| model.joints[model.learned[i]].middle())
}

/// The angle of joint `j` that turns the optical axis straight down, from the frames with
/// that joint at rest (the OSCAR-6's θ5 formula for any one joint).
fn one_joint_angle(model: &ArmModel, j: usize, frames: &Frames) -> f64 {
    let axis = frames[j].rotation * model.joints[j].axis.into_inner();
    let optical = (frames.last() * model.camera_mount()).rotation * Vector3::z();
    let down = -Vector3::z();
    let along = |v: Vector3<f64>| v - axis * axis.dot(&v);
    let (from, to) = (along(optical), along(down));
    let turn = axis.dot(&from.cross(&to)).atan2(from.dot(&to));
    // The level frames hold the joint at its rest angle (0 for the OSCAR-6).
    match model.rest[j] {
        0.0 => turn,
        rest => rest + turn,
    }
}
