//! Any serial arm from its real URDF: the Franka Panda and a UR-style arm as `ArmModel`s
//! keep the camera looking down (the image's roll a function of the pose), learn with lin5 on the
//! kinematic simulator, and the camera link rides with the camera. Wrong arm entries are
//! clear errors.

use eyehand::experiment::setup::{fit_reach, fitted_boundaries, load_arm};
use eyehand::experiment::{run, Config, RunOptions};
use eyehand::robot::description::{DescriptionOptions, RobotDescription};
use eyehand::robot::{
    ArmModel, ArmSettings, Controlled, KinematicSim, MoveSettings, ReachSpace, Simulator, Wrist,
};
use nalgebra::{Isometry3, Vector3};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use std::path::Path;
use std::process::Command;

#[path = "common/test_arms.rs"]
mod test_arms;

use test_arms::{PANDA, UR_STYLE};

/// How far (degrees) the camera's optical axis is from straight down, and its image x
/// axis from that of `placed` (the same learned angles placed from rest).
fn tilt_and_twist_deg(camera: &Isometry3<f64>, placed: &Isometry3<f64>) -> (f64, f64) {
    let optical = camera.rotation * Vector3::z();
    let image_x = camera.rotation * Vector3::x();
    // atan2 of the cross and dot products: exact for tiny angles, unlike acos.
    let angle = |a: Vector3<f64>, b: Vector3<f64>| a.cross(&b).norm().atan2(a.dot(&b));
    (
        angle(optical, -Vector3::z()).to_degrees(),
        angle(image_x, placed.rotation * Vector3::x()).to_degrees(),
    )
}

#[test]
fn the_camera_stays_vertical_through_moves_its_roll_set_by_the_pose() {
    for arm in [PANDA, UR_STYLE] {
        let mut model = arm.model();
        assert_ne!(model.wrist(), &Wrist::None, "{}", arm.file);
        let fit = ReachSpace::fit(&model, -0.22, 0.22).expect("a reach space");
        let reach = fit.space;
        model.keep_branch(fit.branch);
        let mut sim = KinematicSim::new(model.clone(), MoveSettings::from_degrees(30.0, 60.0));
        let mut rng = ChaCha8Rng::seed_from_u64(3);
        let mut checked = 0;
        for _ in 0..100 {
            let Ok(theta) = model.solve_camera_position(&reach.sample(&mut rng)) else {
                continue;
            };
            sim.place(&theta).unwrap();
            for _ in 0..5 {
                let delta = Controlled::from_fn(|_, _| rng.random_range(-0.05..0.05));
                sim.execute(&delta);
                let placed = model.pose_of(&model.controlled_of(&sim.joints())).camera;
                let (tilt, twist) = tilt_and_twist_deg(&sim.camera_pose(), &placed);
                assert!(
                    tilt < 1e-6 && twist < 1e-6,
                    "{}: {tilt}° {twist}°",
                    arm.file
                );
                assert!(model.violated_limit(&sim.joints()).is_none());
                checked += 1;
            }
        }
        assert!(checked > 400, "{}: {checked} poses", arm.file);
    }
}

#[test]
fn the_inverse_kinematics_puts_the_camera_where_asked() {
    for arm in [PANDA, UR_STYLE] {
        let mut model = arm.model();
        let fit = ReachSpace::fit(&model, -0.22, 0.22).unwrap();
        let reach = fit.space;
        model.keep_branch(fit.branch);
        let mut rng = ChaCha8Rng::seed_from_u64(4);
        let mut solved = 0;
        for _ in 0..200 {
            let target = reach.sample(&mut rng);
            if let Ok(theta) = model.solve_camera_position(&target) {
                let camera = model.pose_of(&theta).camera.translation.vector;
                assert!((camera - target.coords).norm() < 1e-9, "{}", arm.file);
                assert!(model.is_on_branch(&theta));
                solved += 1;
            }
        }
        assert!(solved >= 190, "{}: {solved} of 200", arm.file);
    }
}

#[test]
fn the_camera_link_and_what_is_fixed_below_it_ride_with_the_camera() {
    // The OSCAR-6: its 0.3 kg camera link with its box is the body after link 6 (0.5 kg).
    let oscar = ArmModel::oscar6();
    assert_eq!(oscar.wrist(), &Wrist::OneJoint(4));
    assert!(oscar.is_oscar6_form());
    let links = oscar.links();
    assert_eq!((links[6].mass, links[7].mass), (0.5, 0.3));
    assert_eq!(links[7].name, "camera_link");
    assert_eq!(links[7].collisions.len(), 1);
    // The Panda with the camera on its hand: the hand (0.81 kg) and the fingers held on it
    // (0.1 kg each) ride with the camera, links 7 and 8 stay the last body; a camera offset
    // leaves the hand where it is.
    let at = |offset_cm: [f64; 3]| {
        let description =
            RobotDescription::load(&PANDA.urdf(), &DescriptionOptions::default()).unwrap();
        let settings = ArmSettings {
            camera_link: PANDA.camera_link.into(),
            camera_offset: Vector3::from(offset_cm) / 100.0,
            learned_joints: PANDA.learned.into(),
            ..ArmSettings::default()
        };
        ArmModel::from_description(&description, &settings).unwrap()
    };
    let (plain, offset) = (at([0.0; 3]), at([3.0, -2.0, 10.0]));
    let links = plain.links();
    assert_eq!(links.len(), 9);
    assert!((links[7].mass - 0.2).abs() < 1e-12, "{}", links[7].mass);
    assert!((links[8].mass - 1.01).abs() < 1e-12, "{}", links[8].mass);
    assert_eq!(links[8].name, "panda_hand");
    let hand = |model: &ArmModel| -> Vec<Isometry3<f64>> {
        let camera = &model.links()[8];
        let mut poses = vec![model.camera_mount() * camera.inertial_origin];
        poses.extend(
            camera
                .collisions
                .iter()
                .map(|(pose, _)| model.camera_mount() * pose),
        );
        poses
    };
    let (a, b) = (hand(&plain), hand(&offset));
    assert_eq!(a.len(), 4, "the hand's and the fingers' collision meshes");
    for (a, b) in a.iter().zip(&b) {
        assert!((a.to_homogeneous() - b.to_homogeneous()).amax() < 1e-12);
    }
}

/// A real arm nobody tuned, from its URDF alone: the camera link, the learned joints, the
/// reach space and the learner's boundaries are all worked out from the arm, and lin5
/// learns it to within 0.05 mm in 20,000 trials with few moves stopped by a contact.
#[test]
fn lin5_learns_the_panda_and_the_ur_style_arm_from_their_urdfs_alone() {
    let data = tempfile::tempdir().unwrap();
    for arm in [PANDA, UR_STYLE] {
        let config = Config {
            trials: 20_000,
            ..Config::default_config()
        };
        let options = RunOptions {
            urdf: Some(arm.urdf()),
            ..RunOptions::new(config, data.path())
        };
        let result = run(&options).unwrap();
        let summary = &result.summary;
        let mean = summary.mean_distance_mm;
        assert!(
            mean[3].is_some_and(|m| m <= 0.05),
            "{}: 4-step mean {mean:?} mm",
            arm.file
        );
        assert!(
            summary.stopped_by_contact as f64 <= 0.01 * summary.trials as f64,
            "{}: {} moves stopped by a contact",
            arm.file,
            summary.stopped_by_contact
        );
        assert!(
            summary.failures < 200,
            "{}: {} failed",
            arm.file,
            summary.failures
        );
        let info = std::fs::read_to_string(result.folder.join("info")).unwrap();
        let [low2, high2, low3, high3] = arm.boundaries;
        for (name, value) in [
            ("boundary_0_low", low2),
            ("boundary_0_high", high2),
            ("boundary_1_low", low3),
            ("boundary_1_high", high3),
        ] {
            let line = format!("{name} {value:?}");
            let found = info.lines().find(|l| l.starts_with(&format!("{name} ")));
            assert!(
                found.is_some_and(|l| l.starts_with(&line) && l.ends_with("# fitted to the arm")),
                "{}: {line} fitted, in {found:?}",
                arm.file
            );
        }
    }
}

fn eyehand(args: &[&str]) -> (i32, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_eyehand"))
        .args(args)
        .output()
        .unwrap();
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

#[test]
fn reach_prints_the_space_the_coverage_and_the_prelearning_pose() {
    let urdf = PANDA.urdf();
    let sets: Vec<String> = PANDA
        .sets()
        .iter()
        .map(|(n, v)| format!("{n}={v}"))
        .collect();
    let mut args = vec!["reach", "--urdf", urdf.to_str().unwrap()];
    for set in &sets {
        args.extend(["--set", set]);
    }
    let (code, out, err) = eyehand(&args);
    assert_eq!(code, 0, "{err}");
    for expected in [
        "7 joints",
        "reach space (fitted)",
        "covered",
        "pre-learning pose",
        "panda_joint7=",
    ] {
        assert!(out.contains(expected), "{expected} in\n{out}");
    }
    let (code, out, _) = eyehand(&["reach"]);
    assert_eq!(code, 0);
    assert!(out.contains("r 46.0..93.0 cm, z 0.0..52.0 cm"), "{out}");
    assert!(out.contains("(69.5, 0.0, 26.0) cm"), "{out}");
    assert!(
        out.contains("\ncontact              0 of 500 moves"),
        "{out}"
    );
    let (code, out, _) = eyehand(&["reach", "--set", "obstacle=60,20,30,10,10,80"]);
    assert_eq!(code, 0);
    let contact = out.lines().find(|l| l.starts_with("contact ")).unwrap();
    assert!(
        !contact.starts_with("contact              0 of"),
        "a pillar stops moves: {contact}"
    );
}

#[test]
fn wrong_arm_entries_are_clear_errors() {
    let urdf = PANDA.urdf();
    let urdf = urdf.to_str().unwrap();
    let learned = "learned_joints=panda_joint1,panda_joint2,panda_joint4";
    let cases: [(&[&str], &str); 5] = [
        (
            &["--set", "camera_link=nowhere", "--set", learned],
            "camera link `nowhere` is not a link of the robot",
        ),
        (
            &[
                "--set",
                "camera_link=panda_hand",
                "--set",
                "learned_joints=panda_joint1,panda_joint8,panda_joint4",
            ],
            "learned joint `panda_joint8` is a fixed joint",
        ),
        (
            &[
                "--set",
                "camera_link=panda_link4",
                "--set",
                "learned_joints=panda_joint1,panda_joint2,panda_joint6",
            ],
            "learned joint `panda_joint6` is not on the chain",
        ),
        // The Panda's right finger mimics its left one: a <mimic> is refused by name, on
        // the chain or off it.
        (
            &["--set", "camera_link=panda_leftfinger", "--set", learned],
            "joint `panda_finger_joint2` off the chain follows `panda_finger_joint1` on it (<mimic>)",
        ),
        (
            &["--set", "camera_link=panda_rightfinger", "--set", learned],
            "joint `panda_finger_joint2` on the chain to the camera link follows `panda_finger_joint1` (<mimic>)",
        ),
    ];
    let data = tempfile::tempdir().unwrap();
    let data = data.path().to_str().unwrap();
    for (sets, message) in cases {
        let mut args = vec!["run", "--urdf", urdf, "--trials", "5", "--data", data];
        args.extend(sets);
        let (code, _, err) = eyehand(&args);
        assert_eq!(code, 2, "{args:?}: {err}");
        assert!(err.contains(message), "{message} in {err}");
    }
    // From a config file, the error names the entry's line.
    let shipped = eyehand::experiment::defaults_text();
    let text: String = shipped
        .lines()
        .map(|line| match line.split_whitespace().next() {
            Some("camera_link") => "camera_link panda_hand".to_string(),
            Some("learned_joints") => {
                "learned_joints panda_joint1,panda_joint8,panda_joint4".to_string()
            }
            _ => line.to_string(),
        })
        .collect::<Vec<_>>()
        .join("\n");
    let line = 1 + shipped
        .lines()
        .position(|l| l.starts_with("learned_joints"))
        .unwrap();
    let file = Path::new(data).join("panda.conf");
    std::fs::write(&file, text).unwrap();
    let file = file.to_str().unwrap();
    let (code, _, err) = eyehand(&["run", "--config", file, "--urdf", urdf, "--data", data]);
    assert_eq!(code, 2, "{err}");
    let at = format!("{file}:{line}: learned_joints: ");
    assert!(err.contains(&at), "{at} in {err}");
    let (code, _, err) = eyehand(&["run", "--set", "reach_space=90,46,0,52", "--trials", "5"]);
    assert_eq!(code, 2);
    assert!(err.contains("reach_space"), "{err}");
}

#[test]
fn an_arm_whose_meshes_are_all_missing_gets_one_warning_line() {
    let dir = tempfile::tempdir().unwrap();
    let urdf = dir.path().join("panda.urdf");
    std::fs::copy(PANDA.urdf(), &urdf).unwrap();
    let mut args = vec![
        "reach".to_string(),
        "--urdf".into(),
        urdf.display().to_string(),
    ];
    for (name, value) in PANDA.sets() {
        args.extend(["--set".to_string(), format!("{name}={value}")]);
    }
    let args: Vec<&str> = args.iter().map(String::as_str).collect();
    let (code, _, err) = eyehand(&args);
    assert_eq!(code, 0, "{err}");
    let warnings: Vec<&str> = err
        .lines()
        .filter(|l| l.starts_with("eyehand: warning: "))
        .collect();
    let [warning] = warnings.as_slice() else {
        panic!("one warning line, not {}:\n{err}", warnings.len());
    };
    assert!(warning.contains("meshes missing or unread ("), "{warning}");
    assert!(warning.contains("replaced by capsules"), "{warning}");
    assert!(warning.contains("; the first: link `"), "{warning}");
}

#[test]
fn auto_picks_the_camera_link_and_the_learned_joints_of_every_test_arm() {
    let expected = [
        (None, "camera_link", ["joint_1", "joint_2", "joint_3"]),
        (Some(PANDA.urdf()), "panda_hand", PANDA.learned),
        (Some(UR_STYLE.urdf()), "tool0", UR_STYLE.learned),
    ];
    for (urdf, camera_link, learned) in expected {
        let config = Config::default_config();
        let model = load_arm(&config, urdf.as_deref()).unwrap().model;
        let names: Vec<&str> = model
            .learned()
            .iter()
            .map(|&j| model.joints()[j].name.as_str())
            .collect();
        assert_eq!(names, learned, "{urdf:?}");
        let camera = &model.links().last().unwrap().name;
        assert_eq!(camera, camera_link, "{urdf:?}");
    }
}

/// The UR-style arm with its shoulder limited to ±360° and its elbow `continuous`: the
/// description a real UR gives.
fn full_turn_ur_style(folder: &Path) -> std::path::PathBuf {
    let urdf = std::fs::read_to_string(UR_STYLE.urdf()).unwrap();
    let edits = [
        (
            r#"lower="-3.1416" upper="0.5""#,
            r#"lower="-6.2832" upper="6.2832""#,
        ),
        (
            r#"<joint name="elbow_joint" type="revolute">"#,
            r#"<joint name="elbow_joint" type="continuous">"#,
        ),
        (
            r#"<limit lower="-2.8" upper="3.0" effort="150""#,
            r#"<limit effort="150""#,
        ),
    ];
    let edited = edits.iter().fold(urdf, |text, (from, to)| {
        assert!(text.contains(from), "{from} in the UR-style fixture");
        text.replace(from, to)
    });
    let path = folder.join("ur_full_turn.urdf");
    std::fs::write(&path, edited).unwrap();
    path
}

/// Joints limited to a turn either way or not at all still fit a reach space, with the
/// learned joints' boundaries inside one turn, and lin5 learns there.
#[test]
fn an_arm_with_full_turn_and_continuous_joints_fits_a_reach_space_and_learns() {
    let folder = tempfile::tempdir().unwrap();
    let urdf = full_turn_ur_style(folder.path());
    let config = Config {
        trials: 3_000,
        ..Config::default_config()
    };
    let mut model = load_arm(&config, Some(&urdf)).unwrap().model;
    let fit = fit_reach(&config, &mut model).unwrap();
    assert!(fit.space.volume() > 0.1, "{fit:?}");
    let boundaries = fitted_boundaries(&model, &fit.space).unwrap();
    // One branch, within one turn: each range narrower than half a turn.
    for (low, high) in boundaries {
        assert!(high - low < 180.0, "{boundaries:?}");
    }
    let options = RunOptions {
        urdf: Some(urdf),
        ..RunOptions::new(config, folder.path())
    };
    let summary = run(&options).unwrap().summary;
    let mean = summary.mean_distance_mm;
    assert!(mean[3].is_some_and(|m| m <= 0.5), "4-step mean {mean:?} mm");
    assert!(
        summary.stopped_by_contact as f64 <= 0.01 * summary.moves as f64,
        "{} of {} moves stopped by a contact",
        summary.stopped_by_contact,
        summary.moves
    );
}

/// `configs/arms/ur_style.conf` names the arm by its `urdf` entry (relative to the file's
/// folder): the run it gives is the run of `--urdf`, distance for distance, and `info`
/// records the URDF either way.
#[test]
fn an_arm_config_file_runs_the_arm_its_urdf_entry_names() {
    let data = tempfile::tempdir().unwrap();
    let root = env!("CARGO_MANIFEST_DIR");
    let conf = format!("{root}/configs/arms/ur_style.conf");
    let urdf = UR_STYLE.urdf();
    let runs = [
        ("from-config", vec!["--config", conf.as_str()]),
        ("from-flag", vec!["--urdf", urdf.to_str().unwrap()]),
    ];
    let mut steps = Vec::new();
    for (folder, arm) in runs {
        let out = data.path().join(folder);
        let mut args = vec!["run", "--trials", "200", "--quiet", "--no-plot", "--data"];
        args.push(out.to_str().unwrap());
        args.extend(arm);
        let (code, _, err) = eyehand(&args);
        assert_eq!(code, 0, "{err}");
        let run = out.join("lin5/0");
        let info = std::fs::read_to_string(run.join("info")).unwrap();
        let recorded = info.lines().find(|l| l.starts_with("urdf ")).unwrap();
        assert!(recorded.contains("ur_style.urdf"), "{recorded}");
        // Trial and distance; the last column is the time the run took.
        let text = std::fs::read_to_string(run.join("1step")).unwrap();
        let lines = text
            .lines()
            .map(|l| l.rsplit_once(' ').unwrap().0.to_string());
        steps.push(lines.collect::<Vec<_>>());
    }
    assert!(steps[0].len() > 150, "{} trials", steps[0].len());
    assert!(steps[0] == steps[1], "the two runs differ");
}

/// The `eyehand …` commands of docs/ARMS.md's first `sh` block, each on one line.
fn documented_commands() -> Vec<String> {
    let doc = std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("docs/ARMS.md"))
        .unwrap();
    let block = doc
        .split("```sh\n")
        .nth(1)
        .and_then(|rest| rest.split("```").next())
        .expect("docs/ARMS.md has an sh block");
    block
        .replace("\\\n", " ")
        .lines()
        .map(str::to_string)
        .collect()
}

#[test]
fn every_command_docs_arms_gives_runs() {
    let commands = documented_commands();
    assert!(commands.len() >= 4, "{commands:?}");
    let data = tempfile::tempdir().unwrap();
    for command in &commands {
        let mut args: Vec<&str> = command.split_whitespace().collect();
        assert_eq!(args.remove(0), "eyehand", "{command}");
        if args[0] == "run" {
            let data = data.path().to_str().unwrap();
            args.extend(["--trials", "300", "--data", data, "--quiet", "--no-plot"]);
        }
        // Its paths are the project's: integration tests run in the package's folder.
        let (code, _, err) = eyehand(&args);
        assert_eq!(code, 0, "{command}: {err}");
    }
}

/// A URDF named without a folder (run from its own folder) reads its meshes: its folder is
/// the working folder, and every mesh lies inside it (the test copy has collision meshes
/// only).
#[test]
fn a_urdf_named_from_its_own_folder_reads_its_meshes() {
    let folder = PANDA.urdf().parent().unwrap().to_path_buf();
    let mut args = vec!["reach".to_string(), "--urdf".into(), "panda.urdf".into()];
    for (name, value) in PANDA.sets() {
        args.extend(["--set".to_string(), format!("{name}={value}")]);
    }
    let out = Command::new(env!("CARGO_BIN_EXE_eyehand"))
        .args(&args)
        .current_dir(&folder)
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(0), "{err}");
    assert!(
        !err.contains("warning") || err.contains("(0 collision meshes, "),
        "every collision mesh read: {err}"
    );
}
