//! The camera as users mount it, on the public arms of PyPI's `example-robot-data` (its
//! `share/example-robot-data` folder named by `EYEHAND_ROBOT_DATA`, as in tests/corpus.rs):
//! looking down means the optical axis straight down whatever the image's roll (the SO-100,
//! whose wrist cannot also turn the image x axis away from the base, looks down), a camera
//! no wrist pose turns down is refused before any sampling, the `camera_mount` entry turns
//! the camera on its link, and `base_link` cuts one arm out of a whole humanoid.

use eyehand::experiment::setup::arm_settings;
use eyehand::experiment::Config;
use eyehand::robot::description::{DescriptionOptions, RobotDescription};
use eyehand::robot::{ArmModel, ArmSettings, Controlled};
use nalgebra::Vector3;
use std::path::PathBuf;

/// The variable naming the collection's `share/example-robot-data` folder.
const ROBOT_DATA: &str = "EYEHAND_ROBOT_DATA";

fn robot(urdf: &str) -> RobotDescription {
    let folder = std::env::var_os(ROBOT_DATA).unwrap_or_else(|| {
        panic!(
            "{ROBOT_DATA} is not set: install the collection (`pip install --no-deps \
             example-robot-data==6.0.0`, as scripts/test-all.sh does) and set it to its \
             share/example-robot-data folder"
        )
    });
    let path = PathBuf::from(folder).join("robots").join(urdf);
    RobotDescription::load(&path, &DescriptionOptions::default())
        .unwrap_or_else(|e| panic!("{urdf}: {e}"))
}

/// The arm settings of a config giving only `camera_mount MOUNT`.
fn mounted(mount: &str) -> ArmSettings {
    let config = Config::parse(&format!("camera_mount {mount}\n"), "test.conf").unwrap();
    arm_settings(&config)
}

/// The shoulder–elbow poses of a 5 × 5 grid 10° inside the limits (base yaw at 0) at which
/// the wrist looks down inside its limits, and the image x axis' angle from the radial
/// direction at each (rad).
fn looking_down(model: &ArmModel) -> Vec<f64> {
    let [_, s, e] = model.learned().map(|j| &model.joints()[j]);
    let inside = |lower: f64, upper: f64, n: usize| {
        let margin = 10f64.to_radians();
        lower + margin + (upper - lower - 2.0 * margin) * n as f64 / 4.0
    };
    let mut rolls = Vec::new();
    for i in 0..5 {
        for k in 0..5 {
            let theta = Controlled::new(
                0.0,
                inside(s.lower, s.upper, i),
                inside(e.lower, e.upper, k),
            );
            let pose = model.pose_of(&theta);
            if !model.wrist_fits(&pose) {
                continue;
            }
            let optical = pose.camera.rotation * Vector3::z();
            assert!((optical + Vector3::z()).norm() < 1e-9, "{optical:?}");
            let p = pose.camera.translation.vector;
            let x = pose.camera.rotation * Vector3::x();
            rolls.push(x.y.atan2(x.x) - p.y.atan2(p.x));
        }
    }
    rolls
}

#[test]
fn the_so100_looks_down_with_the_roll_its_wrist_gives() {
    // Its two wrist joints (flex and roll) cannot point the image x axis away from the
    // base too: with that rule it looked down nowhere.
    let model = ArmModel::from_description(
        &robot("so_arm_description/urdf/so100.urdf"),
        &ArmSettings::default(),
    )
    .unwrap();
    let rolls = looking_down(&model);
    assert!(
        rolls.len() >= 10,
        "looks down at {} of 25 poses",
        rolls.len()
    );
    let radial = |r: &f64| r.sin().abs() < 1e-6 && r.cos() > 0.0;
    assert!(!rolls.iter().all(radial), "{rolls:?}");
}

#[test]
fn camera_mount_turns_the_camera_on_its_link_and_its_default_changes_nothing() {
    let config = |text: &str| Config::parse(text, "test.conf").unwrap();
    let so100 = robot("so_arm_description/urdf/so100.urdf");
    let plain = ArmModel::from_description(&so100, &arm_settings(&config(""))).unwrap();
    let zeros = config("camera_mount 0,0,0,0,0,0");
    let same = ArmModel::from_description(&so100, &arm_settings(&zeros)).unwrap();
    assert_eq!(plain, same);
    // The Kinova's link 6 has its z axis pointing back into the wrist: turned half round
    // about x the camera looks along the hand, and an offset moves it along the link's -z.
    let kinova = robot("kinova_description/robots/kinova.urdf");
    let mounted = |text: &str| {
        ArmModel::from_description(&kinova, &arm_settings(&config(text)))
            .unwrap()
            .camera_mount()
    };
    let (at, out) = (
        mounted("camera_mount 0,0,0,180,0,0"),
        mounted("camera_mount 0,0,-0.05,180,0,0"),
    );
    let link = at * nalgebra::UnitQuaternion::from_euler_angles(std::f64::consts::PI, 0.0, 0.0);
    assert!((at.rotation * Vector3::z() + link.rotation * Vector3::z()).norm() < 1e-12);
    let moved = out.translation.vector - at.translation.vector;
    assert!((moved - link.rotation * Vector3::new(0.0, 0.0, -0.05)).norm() < 1e-12);
}

#[test]
fn camera_mount_and_camera_offset_may_not_both_move_the_camera() {
    let both = Config::parse(
        "camera_offset 0,0,5\ncamera_mount 0,0,0.05,0,0,0\n",
        "test.conf",
    );
    let error = both.unwrap_err().to_string();
    assert!(
        error.contains("camera_mount") && error.contains("camera_offset"),
        "{error}"
    );
    let turn = Config::parse(
        "camera_offset 0,0,5\ncamera_mount 0,0,0,180,0,0\n",
        "test.conf",
    );
    assert!(turn.is_ok());
    let far = Config::parse("camera_mount 0,0,11,0,0,0\n", "test.conf").unwrap_err();
    assert!(far.to_string().contains("10 m"), "{far}");
}

#[test]
fn a_camera_no_wrist_pose_turns_down_is_refused_before_any_sampling() {
    // The SO-101's gripper link points its z axis back into the arm, and its roll axis
    // stands 2.8° off square to the wrist's flex axis: along that axis the camera never
    // looks exactly down. Tilted 2.8° on the link, it does.
    let description = robot("so_arm_description/urdf/so101.urdf");
    let error = ArmModel::from_description(&description, &mounted("0,0,0,180,0,0")).unwrap_err();
    let text = error.to_string();
    assert!(
        text.contains("the camera on `gripper_link` cannot look down")
            && text.contains("wrist_flex, wrist_roll")
            && text.contains("camera_mount"),
        "{text}"
    );
    let tilted = ArmModel::from_description(&description, &mounted("0,0,0,180,2.789,0"));
    assert!(tilted.is_ok(), "{:?}", tilted.err());
}

#[test]
fn base_link_and_camera_link_cut_one_arm_out_of_a_whole_humanoid() {
    let talos = robot("talos_data/robots/talos_reduced.urdf");
    let arm = robot("talos_data/robots/talos_left_arm.urdf");
    let config = |text: &str| Config::parse(text, "test.conf").unwrap();
    let names = |model: &ArmModel| -> Vec<String> {
        model.joints().iter().map(|j| j.name.clone()).collect()
    };
    let cut = ArmModel::from_description(
        &talos,
        &arm_settings(&config("base_link arm_left_1_link\n")),
    )
    .unwrap();
    let alone = ArmModel::from_description(&arm, &ArmSettings::default()).unwrap();
    assert_eq!(names(&cut), names(&alone));
    assert_eq!(cut.learned(), alone.learned());
    let error = |text: &str| {
        ArmModel::from_description(&talos, &arm_settings(&config(text)))
            .unwrap_err()
            .to_string()
    };
    let above = error("base_link arm_left_1_link\ncamera_link arm_right_7_link\n");
    assert!(
        above.contains(
            "camera link `arm_right_7_link` does not lie below base link `arm_left_1_link`"
        ),
        "{above}"
    );
    let unknown = error("base_link shoulder\n");
    assert!(
        unknown.contains("base link `shoulder` is not a link"),
        "{unknown}"
    );
}

#[test]
fn a_camera_looking_back_into_its_arm_is_refused_before_any_trial() {
    // The Kinova's link 6 has its z axis along joint 6 back into the wrist: looking down,
    // the camera saw link 5 10 cm below it at every start. Turned, it looks along the hand.
    let description = robot("kinova_description/robots/kinova.urdf");
    let error = ArmModel::from_description(&description, &mounted("0,0,0,0,0,0")).unwrap_err();
    assert!(
        error
            .to_string()
            .contains("the camera on `j2s6s200_link_6` looks back into the arm"),
        "{error}"
    );
    let turned = ArmModel::from_description(&description, &mounted("0,0,0,180,0,0"));
    assert!(turned.is_ok(), "{:?}", turned.err());
}
