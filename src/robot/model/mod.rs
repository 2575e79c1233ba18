//! The arm's kinematic model: forward kinematics from the URDF's joint origins and axes,
//! the three learned joints, the wrist that keeps the optical axis vertical, link
//! stretching and camera turning.

mod branch;
mod build;
mod frames;
pub(crate) mod ik;
mod ik_seeds;
mod joint;
mod joint_vector;
mod wrist;

pub(crate) use branch::side_of;
pub use branch::{Branch, Centre, PoseGrid};
pub use build::{ArmSettings, BaseLink, CameraLink, LearnedJoints};
pub use frames::Frames;
pub(crate) use wrist::tilting;
pub use wrist::Wrist;

use super::RobotError;
use ik::GuessGeometry;
use ik_seeds::IkSeeds;
pub use joint::{LinkBody, RevoluteJoint};
pub use joint_vector::{Joints, MAX_JOINTS};
use nalgebra::{Isometry3, Point3, Unit, UnitQuaternion, Vector3};

/// The three learned joint angles (rad): the study's θ1 (base yaw), θ2 (shoulder), θ3
/// (elbow), whichever joints of the chain play those roles.
pub type Controlled = Vector3<f64>;

/// A controlled pose worked out once: every joint's angle, the camera frame's pose and
/// the joint frames with the wrist at its rest angles (the elbow test reads those).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ArmPose {
    /// Every joint: the learned ones as asked, the wrist keeping the camera vertical.
    pub joints: Joints,
    /// The camera frame's pose in the world (z along the optical axis).
    pub camera: Isometry3<f64>,
    /// The joint frames with the learned joints as asked and the others at rest.
    pub level_frames: Frames,
    /// The joint frames of `joints` (as [`ArmModel::link_frames`] gives them).
    pub frames: Frames,
    /// False when no wrist angles turn the optical axis straight down (the pose is then
    /// outside the arm's reach; `joints` holds the last attempt).
    pub wrist_found: bool,
}

/// An arm as its URDF describes it, plus the run-time changes made to it.
#[derive(Debug, Clone, PartialEq)]
pub struct ArmModel {
    name: String,
    joints: Vec<RevoluteJoint>,
    nominal_origins: Vec<Isometry3<f64>>,
    /// The camera's pose in the last joint's frame, as the URDF and config give it.
    urdf_mount: Isometry3<f64>,
    camera_turn: f64,
    /// `urdf_mount` turned by `camera_turn`, kept up to date with it.
    camera_mount: Isometry3<f64>,
    links: Vec<LinkBody>,
    /// The chain indices of the three learned joints.
    learned: [usize; 3],
    /// Every joint at rest: the learned ones at 0 (clamped), the rest where the wrist
    /// solver starts from.
    rest: Joints,
    /// How the other joints keep the camera vertical.
    wrist: Wrist,
    /// The link lengths the inverse kinematics starts from, kept up to date with the links.
    guess: GuessGeometry,
    /// Starting poses of the inverse kinematics of an arm not of the OSCAR-6 form.
    seeds: IkSeeds,
    /// The branch of its solutions the inverse kinematics of an arm not of the OSCAR-6
    /// form keeps to (`None` when no pose of the arm looks down).
    branch: Option<Branch>,
    /// Whether the arm is of the OSCAR-6 form ([`is_oscar6_form`](Self::is_oscar6_form)),
    /// decided once when it is built.
    oscar6_form: bool,
}

impl ArmModel {
    /// The OSCAR-6 form: six revolute joints in chain order, the first three learned, the
    /// fixed camera joint's origin in link 6, and the link bodies (root, links 1–6,
    /// camera link).
    pub fn new(
        name: String,
        joints: [RevoluteJoint; 6],
        camera_mount: Isometry3<f64>,
        links: Vec<LinkBody>,
    ) -> ArmModel {
        ArmModel::from_parts(name, joints.to_vec(), [0, 1, 2], camera_mount, links)
            .expect("six revolute joints, the first three learned")
    }

    /// A model of any chain: revolute joints in chain order (at most [`MAX_JOINTS`]), the
    /// chain indices of the three learned joints, the camera's pose in the last joint's
    /// frame and the link bodies (root, one per joint, camera link).
    pub fn from_parts(
        name: String,
        joints: Vec<RevoluteJoint>,
        learned: [usize; 3],
        camera_mount: Isometry3<f64>,
        links: Vec<LinkBody>,
    ) -> Result<ArmModel, RobotError> {
        if joints.len() > MAX_JOINTS || learned.iter().any(|&i| i >= joints.len()) {
            return Err(RobotError::ChainTooLong {
                joints: joints.len(),
                max: MAX_JOINTS,
            });
        }
        let nominal_origins = joints.iter().map(|j| j.origin).collect();
        let rest = Joints::from_fn(joints.len(), |i| {
            0.0_f64.clamp(joints[i].lower, joints[i].upper)
        });
        let mut model = ArmModel {
            name,
            joints,
            nominal_origins,
            urdf_mount: camera_mount,
            camera_turn: 0.0,
            camera_mount,
            links,
            learned,
            rest,
            wrist: Wrist::None,
            guess: GuessGeometry::default(),
            seeds: IkSeeds::default(),
            branch: None,
            oscar6_form: false,
        };
        (model.wrist, model.rest) = Wrist::choose(&model);
        model.oscar6_form =
            model.dof() == 6 && model.learned == [0, 1, 2] && model.wrist == Wrist::OneJoint(4);
        model.update_derived();
        model.oscar6_form = model.oscar6_form && model.closed_form_answers();
        if !model.is_oscar6_form() {
            model.branch = Branch::kinematic(&model);
            model.seeds = IkSeeds::of(&model);
        }
        Ok(model)
    }

    /// Recomputes what is derived from the joints and the camera turn.
    fn update_derived(&mut self) {
        self.camera_mount =
            self.urdf_mount * UnitQuaternion::from_axis_angle(&Vector3::z_axis(), self.camera_turn);
        let wrist = self.wrist;
        wrist.settle_rest(self);
        self.guess = GuessGeometry::of(self);
        if !self.is_oscar6_form() {
            self.seeds = IkSeeds::of(self);
        }
    }

    /// Keeps the inverse kinematics of an arm not of the OSCAR-6 form to `branch` (the one
    /// its reach space was fitted on, [`ReachFit::branch`](crate::robot::ReachFit)); the
    /// OSCAR-6 form keeps its elbow up.
    pub fn keep_branch(&mut self, branch: Branch) {
        self.branch = Some(branch);
        if !self.is_oscar6_form() {
            self.seeds = IkSeeds::of(self);
        }
    }

    /// The branch of its solutions the inverse kinematics keeps to (see
    /// [`keep_branch`](Self::keep_branch)).
    pub fn branch(&self) -> Option<&Branch> {
        self.branch.as_ref()
    }

    /// Starting poses of the inverse kinematics.
    fn ik_seeds(&self) -> &IkSeeds {
        &self.seeds
    }

    /// The link lengths the inverse kinematics starts from.
    fn guess_geometry(&self) -> &GuessGeometry {
        &self.guess
    }

    /// The shipped OSCAR-6 (`urdf/oscar6.urdf`).
    pub fn oscar6() -> ArmModel {
        super::parse_urdf(super::DEFAULT_URDF, super::DEFAULT_URDF_NAME)
            .expect("the shipped URDF is valid")
    }

    /// The robot's name in the URDF.
    pub fn name(&self) -> &str {
        &self.name
    }

    /// The chain's revolute joints, joint 1 first.
    pub fn joints(&self) -> &[RevoluteJoint] {
        &self.joints
    }

    /// How many joints the chain has.
    pub fn dof(&self) -> usize {
        self.joints.len()
    }

    /// The chain indices of the three learned joints (θ1, θ2, θ3).
    pub fn learned(&self) -> [usize; 3] {
        self.learned
    }

    /// How the wrist is solved.
    pub fn wrist(&self) -> &Wrist {
        &self.wrist
    }

    /// True for the OSCAR-6 form: six joints, the first three learned, joint 5 alone keeping
    /// the camera looking down in closed form, and the inverse kinematics' closed-form
    /// guess with the elbow-up rule giving back the arm's own elbow-up poses (a base axis
    /// pointing down or limits past half a turn leave an arm of this shape out: it keeps
    /// to a branch of its solutions instead).
    pub fn is_oscar6_form(&self) -> bool {
        self.oscar6_form
    }

    /// Link bodies: the root link, one per joint and the camera link.
    pub fn links(&self) -> &[LinkBody] {
        &self.links
    }

    /// The camera's pose in the last joint's frame, including any camera turn.
    pub fn camera_mount(&self) -> Isometry3<f64> {
        self.camera_mount
    }

    /// The camera's pose in the last joint's frame without the camera turn.
    pub(crate) fn unturned_mount(&self) -> Isometry3<f64> {
        self.urdf_mount
    }

    /// The learned angles of a full joint vector.
    pub fn controlled_of(&self, q: &Joints) -> Controlled {
        Controlled::from_fn(|i, _| q[self.learned[i]])
    }

    /// Every joint at rest with the learned ones at `theta`.
    pub fn with_learned(&self, theta: &Controlled) -> Joints {
        let mut q = self.rest;
        for (i, &j) in self.learned.iter().enumerate() {
            q[j] = theta[i];
        }
        q
    }

    /// Every joint at rest (learned ones at 0 clamped into their limits).
    pub fn rest(&self) -> Joints {
        self.rest
    }

    /// Poses of the joint frames (the child links' frames) in the world frame.
    pub fn link_frames(&self, q: &Joints) -> Frames {
        let mut frames = Frames::identities(self.joints.len());
        let mut pose = Isometry3::identity();
        for (i, joint) in self.joints.iter().enumerate() {
            pose *= joint.transform(q[i]);
            frames.set(i, pose);
        }
        frames
    }

    /// The camera frame's pose in the world (z along the optical axis).
    pub fn camera_pose(&self, q: &Joints) -> Isometry3<f64> {
        self.link_frames(q).last() * self.camera_mount()
    }

    /// The camera centre in the world.
    pub fn camera_position(&self, q: &Joints) -> Point3<f64> {
        self.camera_pose(q) * Point3::origin()
    }

    /// A controlled pose worked out: the wrist solved from its rest angles.
    pub fn pose_of(&self, theta: &Controlled) -> ArmPose {
        self.pose_near(theta, &self.rest)
    }

    /// A controlled pose worked out, a numerical wrist solver starting from the wrist
    /// angles of `near` (the last pose, usually).
    pub fn pose_near(&self, theta: &Controlled, near: &Joints) -> ArmPose {
        let level = self.with_learned(theta);
        let level_frames = self.link_frames(&level);
        self.wrist.solve(self, theta, level_frames, near)
    }

    /// Every angle for a controlled pose, the wrist keeping the camera vertical.
    pub fn full_pose(&self, theta: &Controlled) -> Joints {
        self.pose_of(theta).joints
    }

    /// The joint (0-based) whose limits `q` violates first, if any.
    pub fn violated_limit(&self, q: &Joints) -> Option<usize> {
        (0..self.joints.len()).find(|&i| !self.joints[i].admits(q[i]))
    }

    /// Checks that a controlled pose has a wrist solution inside the joint limits.
    pub fn check_limits(&self, theta: &Controlled) -> Result<Joints, RobotError> {
        self.check_pose(&self.pose_of(theta))
    }

    /// Checks that a worked-out pose has a wrist solution inside the joint limits.
    pub fn check_pose(&self, pose: &ArmPose) -> Result<Joints, RobotError> {
        if !pose.wrist_found {
            let theta = self.controlled_of(&pose.joints).map(f64::to_degrees);
            return Err(RobotError::NoWristSolution {
                theta_deg: [theta.x, theta.y, theta.z],
            });
        }
        self.check_joint_limits(&pose.joints)
    }

    /// Checks that every angle of `q` is inside the joint limits.
    pub fn check_joint_limits(&self, q: &Joints) -> Result<Joints, RobotError> {
        match self.violated_limit(q) {
            None => Ok(*q),
            Some(i) => Err(RobotError::OutsideLimits {
                joint: i + 1,
                angle_deg: q[i].to_degrees(),
                lower_deg: self.joints[i].lower.to_degrees(),
                upper_deg: self.joints[i].upper.to_degrees(),
            }),
        }
    }

    /// True when `pose` has a wrist solution whose angles are inside their limits (the
    /// learned joints are not looked at).
    pub fn wrist_fits(&self, pose: &ArmPose) -> bool {
        pose.wrist_found
            && (0..self.joints.len())
                .filter(|i| !self.learned.contains(i))
                .all(|i| self.joints[i].admits(pose.joints[i]))
    }

    /// The first wrist joint (0-based) outside its limits in `pose`, or the first wrist
    /// joint when there is no wrist solution.
    pub fn wrist_joint_at_fault(&self, pose: &ArmPose) -> usize {
        let mut wrist = (0..self.joints.len()).filter(|i| !self.learned.contains(i));
        let first = wrist.clone().next().unwrap_or(0);
        if !pose.wrist_found {
            return first;
        }
        wrist
            .find(|&i| !self.joints[i].admits(pose.joints[i]))
            .unwrap_or(first)
    }

    /// Stretches (positive) or shortens link 1, 2 or 3 by `delta_m` along the joint origin
    /// at its far end; changes add up over calls.
    pub fn stretch_link(&mut self, link: usize, delta_m: f64) -> Result<(), RobotError> {
        if !(1..=3).contains(&link) {
            return Err(RobotError::NoSuchLink(link));
        }
        let nominal = self.nominal_origins[link].translation.vector;
        let current = self.joints[link].origin.translation.vector;
        let direction = Unit::try_new(nominal, 1e-9).ok_or(RobotError::NoSuchLink(link))?;
        let length = direction.dot(&current) + delta_m;
        if length <= 0.01 || !delta_m.is_finite() {
            return Err(RobotError::LinkTooShort {
                link,
                delta_cm: delta_m * 100.0,
                length_cm: length * 100.0,
            });
        }
        self.joints[link].origin.translation.vector = current + direction.into_inner() * delta_m;
        self.update_derived();
        Ok(())
    }

    /// How much link 1, 2 or 3 is longer than in the URDF (m); 0 for a link of no length
    /// (two joints at one point), which cannot be stretched.
    pub fn link_stretch(&self, link: usize) -> f64 {
        let nominal = self.nominal_origins[link].translation.vector;
        match Unit::try_new(nominal, 1e-9) {
            Some(direction) => {
                (self.joints[link].origin.translation.vector - nominal).dot(&direction)
            }
            None => 0.0,
        }
    }

    /// Turns the camera about its optical axis by `angle` (rad); turns add up.
    pub fn rotate_camera(&mut self, angle: f64) {
        self.camera_turn += angle;
        self.update_derived();
    }

    /// The camera's total turn about its optical axis (rad).
    pub fn camera_turn(&self) -> f64 {
        self.camera_turn
    }
}
