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
    assert!(stderr.contains("--from takes 7 joint angles"), "{stderr}");
    assert!(stderr.contains("not 6"), "{stderr}");
}

/// The energy of an undamped OSCAR-6 swing (servos off, no limits, no contacts) from
/// `--energy`'s CSV columns: each tick's kinetic and potential energy, and the total's
/// drift at the end as a share of the largest kinetic energy.
fn swing_energy(dt: &str, duration: &str) -> (Vec<(f64, f64)>, f64) {
    let args = [
        "--from",
        "0,30,20,0,40,0",
        "--duration",
        duration,
        "--dt",
        dt,
    ];
    let mut args = args.to_vec();
    args.extend(["--no-limits", "--no-contacts", "--energy", "--csv"]);
    let out = simulate(&args);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let stdout = String::from_utf8_lossy(&out.stdout);
    let mut lines = stdout.lines();
    let header = lines.next().unwrap();
    assert!(
        header.ends_with(",kinetic_J,potential_J,total_J"),
        "{header}"
    );
    let rows: Vec<Vec<f64>> = lines
        .map(|l| l.split(',').map(|v| v.parse().unwrap()).collect())
        .collect();
    let energies: Vec<(f64, f64)> = rows
        .iter()
        .map(|r| (r[r.len() - 3], r[r.len() - 2]))
        .collect();
    let total = |r: &Vec<f64>| r[r.len() - 1];
    for r in &rows {
        assert!((r[r.len() - 3] + r[r.len() - 2] - total(r)).abs() < 1e-6);
    }
    let peak = energies.iter().map(|e| e.0).fold(0.0, f64::max);
    let drift = (total(rows.last().unwrap()) - total(&rows[0])) / peak;
    let said = String::from_utf8_lossy(&out.stderr);
    assert!(said.contains("energy: the total drifted"), "{said}");
    (energies, drift)
}

/// The swing starts at rest and turns its weight into motion (the kinetic energy rises
/// to about the potential energy it lost); the fourth-order steps keep the total: within
/// 1e-5 of the largest kinetic energy in 1 s at 1 ms and at the runs' 5 ms (6e-11 and 1.4e-7
/// measured; Rapier's first-order steps bled 0.9% and 4.5%).
#[test]
fn energy_shows_the_swing_and_what_the_integration_keeps() {
    let (energies, fine) = swing_energy("0.001", "1");
    assert_eq!(energies[0].0, 0.0);
    let (peak, potential) =
        energies
            .iter()
            .cloned()
            .fold((0.0, 0.0), |a, e| if e.0 > a.0 { e } else { a });
    assert!(peak > 100.0, "the arm falls: {peak} J");
    let lost = energies[0].1 - potential;
    assert!(
        (peak - lost).abs() < 0.02 * peak,
        "{peak} J of motion, {lost} J lost"
    );
    assert!(fine.abs() < 1e-5, "{fine}");
    let (_, coarse) = swing_energy("0.005", "1");
    assert!(coarse.abs() < 1e-5, "{coarse}");
}

/// `--torques`: what each joint took in the tick. Held, the shoulder carries the arm's
/// weight (over 100 N·m at 30°, 80°); swinging free, the joints take next to nothing.
#[test]
fn torques_show_what_the_servos_hold_and_a_free_swing_takes_none() {
    let last_torques = |drive: &str| {
        let args = [
            "--from",
            "0,30,80,0,40,0",
            "--duration",
            "0.2",
            "--dt",
            "0.001",
        ];
        let mut args = args.to_vec();
        args.extend([drive, "--no-contacts", "--torques", "--csv"]);
        let out = simulate(&args);
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        let stdout = String::from_utf8_lossy(&out.stdout).into_owned();
        let header = stdout.lines().next().unwrap().to_string();
        assert!(
            header.ends_with(",tau1_Nm,tau2_Nm,tau3_Nm,tau4_Nm,tau5_Nm,tau6_Nm"),
            "{header}"
        );
        let last = stdout.lines().last().unwrap();
        let values: Vec<f64> = last.split(',').map(|v| v.parse().unwrap()).collect();
        values[values.len() - 6..].to_vec()
    };
    let held = last_torques("--hold");
    assert!(held[1] > 100.0, "{held:?}");
    let free = last_torques("--passive");
    assert!(free.iter().all(|t| t.abs() < 1.0), "{free:?}");
}
