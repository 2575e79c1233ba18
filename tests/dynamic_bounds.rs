//! Every wait for the physics is bounded: an arm too weak or too heavy to hold a pose is
//! refused at placing (with the numbers) instead of being left to settle for ever, and a
//! run on such an arm ends.

use eyehand::robot::{
    parse_urdf, ArmModel, Controlled, DynamicSettings, DynamicSim, RobotError, Simulator,
    DEFAULT_URDF,
};
use std::process::Command;
use std::time::{Duration, Instant};

fn weak_arm() -> String {
    DEFAULT_URDF.replacen(r#"effort="600""#, r#"effort="0.001""#, 1)
}

fn heavy_arm() -> String {
    DEFAULT_URDF.replacen(r#"<mass value="8.0"/>"#, r#"<mass value="1e5"/>"#, 1)
}

#[test]
fn an_arm_that_cannot_hold_a_pose_is_refused_there() {
    for (what, urdf) in [("weak", weak_arm()), ("heavy", heavy_arm())] {
        let model: ArmModel = parse_urdf(&urdf, what).expect("a valid URDF");
        let mut sim = DynamicSim::new(model, DynamicSettings::default());
        let started = Instant::now();
        match sim.place(&Controlled::new(0.0, 0.4, 1.2)) {
            Err(RobotError::CannotHold {
                joint,
                torque_nm,
                effort_nm,
            }) => assert!(
                torque_nm > effort_nm && (2..=3).contains(&joint),
                "{what}: joint {joint} {torque_nm} > {effort_nm}"
            ),
            other => panic!("{what}: {other:?}"),
        }
        assert!(started.elapsed() < Duration::from_millis(100), "{what}");
    }
}

#[test]
fn a_run_on_an_arm_too_weak_to_hold_itself_ends() {
    let dir = tempfile::tempdir().expect("a temporary folder");
    let urdf = dir.path().join("weak.urdf");
    std::fs::write(&urdf, weak_arm()).expect("writable");
    let started = Instant::now();
    let out = Command::new(env!("CARGO_BIN_EXE_eyehand"))
        .args([
            "run",
            "--sim",
            "dynamic",
            "--trials",
            "3",
            "--quiet",
            "--no-plot",
        ])
        .arg("--urdf")
        .arg(&urdf)
        .arg("--data")
        .arg(dir.path())
        .output()
        .expect("eyehand runs");
    assert!(
        started.elapsed() < Duration::from_secs(60),
        "took {:?}",
        started.elapsed()
    );
    let folder = String::from_utf8_lossy(&out.stdout).trim().to_string();
    let summary = std::fs::read_to_string(format!("{folder}/summary.json"))
        .unwrap_or_else(|e| panic!("{folder}: {e}; {}", String::from_utf8_lossy(&out.stderr)));
    let summary: serde_json::Value = serde_json::from_str(&summary).expect("JSON");
    // No start pose can be held: every trial fails, counted, and the run ends.
    assert_eq!(summary["failures"], 3, "{summary}");
    assert!(summary["settle_timeouts"].as_u64().is_some(), "{summary}");
}
