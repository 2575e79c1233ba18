//! The arm's kinematic model: forward kinematics from the URDF's joint origins and axes,
//! the wrist angle that keeps the optical axis vertical, link stretching and camera turning.

use super::ik::GuessGeometry;
use super::joint::{LinkBody, RevoluteJoint};
use super::RobotError;
use nalgebra::{Isometry3, Point3, Unit, UnitQuaternion, Vector3, Vector6};

/// All six joint angles θ1..θ6 (rad).
pub type Joints = Vector6<f64>;
/// The three controlled joint angles θ1, θ2, θ3 (rad).
pub type Controlled = Vector3<f64>;

/// A controlled pose worked out once: its six angles, the camera frame's pose and the
/// joint frames with θ4 = θ5 = θ6 = 0 (the wrist angle and the elbow test read those).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ArmPose {
    /// θ1..θ6: θ4 = θ6 = 0, θ5 keeping the optical axis vertical.
    pub joints: Joints,
    /// The camera frame's pose in the world (z along the optical axis).
    pub camera: Isometry3<f64>,
    /// The six joint frames for (θ1, θ2, θ3, 0, 0, 0).
    pub level_frames: [Isometry3<f64>; 6],
}

/// The OSCAR-6 as its URDF describes it, plus the run-time changes made to it.
#[derive(Debug, Clone, PartialEq)]
pub struct ArmModel {
    name: String,
    joints: [RevoluteJoint; 6],
    nominal_origins: [Isometry3<f64>; 6],
    /// The fixed camera joint's origin in link 6, as the URDF gives it.
    urdf_mount: Isometry3<f64>,
    camera_turn: f64,
    /// `urdf_mount` turned by `camera_turn`, kept up to date with it.
    camera_mount: Isometry3<f64>,
    links: Vec<LinkBody>,
    /// The link lengths the inverse kinematics starts from, kept up to date with the links.
    guess: GuessGeometry,
}

impl ArmModel {
    /// A model from its parts: the six revolute joints in chain order, the fixed camera
    /// joint's origin in link 6, and the link bodies (root, links 1–6, camera link).
    pub fn new(
        name: String,
        joints: [RevoluteJoint; 6],
        camera_mount: Isometry3<f64>,
        links: Vec<LinkBody>,
    ) -> ArmModel {
        let nominal_origins = joints.clone().map(|j| j.origin);
        let mut model = ArmModel {
            name,
            joints,
            nominal_origins,
            urdf_mount: camera_mount,
            camera_turn: 0.0,
            camera_mount,
            links,
            guess: GuessGeometry::default(),
        };
        model.update_derived();
        model
    }

    /// Recomputes what is derived from the joints and the camera turn.
    fn update_derived(&mut self) {
        self.camera_mount =
            self.urdf_mount * UnitQuaternion::from_axis_angle(&Vector3::z_axis(), self.camera_turn);
        self.guess = GuessGeometry::of(self);
    }

    /// The link lengths the inverse kinematics starts from.
    pub(super) fn guess_geometry(&self) -> &GuessGeometry {
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

    /// The six revolute joints, joint 1 first.
    pub fn joints(&self) -> &[RevoluteJoint; 6] {
        &self.joints
    }

    /// Link bodies: the root link, links 1–6 and the camera link.
    pub fn links(&self) -> &[LinkBody] {
        &self.links
    }

    /// The fixed camera joint's pose in link 6, including any camera turn.
    pub fn camera_mount(&self) -> Isometry3<f64> {
        self.camera_mount
    }

    /// Poses of the six joint frames (the child links' frames) in the world frame.
    pub fn link_frames(&self, q: &Joints) -> [Isometry3<f64>; 6] {
        let mut frames = [Isometry3::identity(); 6];
        let mut pose = Isometry3::identity();
        for (i, joint) in self.joints.iter().enumerate() {
            pose *= joint.transform(q[i]);
            frames[i] = pose;
        }
        frames
    }

    /// The camera frame's pose in the world (z along the optical axis).
    pub fn camera_pose(&self, q: &Joints) -> Isometry3<f64> {
        self.link_frames(q)[5] * self.camera_mount()
    }

    /// The camera centre in the world.
    pub fn camera_position(&self, q: &Joints) -> Point3<f64> {
        self.camera_pose(q) * Point3::origin()
    }

    /// A controlled pose worked out with one pass down the chain: the same numbers as
    /// [`full_pose`](Self::full_pose) and [`camera_pose`](Self::camera_pose), at about half
    /// their cost together.
    pub fn pose_of(&self, theta: &Controlled) -> ArmPose {
        let level_frames = self.link_frames(&Joints::new(theta.x, theta.y, theta.z, 0.0, 0.0, 0.0));
        let wrist = self.wrist_angle_from(&level_frames);
        // The chain again from joint 5 on, as `link_frames` walks it.
        let mut flange = level_frames[3];
        flange *= self.joints[4].transform(wrist);
        flange *= self.joints[5].transform(0.0);
        ArmPose {
            joints: Joints::new(theta.x, theta.y, theta.z, 0.0, wrist, 0.0),
            camera: flange * self.camera_mount(),
            level_frames,
        }
    }

    /// θ5 that makes the optical axis point straight down for these θ1..θ3 (θ4 = θ6 = 0).
    pub fn vertical_wrist_angle(&self, theta: &Controlled) -> f64 {
        let q = Joints::new(theta.x, theta.y, theta.z, 0.0, 0.0, 0.0);
        self.wrist_angle_from(&self.link_frames(&q))
    }

    /// θ5 from the joint frames of (θ1, θ2, θ3, 0, 0, 0).
    fn wrist_angle_from(&self, frames: &[Isometry3<f64>; 6]) -> f64 {
        let axis = frames[4].rotation * self.joints[4].axis.into_inner();
        let optical = (frames[5] * self.camera_mount()).rotation * Vector3::z();
        let down = -Vector3::z();
        let along = |v: Vector3<f64>| v - axis * axis.dot(&v);
        let (from, to) = (along(optical), along(down));
        axis.dot(&from.cross(&to)).atan2(from.dot(&to))
    }

    /// All six angles for a controlled pose: θ4 = θ6 = 0, θ5 keeping the camera vertical.
    pub fn full_pose(&self, theta: &Controlled) -> Joints {
        Joints::new(
            theta.x,
            theta.y,
            theta.z,
            0.0,
            self.vertical_wrist_angle(theta),
            0.0,
        )
    }

    /// The joint (0-based) whose limits `q` violates first, if any.
    pub fn violated_limit(&self, q: &Joints) -> Option<usize> {
        (0..6).find(|&i| !self.joints[i].admits(q[i]))
    }

    /// Checks that a controlled pose and its wrist angle are inside the joint limits.
    pub fn check_limits(&self, theta: &Controlled) -> Result<Joints, RobotError> {
        self.check_joint_limits(&self.full_pose(theta))
    }

    /// Checks that all six angles `q` are inside the joint limits.
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

    /// How much link 1, 2 or 3 is longer than in the URDF (m).
    pub fn link_stretch(&self, link: usize) -> f64 {
        let nominal = self.nominal_origins[link].translation.vector;
        (self.joints[link].origin.translation.vector - nominal).dot(&nominal.normalize())
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
