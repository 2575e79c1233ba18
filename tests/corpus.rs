//! The serial arms of a public robot collection, PyPI's `example-robot-data` (its
//! `share/example-robot-data` folder named by `EYEHAND_ROBOT_DATA`; scripts/test-all.sh
//! installs the package and sets it): every arm, from its URDF alone, either fits a reach
//! space and learns, or is refused with its reason; and every one loads all its meshes
//! (COLLADA, STL, OBJ; `package://` found in the folder tree, no `package_paths`).

use eyehand::experiment::setup::{fit_reach, load_arm};
use eyehand::experiment::{Config, PackagePaths};
use eyehand::robot::description::{DescriptionOptions, RobotDescription};
use eyehand::robot::{ArmModel, ReachSpace};
use nalgebra::{Point3, Vector3};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use std::path::{Path, PathBuf};
use std::process::Command;

#[path = "common/robot_data.rs"]
mod robot_data;
use robot_data::{robot_data, ROBOT_DATA};

/// What an arm does with nothing but `--urdf`.
#[derive(Debug, Clone, Copy)]
enum Verdict {
    /// A run fits a space and lin5's 4-step mean is at most [`LEARNED_MM`] after `TRIALS`.
    Learns,
    /// The run is refused (exit 2) with each of these in its reason.
    Refused(&'static [&'static str]),
}

/// Trials of each learning run (the test profile; docs/ARMS.md's table has 20,000).
const TRIALS: &str = "5000";
/// The most lin5's mean distance after 4 steps may be after `TRIALS` (mm).
const LEARNED_MM: f64 = 0.1;

/// An arm of the collection: its URDF under `robots/`, the config entries set on the
/// command line (none: nothing but `--urdf`) and what it does.
struct Arm {
    urdf: &'static str,
    sets: &'static [&'static str],
    verdict: Verdict,
}

/// Every serial arm of the collection: a chain from a fixed base to a link that can carry
/// a camera (legged robots, hands, humanoids' whole bodies and flying bases are not arms).
const ARMS: &[Arm] = &[
    Arm {
        urdf: "panda_description/urdf/panda.urdf",
        sets: &[],
        verdict: Verdict::Learns,
    },
    Arm {
        urdf: "xarm_description/urdf/xarm7.urdf",
        sets: &[],
        verdict: Verdict::Learns,
    },
    // The camera on link 6 looks along its z axis, back into the arm; the refusal names the
    // mount that learns (the next case).
    Arm {
        urdf: KINOVA,
        sets: &[],
        verdict: Verdict::Refused(&[
            "looks back into the arm",
            "a camera looking along the link's -z axis works: with camera_mount 0,0,0,180,0,0",
        ]),
    },
    Arm {
        urdf: KINOVA,
        sets: &[KINOVA_MOUNT],
        verdict: Verdict::Learns,
    },
    Arm {
        urdf: "ur_description/urdf/ur3_robot.urdf",
        sets: &[],
        verdict: Verdict::Learns,
    },
    Arm {
        urdf: "ur_description/urdf/ur5_robot.urdf",
        sets: &[],
        verdict: Verdict::Learns,
    },
    Arm {
        urdf: "ur_description/urdf/ur10_robot.urdf",
        sets: &[],
        verdict: Verdict::Learns,
    },
    // The gripper link's z axis stands square to the gripper: looking down along it needs
    // the three pitch joints to sum to a half turn, which their limits allow in a band of
    // poses a few cm wide. The refusal names the mount that learns (the case after next).
    Arm {
        urdf: "z1_description/urdf/z1.urdf",
        sets: &[],
        verdict: Verdict::Refused(&[
            "the wrist could not look down at 87%",
            "a camera looking along the link's -z axis works: with camera_mount 0,0,0,180,0,0",
        ]),
    },
    Arm {
        urdf: "so_arm_description/urdf/so100.urdf",
        sets: &[],
        verdict: Verdict::Learns,
    },
    // The Z1 with the mount its refusal names.
    Arm {
        urdf: "z1_description/urdf/z1.urdf",
        sets: &["camera_mount=0,0,0,180,0,0"],
        verdict: Verdict::Learns,
    },
    // Along −x (or ±y) at the link's origin, the wrist roll's axis, the camera sits at the
    // surface of `wrist_link` (its roll servo), which hides the object half a millimetre in
    // front of it; the refusal names the mount 5 cm out of the arm (along the link's −z,
    // beside the jaw), which learns (the next case).
    Arm {
        urdf: "so_arm_description/urdf/so101.urdf",
        sets: &[],
        verdict: Verdict::Refused(&[
            "the camera on `gripper_link` cannot look down",
            "a camera looking along the link's -x axis and moved 5 cm out of the arm along its \
             -z axis works: with camera_mount 0,0,-0.05,0,-90,0",
        ]),
    },
    Arm {
        urdf: "so_arm_description/urdf/so101.urdf",
        sets: &["camera_mount=0,0,-0.05,0,-90,0"],
        verdict: Verdict::Learns,
    },
    // One arm of a humanoid, as the collection cuts it out: the refusal names the wrist
    // joint whose limits stop it, what each other axis of the link met, the joints learned
    // and those left to the wrist, and the entries a user can change.
    Arm {
        urdf: "talos_data/robots/talos_left_arm.urdf",
        sets: &[],
        verdict: Verdict::Refused(&[
            "the wrist could not look down at 82% (at 20% it would have to turn \
             `arm_left_2_joint` outside its limits, 0°..165°; at 62% no angles of its joints \
             turn the camera down)",
            "no other axis of the camera link does either (along -z: no reach space fits",
            "along x: no reach space fits, the wrist looking down at 100% of the poses sampled",
            "along y: the wrist cannot turn it down): no camera on this link looking along one \
             of its axes lets the arm work looking down with `arm_left_3_joint`, \
             `arm_left_4_joint`, `arm_left_6_joint` learned (the others, `arm_left_2_joint`, \
             `arm_left_5_joint`, `arm_left_7_joint`, left to turn it down); to use this arm, \
             name other joints for it to learn with learned_joints, another link for the \
             camera with camera_link, or say how the camera is mounted with camera_mount",
        ]),
    },
    // With its shoulder's second joint, upper arm roll and elbow learned and a floor 1.2 m
    // below, along −z (and ±y) a space fits but the camera does not reach its middle, where
    // the pre-learning moves end: with no pre-learning pattern the learner would answer zero
    // moves, so the run is refused and such a mount is no proposal.
    Arm {
        urdf: "talos_data/robots/talos_left_arm.urdf",
        sets: &[
            "learned_joints=arm_left_2_joint,arm_left_3_joint,arm_left_4_joint",
            "floor_z=-120",
        ],
        verdict: Verdict::Refused(&[
            "looks back into the arm",
            "no other axis of the camera link does either (along -z: the middle of the \
             space it fits is not reached looking down;",
            "along y: the middle of the space it fits is not reached looking down)",
        ]),
    },
    // The same arm with the camera along −z, as a user would try it: refused before a run
    // (every other check passes, and a run would learn nothing: it never moves).
    Arm {
        urdf: "talos_data/robots/talos_left_arm.urdf",
        sets: &[
            "learned_joints=arm_left_2_joint,arm_left_3_joint,arm_left_4_joint",
            "floor_z=-120",
            "camera_mount=0,0,0,180,0,0",
        ],
        verdict: Verdict::Refused(&[
            "no pre-learning move can be made: the camera cannot reach the middle of the \
             reach space",
            "a learner given no pattern answers zero moves",
        ]),
    },
];

fn robots() -> PathBuf {
    let robots = robot_data().join("robots");
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
        let sets = arm
            .sets
            .iter()
            .flat_map(|set| ["--set".to_string(), set.to_string()]);
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
            .args(sets)
            .output()
            .unwrap();
        let err = String::from_utf8_lossy(&out.stderr);
        match arm.verdict {
            Verdict::Refused(reasons) => {
                assert_eq!(out.status.code(), Some(2), "{}: {err}", arm.urdf);
                for reason in reasons {
                    assert!(err.contains(reason), "{}: `{reason}` in {err}", arm.urdf);
                }
            }
            Verdict::Learns => {
                assert_eq!(out.status.code(), Some(0), "{}: {err}", arm.urdf);
                let summary = std::fs::read_to_string(folder.join("lin5/0/summary.json"))
                    .unwrap_or_else(|e| panic!("{}: summary.json: {e}", arm.urdf));
                let summary: serde_json::Value = serde_json::from_str(&summary).unwrap();
                let four = summary["mean_distance_mm"][3].as_f64();
                assert!(
                    four.is_some_and(|mm| mm <= LEARNED_MM),
                    "{}: 4-step mean {four:?} mm",
                    arm.urdf
                );
            }
        }
    }
}

/// The collection's UR5.
const UR5: &str = "ur_description/urdf/ur5_robot.urdf";
/// The collection's Kinova Jaco (j2s6s200), and the mount its refusal names: the camera
/// looking along link 6's −z axis, out of the hand.
const KINOVA: &str = "kinova_description/robots/kinova.urdf";
const KINOVA_MOUNT: &str = "camera_mount=0,0,0,180,0,0";

/// The UR5 of the collection with its `world_joint` placing the base at `rpy` instead of
/// its own, written into `folder` (its meshes found through `package_paths`: the
/// collection's `share` folder), and the config that reads it with the floor at `floor_cm`.
fn ur5_placed(folder: &Path, rpy: &str, floor_cm: f64) -> (PathBuf, Config) {
    let robots = robots();
    let text = std::fs::read_to_string(robots.join(UR5)).unwrap();
    let own = r#"<child link="base_link"/>
    <origin rpy="0.0 0.0 0.0" xyz="0.0 0.0 0.0"/>"#;
    assert!(text.contains(own), "the UR5's world_joint is as it was");
    let placed = format!("<child link=\"base_link\"/>\n    <origin rpy=\"{rpy}\" xyz=\"0 0 0\"/>");
    let urdf = folder.join("ur5_placed.urdf");
    std::fs::write(&urdf, text.replace(own, &placed)).unwrap();
    let share = robots.parent().unwrap().parent().unwrap().to_path_buf();
    let config = Config {
        package_paths: PackagePaths(vec![share]),
        floor_z: floor_cm,
        ..Config::default_config()
    };
    (urdf, config)
}

/// The arm of `urdf` with its reach space fitted (the model keeping to the branch).
fn fitted(config: &Config, urdf: &Path) -> (ArmModel, ReachSpace) {
    let mut model = load_arm(config, Some(urdf)).unwrap().model;
    let fit = fit_reach(config, &mut model).unwrap_or_else(|why| panic!("{why}"));
    (model, fit.space)
}

/// How many of `count` seeded targets in `space` the arm reaches.
fn solved(model: &ArmModel, space: &ReachSpace, count: usize) -> usize {
    let mut rng = ChaCha8Rng::seed_from_u64(2);
    (0..count)
        .filter(|_| model.solve_camera_position(&space.sample(&mut rng)).is_ok())
        .count()
}

/// The UR arms were refused: an elbow-up rule built from joint origins (the first wrist
/// joint's taken as the wrist, a few cm off the forearm) turned away three quarters of
/// their poses. Without it, the UR5's space is fitted on one branch of its solutions:
/// every target is reached, and targets a millimetre apart by poses a fraction of a degree
/// apart (no jump to another branch, no whole turn between them).
#[test]
fn the_ur5_is_solved_on_one_branch_without_an_elbow_rule() {
    let urdf = robots().join(UR5);
    let (model, space) = fitted(&Config::default_config(), &urdf);
    assert_eq!(solved(&model, &space, 500), 500, "{space:?}");
    let mut rng = ChaCha8Rng::seed_from_u64(3);
    for _ in 0..300 {
        let target = space.sample(&mut rng);
        let nudge = Vector3::from_fn(|_, _| rng.random_range(-1e-3..1e-3));
        let near = Point3::from(target.coords + nudge);
        let (Ok(a), Ok(b)) = (
            model.solve_camera_position(&target),
            model.solve_camera_position(&near),
        ) else {
            continue;
        };
        assert!(model.is_on_branch(&a), "{target:?}: {a:?}");
        assert!(
            (a - b).amax() < 1f64.to_radians(),
            "{target:?}: {a:?} and {b:?}"
        );
    }
}

/// A base frame upside down (joint 1's axis pointing down, the arm hanging from above the
/// floor) was refused with 21% of its space reached; a base turned about the vertical must
/// fit the space the arm fits unturned.
#[test]
fn a_base_upside_down_or_turned_fits_and_reaches_its_space() {
    let folder = tempfile::tempdir().unwrap();
    let (urdf, config) = ur5_placed(folder.path(), "3.14159265359 0 0", -150.0);
    let (model, space) = fitted(&config, &urdf);
    assert!(solved(&model, &space, 500) >= 495, "{space:?}");
    let (urdf, config) = ur5_placed(folder.path(), "0 0 1.2", -22.0);
    let (turned, space) = fitted(&config, &urdf);
    assert_eq!(solved(&turned, &space, 500), 500, "{space:?}");
    let (_, own) = fitted(&Config::default_config(), &robots().join(UR5));
    for (a, b) in [
        (space.r_min, own.r_min),
        (space.r_max, own.r_max),
        (space.z_min, own.z_min),
        (space.z_max, own.z_max),
    ] {
        assert!(
            (a - b).abs() < 0.01,
            "{space:?} turned, {own:?} as it comes"
        );
    }
}

/// The Kinova looking out of its hand was refused with a tenth of its fitted space reached:
/// its six joints, the first three learned and joint 5 alone turning the camera down, were
/// taken for the OSCAR-6's form, whose closed-form guess and elbow-up rule do not hold for
/// a base axis pointing down (the inverse kinematics then answered "only an elbow-down pose
/// reaches it"); its shoulder and elbow limits (47°..313°, 19°..341°) were sampled only up
/// to 180°; and joint 5 (30°..330°) was given the angle within half a turn of its rest,
/// outside its limits where a whole turn on would be inside. Now it keeps to a branch,
/// reaches every target of a space fitted over its whole limits, with joint 5 past 180°
/// where it needs to be; the OSCAR-6 keeps its form.
#[test]
fn the_kinova_looking_out_of_its_hand_reaches_its_whole_space() {
    assert!(ArmModel::oscar6().is_oscar6_form());
    let mut config = Config::default_config();
    let (name, value) = KINOVA_MOUNT.split_once('=').unwrap();
    config.set(name, value).unwrap();
    let (model, space) = fitted(&config, &robots().join(KINOVA));
    assert!(!model.is_oscar6_form());
    assert_eq!(solved(&model, &space, 500), 500, "{space:?}");
    let mut rng = ChaCha8Rng::seed_from_u64(4);
    let (mut shoulder_past_half_turn, mut wrist_past_half_turn) = (false, false);
    for _ in 0..200 {
        let theta = model
            .solve_camera_position(&space.sample(&mut rng))
            .unwrap();
        let q = model.check_limits(&theta).unwrap();
        shoulder_past_half_turn |= q[1] > std::f64::consts::PI;
        wrist_past_half_turn |= q[4] > std::f64::consts::PI;
    }
    assert!(shoulder_past_half_turn && wrist_past_half_turn);
}
