//! The serial arms of a public robot collection, PyPI's `example-robot-data` (its
//! `share/example-robot-data` folder named by `EYEHAND_ROBOT_DATA`; scripts/test-all.sh
//! installs the package and sets it): every arm, from its URDF alone, either fits a reach
//! space and learns, or is refused with its reason; and every one loads all its meshes
//! (COLLADA, STL, OBJ; `package://` found in the folder tree, no `package_paths`).

use eyehand::robot::description::{DescriptionOptions, RobotDescription};
use std::path::PathBuf;
use std::process::Command;

/// The variable naming the collection's `share/example-robot-data` folder.
const ROBOT_DATA: &str = "EYEHAND_ROBOT_DATA";

/// What an arm does with nothing but `--urdf`.
#[derive(Debug, Clone, Copy)]
enum Verdict {
    /// A run fits a space and lin5's 4-step mean is at most this (mm) after `TRIALS`.
    Learns(f64),
    /// The run is refused (exit 2) with this in its reason.
    Refused(&'static str),
}

/// Trials of each learning run (the test profile; docs/ARMS.md's table has 20,000).
const TRIALS: &str = "5000";

/// An arm of the collection: its URDF under `robots/` and what it does.
struct Arm {
    urdf: &'static str,
    verdict: Verdict,
}

/// Every serial arm of the collection: a chain from a fixed base to a link that can carry
/// a camera (legged robots, hands, humanoids' whole bodies and flying bases are not arms).
const ARMS: &[Arm] = &[
    Arm {
        urdf: "panda_description/urdf/panda.urdf",
        verdict: Verdict::Learns(0.5),
    },
    Arm {
        urdf: "xarm_description/urdf/xarm7.urdf",
        verdict: Verdict::Learns(0.5),
    },
    // The camera on link 6 looks along its z axis, back into the arm.
    Arm {
        urdf: "kinova_description/robots/kinova.urdf",
        verdict: Verdict::Refused("looks back into the arm"),
    },
    Arm {
        urdf: "ur_description/urdf/ur3_robot.urdf",
        verdict: Verdict::Learns(0.5),
    },
    Arm {
        urdf: "ur_description/urdf/ur5_robot.urdf",
        verdict: Verdict::Learns(0.5),
    },
    Arm {
        urdf: "ur_description/urdf/ur10_robot.urdf",
        verdict: Verdict::Learns(0.5),
    },
    Arm {
        urdf: "z1_description/urdf/z1.urdf",
        verdict: Verdict::Refused("the wrist could not look down at 87%"),
    },
    Arm {
        urdf: "so_arm_description/urdf/so100.urdf",
        verdict: Verdict::Learns(0.5),
    },
    Arm {
        urdf: "so_arm_description/urdf/so101.urdf",
        verdict: Verdict::Refused("the camera on `gripper_link` cannot look down"),
    },
    // One arm of a humanoid, as the collection cuts it out.
    Arm {
        urdf: "talos_data/robots/talos_left_arm.urdf",
        verdict: Verdict::Refused("the wrist could not look down at 76%"),
    },
];

fn robots() -> PathBuf {
    let folder = std::env::var_os(ROBOT_DATA).unwrap_or_else(|| {
        panic!(
            "{ROBOT_DATA} is not set: install the collection (`pip install --no-deps \
             example-robot-data==6.0.0`, as scripts/test-all.sh does) and set it to its \
             share/example-robot-data folder"
        )
    });
    let robots = PathBuf::from(folder).join("robots");
    assert!(
        robots.is_dir(),
        "{ROBOT_DATA}: no folder {}",
        robots.display()
    );
    robots
}

#[test]
fn every_arm_loads_all_its_meshes_without_package_paths() {
    let robots = robots();
    for arm in ARMS {
        let path = robots.join(arm.urdf);
        let description = RobotDescription::load(&path, &DescriptionOptions::default())
            .unwrap_or_else(|e| panic!("{}: {e}", arm.urdf));
        assert_eq!(description.warnings, [], "{}", arm.urdf);
    }
}

#[test]
fn every_serial_arm_learns_or_is_refused_with_its_reason() {
    let robots = robots();
    let data = tempfile::tempdir().unwrap();
    for (i, arm) in ARMS.iter().enumerate() {
        let folder = data.path().join(i.to_string());
        let urdf = robots.join(arm.urdf);
        let args = [
            "run".to_string(),
            "--urdf".into(),
            urdf.display().to_string(),
            "--trials".into(),
            TRIALS.into(),
            "--seed".into(),
            "1".into(),
            "--data".into(),
            folder.display().to_string(),
            "--quiet".into(),
            "--no-plot".into(),
        ];
        let out = Command::new(env!("CARGO_BIN_EXE_eyehand"))
            .args(&args)
            .output()
            .unwrap();
        let err = String::from_utf8_lossy(&out.stderr);
        match arm.verdict {
            Verdict::Refused(reason) => {
                assert_eq!(out.status.code(), Some(2), "{}: {err}", arm.urdf);
                assert!(err.contains(reason), "{}: `{reason}` in {err}", arm.urdf);
            }
            Verdict::Learns(most) => {
                assert_eq!(out.status.code(), Some(0), "{}: {err}", arm.urdf);
                let summary = std::fs::read_to_string(folder.join("lin5/0/summary.json"))
                    .unwrap_or_else(|e| panic!("{}: summary.json: {e}", arm.urdf));
                let summary: serde_json::Value = serde_json::from_str(&summary).unwrap();
                let four = summary["mean_distance_mm"][3].as_f64();
                assert!(
                    four.is_some_and(|mm| mm <= most),
                    "{}: 4-step mean {four:?} mm",
                    arm.urdf
                );
            }
        }
    }
}
