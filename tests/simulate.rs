//! `eyehand simulate` for any arm: as many start angles as the chain has (a leading minus
//! without `=`), the arm and the dynamic simulator's entries from `--config` / `--set`.

use std::process::{Command, Output};

const ROOT: &str = env!("CARGO_MANIFEST_DIR");

fn simulate(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_eyehand"))
        .arg("simulate")
        .args(args)
        .output()
        .unwrap()
}

fn panda() -> String {
    format!("{ROOT}/tests/data/panda/panda.urdf")
}

const PANDA_ARM: [&str; 4] = [
    "--set",
    "camera_link=panda_hand",
    "--set",
    "learned_joints=panda_joint1,panda_joint2,panda_joint4",
];

#[test]
fn the_panda_runs_from_a_seven_angle_pose_with_a_leading_minus() {
    let urdf = panda();
    let mut args = vec!["--urdf", &urdf, "--from", "-40,10,0,-120,0,130,45"];
    args.extend(["--duration", "0.02", "--hold", "--csv"]);
    args.extend(PANDA_ARM);
    let out = simulate(&args);
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let lines: Vec<&str> = stdout.lines().collect();
    assert!(
        lines[0]
            .ends_with(",q7_deg,v1_deg_s,v2_deg_s,v3_deg_s,v4_deg_s,v5_deg_s,v6_deg_s,v7_deg_s"),
        "{}",
        lines[0]
    );
    assert_eq!(
        lines.len(),
        1 + 1 + 4,
        "the header, the start and 4 ticks of 5 ms"
    );
    let first: Vec<f64> = lines[1].split(',').map(|v| v.parse().unwrap()).collect();
    assert_eq!(first.len(), 1 + 7 + 7);
    assert!(
        (first[1] + 40.0).abs() < 1e-9,
        "q1 starts at -40°: {}",
        lines[1]
    );
}

#[test]
fn the_config_sets_the_time_step_and_a_wrong_count_of_angles_is_refused() {
    let urdf = panda();
    let mut args = vec![
        "--urdf",
        &urdf,
        "--from",
        "0,0,0,-90,0,90,0",
        "--duration",
        "0.003",
    ];
    args.extend([
        "--json",
        "--set",
        "dt=0.001",
        "--set",
        "solver_iterations=2",
    ]);
    args.extend(PANDA_ARM);
    let out = simulate(&args);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let value: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(value["dt_s"], 0.001);
    assert_eq!(value["ticks"].as_array().unwrap().len(), 4);

    let mut args = vec![
        "--urdf",
        &urdf,
        "--from",
        "0,0,0,-90,0,90",
        "--duration",
        "0.01",
    ];
    args.extend(PANDA_ARM);
    let out = simulate(&args);
    assert_eq!(out.status.code(), Some(2));
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(
        stderr.contains("--from takes 7 finite joint angles"),
        "{stderr}"
    );
    assert!(stderr.contains("not 6"), "{stderr}");
}
