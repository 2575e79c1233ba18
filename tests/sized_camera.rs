//! The camera's scale on a public table-top arm, the SO-100 of PyPI's `example-robot-data`
//! (its `share/example-robot-data` folder named by `EYEHAND_ROBOT_DATA`): the standoff
//! left at its default is sized to the fitted reach space, the object lies that far below
//! the camera at the target, cz's boundaries keep the target's reading a third of the way
//! up their range, the minimal joint move keeps its default, `ik` reaches the targets with
//! it, lin5 learns with it, and `info` and `eyehand reach` say it was fitted to the arm.

use eyehand::camera::CameraModel;
use eyehand::experiment::setup::{sized_standoff_cm, MIN_SIZED_STANDOFF_CM};
use eyehand::experiment::{run, Config, RunOptions, RunSetup, Source, Sources};
use eyehand::learn::Method;
use eyehand::units::M_PER_CM;
use std::path::PathBuf;
use std::process::Command;

#[path = "common/robot_data.rs"]
mod robot_data;
use robot_data::robot_data;

/// The collection's SO-100, a table-top arm whose reach space is about 14 cm high.
fn so100() -> PathBuf {
    robot_data().join("robots/so_arm_description/urdf/so100.urdf")
}

/// The SO-100's run, put together from nothing but its URDF and `config`.
fn setup(config: Config) -> RunSetup {
    RunSetup::new(config, Some(&so100()), Vec::new(), &Sources::default())
        .unwrap_or_else(|e| panic!("{e}"))
}

#[test]
fn the_so100s_object_lies_the_sized_standoff_below_its_targets() {
    let setup = setup(Config::default_config());
    assert_eq!(setup.config.standoff, sized_standoff_cm(&setup.reach));
    assert!(
        (MIN_SIZED_STANDOFF_CM..20.0).contains(&setup.config.standoff),
        "{} cm over {:?}",
        setup.config.standoff,
        setup.reach
    );
    let standoff = setup.config.standoff * M_PER_CM;
    assert_eq!(
        setup.config.source_of("standoff", &setup.sources),
        Source::Fitted
    );
    // The minimal joint move is an angle whose best value does not follow the arm's size:
    // it keeps the study's.
    assert_eq!(
        setup.config.source_of("minimal_joint_move", &setup.sources),
        Source::Default
    );
    let (low, high) = setup.config.boundary(4);
    assert!(
        (-low / (high - low) - 1.0 / 3.0).abs() < 1e-12,
        "cz's boundaries {low}..{high}"
    );
    let radius = CameraModel::default().object_radius;
    let mut trials = setup.trial_loop();
    let mut begun = 0;
    for _ in 0..200 {
        if trials.begin_trial().is_err() {
            continue;
        }
        begun += 1;
        let (goal, object) = (trials.goal().unwrap(), trials.object().unwrap());
        assert!((goal - object - nalgebra::Vector3::z() * standoff).norm() < 1e-12);
        assert!(goal.z >= setup.reach.z_min - 1e-9 && goal.z <= setup.reach.z_max + 1e-9);
        assert!(object.z - radius >= setup.config.floor_z * M_PER_CM);
    }
    assert!(begun >= 190, "{begun} of 200 trials begun");
}

#[test]
fn ik_reaches_and_lin5_learns_the_so100_with_its_sized_standoff() {
    let data = tempfile::tempdir().unwrap();
    for (method, trials, most_mm) in [(Method::Ik, 200, 1e-3), (Method::Lin5, 3000, 0.1)] {
        let config = Config {
            trials,
            ..Config::defaults_for(method).unwrap()
        };
        let options = RunOptions {
            urdf: Some(so100()),
            ..RunOptions::new(config, data.path())
        };
        let result = run(&options).unwrap_or_else(|e| panic!("{method}: {e}"));
        let mean = result.summary.mean_distance_mm;
        assert!(
            mean[3].is_some_and(|mm| mm <= most_mm),
            "{method}: 4-step mean {mean:?} mm"
        );
        assert!(
            result.summary.failures <= trials / 20,
            "{method}: {} of {trials} failed",
            result.summary.failures
        );
        let info = std::fs::read_to_string(result.folder.join("info")).unwrap();
        let line = info.lines().find(|l| l.starts_with("standoff "));
        assert!(
            line.is_some_and(|l| l.ends_with("# fitted to the arm")),
            "{method}: {line:?}"
        );
    }
}

#[test]
fn reach_prints_the_sized_standoff_and_a_given_one_is_kept() {
    let urdf = so100().display().to_string();
    let reach = |sets: &[&str]| {
        let out = Command::new(env!("CARGO_BIN_EXE_eyehand"))
            .args(["reach", "--urdf", &urdf])
            .args(sets.iter().flat_map(|s| ["--set", s]))
            .output()
            .unwrap();
        assert_eq!(out.status.code(), Some(0), "{out:?}");
        let text = String::from_utf8(out.stdout).unwrap();
        let line = text.lines().find(|l| l.starts_with("standoff "));
        line.unwrap_or_else(|| panic!("no standoff line in {text}"))
            .to_string()
    };
    let sized = setup(Config::default_config()).config.standoff;
    let line = reach(&[]);
    assert!(line.contains(&format!("{sized:.1} cm")), "{line}");
    assert!(line.contains("sized to the fitted space"), "{line}");
    let line = reach(&["standoff=16"]);
    assert!(
        line.contains("16.0 cm") && line.contains("given: --set"),
        "{line}"
    );
    let given = setup(Config {
        standoff: 16.0,
        ..Config::default_config()
    });
    assert_eq!(given.config.standoff, 16.0);
}
