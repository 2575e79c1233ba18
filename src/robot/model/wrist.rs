//! The wrist: every joint that is not learned is set so that the optical axis points
//! straight down and the image's x axis points radially outwards (away from the base's z
//! axis). One joint that can do it alone (the OSCAR-6's θ5) is solved in closed form;
//! otherwise up to three joints are solved by Newton steps on the camera's orientation,
//! warm-started from the last pose, and any further joint is held at rest.

use super::{ArmModel, ArmPose, Controlled, Frames, Joints, MAX_JOINTS};
use nalgebra::{Isometry3, Matrix3, Rotation3, UnitQuaternion, Vector3};

/// Orientation error (rad) at which a numerical wrist solution is accepted.
const TOLERANCE_RAD: f64 = 1e-12;
/// Newton steps before a start is given up.
const MAX_STEPS: usize = 30;
/// The largest change of a wrist angle in one Newton step (rad).
const MAX_STEP_RAD: f64 = 0.5;
/// A closed-form wrist must leave at most this orientation error (rad) at every test pose.
const ONE_JOINT_TOLERANCE_RAD: f64 = 1e-9;
/// Test poses per learned joint when deciding whether one joint can do the wrist's work.
const TEST_STEPS: usize = 4;
/// The damping of the wrist's least-squares steps.
const DAMPING: f64 = 1e-12;
/// The least conditioning (smallest singular value of the wrist's turning axes) a set of
/// wrist joints needs to be solved by Newton steps.
const MIN_CONDITIONING: f64 = 0.3;
/// Cameras closer than this to the base's z axis have no radial direction (m).
const MIN_RADIUS: f64 = 1e-6;

/// How the joints that are not learned keep the camera looking down.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Wrist {
    /// No joint is left to solve (set while a model is being built).
    None,
    /// This joint alone (0-based), in closed form; the other wrist joints stay at rest.
    OneJoint(usize),
    /// These joints (0-based, `count` of them, at most three) by Newton steps.
    Numerical {
        /// The solved joints, nearest the base first.
        joints: [usize; 3],
        /// How many of `joints` are used.
        count: usize,
    },
}

impl Wrist {
    /// The closed form when one joint (with the others at rest) keeps the camera vertical
    /// and the image x axis radial at every test pose; else the last three wrist joints.
    pub(super) fn choose(model: &ArmModel) -> Wrist {
        let wrist: Vec<usize> = (0..model.dof())
            .filter(|i| !model.learned.contains(i))
            .collect();
        let one_joint = wrist
            .iter()
            .map(|&j| Wrist::OneJoint(j))
            .find(|candidate| candidate.keeps_vertical(model));
        if let Some(found) = one_joint {
            return found;
        }
        let theta = reference_angles(model);
        let level = model.with_learned(&theta);
        let frames = model.link_frames(&level);
        // The last three (or fewer) joints solve the reference pose; if two of them turn
        // the camera about one axis there, the best-conditioned two or one of them are
        // solved instead and the others held where that solution put them.
        let count = wrist.len().min(3);
        if count == 0 {
            return Wrist::None;
        }
        let mut joints = [0; 3];
        joints[..count].copy_from_slice(&wrist[wrist.len() - count..]);
        let all = Wrist::Numerical { joints, count };
        let home = all.solve(model, &theta, frames, &level);
        if !home.wrist_found || conditioning(model, &all, &home.joints) > MIN_CONDITIONING {
            return all;
        }
        let mut held = model.clone();
        held.rest = home.joints;
        for smaller in (1..count).rev() {
            for subset in subsets(&joints[..count], smaller) {
                let mut chosen = [0; 3];
                chosen[..smaller].copy_from_slice(&subset);
                let candidate = Wrist::Numerical {
                    joints: chosen,
                    count: smaller,
                };
                if conditioning(&held, &candidate, &home.joints) > MIN_CONDITIONING {
                    return candidate;
                }
            }
        }
        all
    }

    /// The rest angles of the joints this wrist holds: where the solution of the reference
    /// pose with every wrist joint free puts them.
    pub(super) fn held_rest(&self, model: &ArmModel) -> Joints {
        let mut rest = model.rest;
        let Wrist::Numerical { count, .. } = *self else {
            return rest;
        };
        let wrist: Vec<usize> = (0..model.dof())
            .filter(|i| !model.learned.contains(i))
            .collect();
        let all_count = wrist.len().min(3);
        if count == all_count {
            return rest;
        }
        let mut joints = [0; 3];
        joints[..all_count].copy_from_slice(&wrist[wrist.len() - all_count..]);
        let all = Wrist::Numerical {
            joints,
            count: all_count,
        };
        let theta = reference_angles(model);
        let level = model.with_learned(&theta);
        let home = all.solve(model, &theta, model.link_frames(&level), &level);
        if home.wrist_found {
            for &j in &joints[..all_count] {
                rest[j] = home.joints[j];
            }
        }
        rest
    }

    /// True when this wrist meets the orientation goal at a grid of learned poses inside
    /// the limits.
    fn keeps_vertical(&self, model: &ArmModel) -> bool {
        let span = |j: usize| {
            let (lower, upper) = model.joints[j].one_turn();
            (lower, upper - lower)
        };
        let mut tested = 0;
        for k in 0..TEST_STEPS.pow(3) {
            let theta = Controlled::from_fn(|i, _| {
                let (lower, width) = span(model.learned[i]);
                let step = (k / TEST_STEPS.pow(i as u32)) % TEST_STEPS;
                lower + width * (step as f64 + 0.5) / TEST_STEPS as f64
            });
            let level = model.with_learned(&theta);
            let pose = self.solve(model, &theta, model.link_frames(&level), &level);
            match orientation_error(&pose.camera_unturned(model)) {
                Some(error) if error > ONE_JOINT_TOLERANCE_RAD => return false,
                Some(_) => tested += 1,
                None => {}
            }
        }
        tested > 0
    }

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

    /// The joints this wrist sets.
    fn solved(&self) -> impl Iterator<Item = usize> + '_ {
        let (slice, count): (&[usize], usize) = match self {
            Wrist::None => (&[], 0),
            Wrist::OneJoint(j) => (std::slice::from_ref(j), 1),
            Wrist::Numerical { joints, count } => (joints, *count),
        };
        slice.iter().copied().take(count)
    }

    /// The pose for learned angles `theta`, given the joint frames `level_frames` with
    /// every other joint at rest; a numerical wrist starts from the wrist angles of `near`.
    pub(super) fn solve(
        &self,
        model: &ArmModel,
        theta: &Controlled,
        level_frames: Frames,
        near: &Joints,
    ) -> ArmPose {
        let mut joints = model.with_learned(theta);
        match *self {
            Wrist::None => {
                let camera = level_frames.last() * model.camera_mount();
                let found = orientation_error(&(level_frames.last() * model.unturned_mount()))
                    .is_some_and(|e| e < TOLERANCE_RAD);
                ArmPose {
                    joints,
                    camera,
                    level_frames,
                    frames: level_frames,
                    wrist_found: found,
                }
            }
            Wrist::OneJoint(j) => {
                let angle = one_joint_angle(model, j, &level_frames);
                joints[j] = angle;
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
                let mut flange = newton(model, self, &prefix, &mut joints);
                if flange.is_none() && near != &model.rest {
                    joints = model.with_learned(theta);
                    flange = newton(model, self, &prefix, &mut joints);
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

/// Every `count`-joint subset of `joints` (in chain order), those nearest the end first.
fn subsets(joints: &[usize], count: usize) -> Vec<Vec<usize>> {
    if count == 0 {
        return vec![Vec::new()];
    }
    let mut found = Vec::new();
    for (i, &last) in joints.iter().enumerate().rev() {
        for mut head in subsets(&joints[..i], count - 1) {
            head.push(last);
            found.push(head);
        }
    }
    found
}

/// The smallest singular value of how the solved joints turn the camera against the goal
/// at `q`: near 0 where two of them turn it about the same axis.
fn conditioning(model: &ArmModel, wrist: &Wrist, q: &Joints) -> f64 {
    let Wrist::Numerical { joints, count } = *wrist else {
        return 0.0;
    };
    let frames = model.link_frames(q);
    let turns = nalgebra::DMatrix::from_fn(3, count, |r, c| {
        let j = joints[c];
        (frames[j].rotation * model.joints[j].axis.into_inner())[r]
    });
    turns.singular_values().min()
}

impl ArmPose {
    /// The camera's pose without the camera turn (what the wrist aims).
    fn camera_unturned(&self, model: &ArmModel) -> Isometry3<f64> {
        self.camera * model.camera_mount().inverse() * model.unturned_mount()
    }
}

/// The angle of joint `j` that turns the optical axis straight down, from the frames with
/// that joint at 0 (the OSCAR-6's θ5 formula for any one joint).
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

/// The camera orientation the wrist aims at: z straight down, x radially outwards from
/// the base's z axis; `None` on the axis itself.
fn goal_rotation(position: &Vector3<f64>) -> Option<(UnitQuaternion<f64>, Vector3<f64>, f64)> {
    let radius = position.x.hypot(position.y);
    if radius < MIN_RADIUS {
        return None;
    }
    let out = Vector3::new(position.x / radius, position.y / radius, 0.0);
    let down = -Vector3::z();
    let goal = Rotation3::from_basis_unchecked(&[out, down.cross(&out), down]);
    let tangent = Vector3::new(-out.y, out.x, 0.0);
    Some((UnitQuaternion::from_rotation_matrix(&goal), tangent, radius))
}

/// How far (rad) a camera frame is turned from the wrist's goal; `None` on the z axis.
pub(crate) fn orientation_error(camera: &Isometry3<f64>) -> Option<f64> {
    let (goal, _, _) = goal_rotation(&camera.translation.vector)?;
    Some((goal * camera.rotation.inverse()).angle())
}

/// Newton steps on the solved wrist joints of `q` until the camera meets the goal; the
/// flange's pose when it does. `prefix` is the frame before the first solved joint, which
/// the wrist does not move.
fn newton(
    model: &ArmModel,
    wrist: &Wrist,
    prefix: &Isometry3<f64>,
    q: &mut Joints,
) -> Option<Isometry3<f64>> {
    let Wrist::Numerical { joints, count } = *wrist else {
        return None;
    };
    for _ in 0..MAX_STEPS {
        let mut pose = *prefix;
        let mut axes = [Vector3::zeros(); 3];
        let mut origins = [Vector3::zeros(); 3];
        for (k, joint) in model.joints.iter().enumerate().skip(joints[0]) {
            pose *= joint.transform(q[k]);
            if let Some(s) = joints[..count].iter().position(|&j| j == k) {
                axes[s] = pose.rotation * joint.axis.into_inner();
                origins[s] = pose.translation.vector;
            }
        }
        let camera = pose * model.unturned_mount();
        let p = camera.translation.vector;
        let (goal, tangent, radius) = goal_rotation(&p)?;
        let error = (goal * camera.rotation.inverse()).scaled_axis();
        if !error.iter().all(|e| e.is_finite()) {
            return None;
        }
        if error.norm() < TOLERANCE_RAD {
            return Some(pose);
        }
        // d(error)/d(angle): the camera turns about the joint's axis, and the goal turns
        // about z as the camera centre moves around the base.
        let mut jacobian = Matrix3::zeros();
        for s in 0..count {
            let moved = axes[s].cross(&(p - origins[s]));
            let column = axes[s] - Vector3::z() * (tangent.dot(&moved) / radius);
            jacobian.set_column(s, &column);
        }
        // Damped least squares: Newton's step where the joints turn the camera about
        // three axes, a least-squares step with fewer joints (unused columns are 0 and
        // held by the damping).
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
        let step = normal.lu().solve(&(jacobian.transpose() * error));
        let step = step?;
        let scale = (MAX_STEP_RAD / step.amax()).min(1.0);
        for s in 0..count {
            q[joints[s]] += step[s] * scale;
        }
    }
    None
}

/// Moves solved angles outside their limits by whole turns when that brings them inside.
fn wrap_into_limits(model: &ArmModel, wrist: &Wrist, q: &mut Joints) {
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

impl ArmModel {
    /// ∂(camera centre)/∂(θ1, θ2, θ3) at `q` with a numerical wrist following the
    /// orientation goal (by the implicit function theorem, from one pass down the chain);
    /// `None` for other wrists or where the wrist is singular.
    pub(crate) fn followed_jacobian(&self, q: &Joints) -> Option<Matrix3<f64>> {
        let Wrist::Numerical { joints, count: 3 } = self.wrist else {
            return None;
        };
        let mut pose = Isometry3::identity();
        let mut axes = [Vector3::zeros(); MAX_JOINTS];
        let mut origins = [Vector3::zeros(); MAX_JOINTS];
        for (k, joint) in self.joints.iter().enumerate() {
            pose *= joint.transform(q[k]);
            axes[k] = pose.rotation * joint.axis.into_inner();
            origins[k] = pose.translation.vector;
        }
        let p = (pose * self.unturned_mount()).translation.vector;
        let (_, tangent, radius) = goal_rotation(&p)?;
        // For joint k: how it moves the camera centre, and how it turns the camera
        // against the goal.
        let moves = |k: usize| axes[k].cross(&(p - origins[k]));
        let turns = |k: usize| axes[k] - Vector3::z() * (tangent.dot(&moves(k)) / radius);
        let wrist_turns = Matrix3::from_fn(|r, c| turns(joints[c])[r]);
        let wrist_moves = Matrix3::from_fn(|r, c| moves(joints[c])[r]);
        let learned_turns = Matrix3::from_fn(|r, c| turns(self.learned[c])[r]);
        let learned_moves = Matrix3::from_fn(|r, c| moves(self.learned[c])[r]);
        let follow = wrist_turns.lu().solve(&learned_turns)?;
        Some(learned_moves - wrist_moves * follow)
    }
}
