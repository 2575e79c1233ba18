//! The arm a description gives when the config leaves it to the arm (`camera_link auto`,
//! `learned_joints auto`): the camera on the chain's end short of any gripper part, and the
//! study's three learned joints — base yaw, shoulder, elbow — found by what they do at the
//! rest pose.

use super::{Chain, DescriptionError, DescriptionErrorKind as Kind, JointKind, RobotDescription};
use nalgebra::{Isometry3, Point3, Vector3};

/// The link named so is the camera link where there is one (the OSCAR-6's).
const NAMED_CAMERA_LINK: &str = "camera_link";
/// A joint axis this close to vertical (|z| of its unit vector) turns the arm about the
/// vertical: a base yaw.
const VERTICAL: f64 = 0.99;

/// Words in a moving joint's name that say it moves a part of a gripper, not the arm.
const GRIPPER_WORDS: [&str; 6] = ["gripper", "finger", "jaw", "claw", "knuckle", "thumb"];
/// The flange frame ROS-Industrial descriptions put at the end of the arm.
const TOOL_FRAME: &str = "tool0";

/// The camera link `camera_link auto` picks, and why.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct CameraChoice {
    /// The link's index in the description.
    pub link: usize,
    /// Why, in words.
    pub reason: String,
}

/// The camera link of `camera_link auto`: the link named `camera_link` where there is one,
/// else the link where the chain from link `base` (an index; the root for a whole robot)
/// ends: followed through every single child,
/// and at a branch into the child whose subtree turns most joints, it stops at a leaf or
/// where no child turns a joint any more (a hand whose fingers slide: the hand), or at the
/// link that carries a gripper joint (the hand). It never passes a gripper joint — a moving joint whose name says gripper, finger, jaw, claw,
/// knuckle or thumb, or that mimics or is mimicked by another — so the camera never rides
/// on a part that moves relative to the flange; and where the chain ends in `tool0` (the
/// flange frame of ROS-Industrial descriptions) among fixed children, it is that.
pub fn camera_choice(description: &RobotDescription, base: usize) -> CameraChoice {
    if let Some(link) = description.link_index(NAMED_CAMERA_LINK) {
        return CameraChoice {
            link,
            reason: format!("the link named `{NAMED_CAMERA_LINK}`"),
        };
    }
    let mut at = base;
    let mut gripper = None;
    loop {
        let children: Vec<usize> = description.links[at]
            .child_joints
            .iter()
            .filter(|&&j| {
                let part = moves_a_gripper(description, j);
                if part && gripper.is_none() {
                    gripper = Some(description.joints[j].name.clone());
                }
                !part
            })
            .map(|&j| description.joints[j].child)
            .collect();
        let turning = |link: usize| turning_joints_below(description, link);
        if gripper.is_some() {
            return chain_end(description, at, children, gripper);
        }
        let next = match children.as_slice() {
            [only] => Some(*only),
            _ => children
                .iter()
                .copied()
                .filter(|&c| turning(c) > 0)
                .max_by_key(|&c| turning(c)),
        };
        match next {
            Some(child) => at = child,
            None => return chain_end(description, at, children, gripper),
        }
    }
}

/// The camera link where the walk stopped at `at` (its children past any gripper joint).
fn chain_end(
    description: &RobotDescription,
    at: usize,
    children: Vec<usize>,
    gripper: Option<String>,
) -> CameraChoice {
    let tool = children
        .into_iter()
        .find(|&c| description.links[c].name == TOOL_FRAME);
    if let Some(link) = tool {
        return CameraChoice {
            link,
            reason: format!("`{TOOL_FRAME}`, the flange frame at the end of the chain"),
        };
    }
    let reason = match gripper {
        Some(joint) => format!(
            "the end of the chain before the gripper joint `{joint}` (a gripper's parts move \
             relative to the flange)"
        ),
        None => "the end of the chain".to_string(),
    };
    CameraChoice { link: at, reason }
}

/// True when joint `j` moves and its name says it moves a gripper part, or it mimics or
/// is mimicked by another joint.
fn moves_a_gripper(description: &RobotDescription, j: usize) -> bool {
    let joint = &description.joints[j];
    if !joint.kind.moves() {
        return false;
    }
    let name = joint.name.to_ascii_lowercase();
    GRIPPER_WORDS.iter().any(|word| name.contains(word))
        || joint.mimic.is_some()
        || description
            .joints
            .iter()
            .any(|other| other.mimic.as_ref().is_some_and(|m| m.joint == joint.name))
}

/// Whether the joint into `link` turns.
fn revolute_into(description: &RobotDescription, link: usize) -> bool {
    description.links[link]
        .parent_joint
        .is_some_and(|j| turns(description.joints[j].kind))
}

fn turns(kind: JointKind) -> bool {
    matches!(kind, JointKind::Revolute | JointKind::Continuous)
}

/// Turning joints in the subtree below `link` (the joint into it included).
fn turning_joints_below(description: &RobotDescription, link: usize) -> usize {
    let own = usize::from(revolute_into(description, link));
    own + description.links[link]
        .child_joints
        .iter()
        .map(|&j| turning_joints_below(description, description.joints[j].child))
        .sum::<usize>()
}

impl Chain {
    /// The learned joints of `learned_joints auto`, as indices into `joints`: the base yaw
    /// (the first joint whose axis is vertical at the rest pose), then the two joints after
    /// it that move the camera's distance from that axis and its height most at rest, in
    /// chain order.
    pub fn auto_learned_joints(
        &self,
        description: &RobotDescription,
    ) -> Result<[usize; 3], DescriptionError> {
        let rest = vec![0.0; self.joints.len()];
        let mut bodies = vec![Isometry3::identity(); self.bodies.len()];
        self.body_frames(&rest, &mut bodies)?;
        // The frame of each moving joint's body: the joint's own frame at rest.
        let frames = &bodies[1..];
        let camera = self.camera_pose(&rest, &Isometry3::identity())? * Point3::origin();
        let base = frames
            .iter()
            .zip(&self.joints)
            .position(|(frame, joint)| (frame.rotation * joint.axis).z.abs() >= VERTICAL)
            .ok_or_else(|| description.error(Kind::NoBaseYaw))?;
        let base_at = frames[base].translation.vector;
        let mut moves: Vec<(usize, f64)> = (base + 1..self.joints.len())
            .map(|j| {
                let axis = frames[j].rotation * self.joints[j].axis;
                let lever = camera.coords - frames[j].translation.vector;
                (
                    j,
                    reach_and_height_speed(axis.cross(&lever), camera, base_at),
                )
            })
            .collect();
        moves.sort_by(|a, b| b.1.total_cmp(&a.1));
        let [(a, _), (b, _), ..] = moves[..] else {
            return Err(description.error(Kind::TooFewJointsToLearn {
                after_base: moves.len(),
            }));
        };
        Ok([base, a.min(b), a.max(b)])
    }
}

/// How fast a camera velocity `v` (per radian) changes the camera's distance from the
/// vertical axis through `base` and its height: `v` without its part around that axis.
fn reach_and_height_speed(v: Vector3<f64>, camera: Point3<f64>, base: Vector3<f64>) -> f64 {
    let radial = Vector3::new(camera.x - base.x, camera.y - base.y, 0.0);
    if radial.norm() < 1e-9 {
        return v.norm();
    }
    let around = Vector3::z().cross(&radial).normalize();
    (v - around * v.dot(&around)).norm()
}
