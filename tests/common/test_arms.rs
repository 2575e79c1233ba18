//! The arms of the test data beside the OSCAR-6 — the Franka Panda and the hand-made
//! UR-style arm — as tests and benchmarks pick them out: URDF, camera link, learned joints
//! and the learner's boundaries.

#![allow(dead_code)]

use eyehand::robot::description::{DescriptionOptions, RobotDescription};
use eyehand::robot::{ArmModel, ArmSettings};
use nalgebra::Vector3;
use std::path::{Path, PathBuf};

/// An arm of the test data: its URDF, camera link, learned joints and the learner's
/// boundaries for θ2 and θ3 (degrees; `eyehand reach` suggests them).
#[derive(Debug, Clone, Copy)]
pub struct TestArm {
    pub file: &'static str,
    pub camera_link: &'static str,
    pub learned: [&'static str; 3],
    pub boundaries: [f64; 4],
}

/// The Panda, its camera on the hand, joints 1, 2 and 4 learned.
pub const PANDA: TestArm = TestArm {
    file: "panda/panda.urdf",
    camera_link: "panda_hand",
    learned: ["panda_joint1", "panda_joint2", "panda_joint4"],
    boundaries: [-39.0, 84.0, -170.0, -50.0],
};

/// The UR-style arm, its camera on `tool0`.
pub const UR_STYLE: TestArm = TestArm {
    file: "ur_style.urdf",
    camera_link: "tool0",
    learned: ["shoulder_pan_joint", "shoulder_lift_joint", "elbow_joint"],
    boundaries: [-161.0, -64.0, -151.0, -27.0],
};

impl TestArm {
    /// The URDF's path.
    pub fn urdf(&self) -> PathBuf {
        Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("tests/data")
            .join(self.file)
    }

    /// The arm as the simulators take it.
    pub fn model(&self) -> ArmModel {
        let description =
            RobotDescription::load(&self.urdf(), &DescriptionOptions::default()).unwrap();
        let settings = ArmSettings {
            camera_link: self.camera_link.into(),
            camera_offset: Vector3::zeros(),
            learned_joints: self.learned.into(),
            ..ArmSettings::default()
        };
        ArmModel::from_description(&description, &settings).unwrap()
    }

    /// The config entries of a run on this arm.
    pub fn sets(&self) -> Vec<(&'static str, String)> {
        let [b0l, b0h, b1l, b1h] = self.boundaries.map(|v| v.to_string());
        vec![
            ("camera_link", self.camera_link.into()),
            ("learned_joints", self.learned.join(",")),
            ("reach_space", "auto".into()),
            ("boundary_0_low", b0l),
            ("boundary_0_high", b0h),
            ("boundary_1_low", b1l),
            ("boundary_1_high", b1h),
        ]
    }
}
