//! A run's folder: the files README.md lists, written the same way for the same seed.

use eyehand::experiment::{run, Config, Event, RunOptions, RunResult, ENTRY_NAMES};
use eyehand::learn::Method;
use std::path::Path;
use std::process::Command;

const DATA_FILES: [&str; 9] = [
    "1step", "2step", "3step", "4step", "5step", "nodes", "bins", "patterns", "abs_err",
];

fn run_in(data: &Path, method: Method, trials: usize, seed: u64, events: Vec<Event>) -> RunResult {
    let mut config = Config::default_config();
    config.method = method;
    config.trials = trials;
    config.seed = seed;
    let options = RunOptions {
        events,
        ..RunOptions::new(config, data)
    };
    run(&options).unwrap()
}

/// A data file without its minutes column.
fn without_minutes(path: &Path) -> String {
    let text = std::fs::read_to_string(path).unwrap();
    text.lines()
        .map(|l| {
            let fields: Vec<&str> = l.split(' ').collect();
            if fields.len() == 3 {
                fields[..2].join(" ")
            } else {
                l.to_string()
            }
        })
        .collect::<Vec<_>>()
        .join("\n")
}

#[test]
fn the_same_seed_gives_the_same_files() {
    let (a, b, c) = (
        tempfile::tempdir().unwrap(),
        tempfile::tempdir().unwrap(),
        tempfile::tempdir().unwrap(),
    );
    let events = vec!["rotate:20:30".parse().unwrap()];
    let first = run_in(a.path(), Method::Ik, 60, 9, events.clone());
    let second = run_in(b.path(), Method::Ik, 60, 9, events.clone());
    let other = run_in(c.path(), Method::Ik, 60, 10, events);
    for name in DATA_FILES {
        let one = without_minutes(&first.folder.join(name));
        assert!(!one.is_empty(), "{name} is written");
        assert_eq!(one, without_minutes(&second.folder.join(name)), "{name}");
    }
    let one = without_minutes(&first.folder.join("1step"));
    assert_ne!(
        one,
        without_minutes(&other.folder.join("1step")),
        "another seed, other trials"
    );
    assert_eq!(
        first.summary.mean_distance_mm,
        second.summary.mean_distance_mm
    );
}

#[test]
fn the_run_folder_has_every_file_and_summary_field() {
    let data = tempfile::tempdir().unwrap();
    let result = run_in(
        data.path(),
        Method::Ik,
        30,
        1,
        vec!["elongate:10:2:10".parse().unwrap()],
    );
    assert_eq!(result.folder, data.path().join("ik").join("0"));
    for name in DATA_FILES
        .iter()
        .chain(&["mem", "merges", "changes", "info", "summary.json"])
    {
        assert!(result.folder.join(name).is_file(), "{name}");
    }
    let step1 = std::fs::read_to_string(result.folder.join("1step")).unwrap();
    let trials: Vec<usize> = step1
        .lines()
        .map(|l| l.split(' ').next().unwrap().parse().unwrap())
        .collect();
    assert_eq!(trials, (1..=30).collect::<Vec<_>>());
    let mem = std::fs::read_to_string(result.folder.join("mem")).unwrap();
    assert_eq!(mem.lines().count(), 6, "every depth_info (5) trials");
    let json: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(result.folder.join("summary.json")).unwrap())
            .unwrap();
    for field in [
        "method",
        "sim",
        "camera",
        "seed",
        "trials",
        "wall_seconds",
        "trials_per_second",
        "peak_rss_kb",
        "nodes",
        "bins",
        "patterns",
        "failures",
        "events",
        "window",
        "mean_distance_mm",
        "median_distance_mm",
        "settle_timeouts",
        "stopped_by_contact",
        "speed_faults",
        "worst_speed_fault",
    ] {
        assert!(json.get(field).is_some(), "summary.json has {field}");
    }
    assert_eq!(json["mean_distance_mm"].as_array().unwrap().len(), 5);
    assert_eq!(json["window"], 3);
    assert_eq!(json["events"], serde_json::json!(["elongate:10:2:10"]));
    let info = std::fs::read_to_string(result.folder.join("info")).unwrap();
    for name in ENTRY_NAMES {
        assert!(
            info.lines().any(|l| l.split(' ').next() == Some(name)),
            "info lists {name}"
        );
    }
    assert!(info.contains("event elongate:10:2:10"));
    assert!(info.contains("trials_per_hour"));
    // The link was stretched at trial 10: the fixed model misses from then on.
    let misses: Vec<f64> = step1
        .lines()
        .map(|l| l.split(' ').nth(1).unwrap().parse().unwrap())
        .collect();
    assert!(misses[..9].iter().all(|&d| d < 1e-3) && misses[9..].iter().all(|&d| d > 1.0));
}

#[test]
fn the_command_line_runs_and_prints_the_folder() {
    let data = tempfile::tempdir().unwrap();
    let out = Command::new(env!("CARGO_BIN_EXE_eyehand"))
        .args([
            "run", "--method", "ik", "--trials", "20", "--seed", "2", "--quiet", "--data",
        ])
        .arg(data.path())
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert_eq!(
        String::from_utf8_lossy(&out.stdout).trim(),
        data.path().join("ik").join("0").display().to_string()
    );
    let out = Command::new(env!("CARGO_BIN_EXE_eyehand"))
        .args([
            "run", "--method", "ik", "--trials", "5", "--event", "spin:3", "--data",
        ])
        .arg(data.path())
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("bad event `spin:3`"));
}

#[test]
fn a_dynamic_run_prints_and_writes_what_its_arm_met() {
    let data = tempfile::tempdir().unwrap();
    let out = Command::new(env!("CARGO_BIN_EXE_eyehand"))
        .args([
            "run", "--method", "ik", "--sim", "dynamic", "--trials", "5", "--seed", "1", "--data",
        ])
        .arg(data.path())
        .output()
        .unwrap();
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(out.status.success(), "{stdout}");
    let line = stdout
        .lines()
        .find(|l| l.starts_with("dynamic arm: "))
        .unwrap_or_else(|| panic!("no line of the arm's work in {stdout}"));
    for words in [
        "physics steps per trial",
        "0 settle time-outs",
        "moves stopped by a contact",
        "0 steps with a joint beyond its velocity limit",
    ] {
        assert!(line.contains(words), "{line}");
    }
    let summary = data.path().join("ik/0/summary.json");
    let json: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(summary).unwrap()).unwrap();
    assert_eq!(json["sim"], "dynamic");
    assert!(json["physics_steps_per_trial"].as_f64().unwrap() > 10.0);
    assert_eq!(json["speed_faults"], 0);
    assert!(json["worst_speed_fault"].is_null());
    assert!(json["moves"].as_u64().unwrap() >= 5);
}

#[test]
fn fk_prints_the_camera_centre_as_json() {
    let out = Command::new(env!("CARGO_BIN_EXE_eyehand"))
        .args(["fk", "--joints", "0,30,100", "--json"])
        .output()
        .unwrap();
    assert!(out.status.success());
    let json: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let camera: Vec<f64> = json["camera_cm"]
        .as_array()
        .unwrap()
        .iter()
        .map(|v| v.as_f64().unwrap())
        .collect();
    let (t2, t3) = (30f64.to_radians(), 100f64.to_radians());
    let x = 60.0 * t2.cos() + 55.0 * (t2 - t3).cos();
    let z = 55.0 + 60.0 * t2.sin() + 55.0 * (t2 - t3).sin() - 10.0;
    assert!(
        (camera[0] - x).abs() < 1e-9 && camera[1].abs() < 1e-9 && (camera[2] - z).abs() < 1e-9,
        "{camera:?}"
    );
    let joints = json["joints_deg"].as_array().unwrap();
    assert_eq!(joints.len(), 6);
    assert!(
        (joints[4].as_f64().unwrap() - 20.0).abs() < 1e-9,
        "θ5 = 90 + θ2 − θ3"
    );
}

#[test]
fn verbose_output_writes_the_tree_every_depth_info_trials_to_a_file_off_a_terminal() {
    let data = tempfile::tempdir().unwrap();
    let run = |verbose: &str| {
        Command::new(env!("CARGO_BIN_EXE_eyehand"))
            .args([
                "run",
                "--trials",
                "40",
                "--quiet",
                "--no-plot",
                "--set",
                "depth_info=10",
                "--set",
            ])
            .arg(format!("verbose_output={verbose}"))
            .arg("--data")
            .arg(data.path())
            .output()
            .unwrap()
    };
    let out = run("1");
    assert!(
        String::from_utf8_lossy(&out.stderr).is_empty(),
        "not on a terminal: no lines"
    );
    let stdout = String::from_utf8_lossy(&out.stdout);
    let folder = Path::new(stdout.lines().next().unwrap());
    let written = std::fs::read_to_string(folder.join("tree_lines")).unwrap();
    let lines: Vec<&str> = written
        .lines()
        .filter(|l| l.starts_with("trial "))
        .collect();
    assert_eq!(lines.len(), 4, "{written}");
    assert!(
        lines[3].starts_with("trial 40: ") && lines[3].contains(" d0: 1 nodes"),
        "{}",
        lines[3]
    );
    let quiet = run("0");
    assert!(String::from_utf8_lossy(&quiet.stderr).is_empty());
    let stdout = String::from_utf8_lossy(&quiet.stdout);
    let folder = Path::new(stdout.lines().next().unwrap());
    assert!(
        !folder.join("tree_lines").exists(),
        "without verbose_output"
    );
}

#[test]
fn max_stored_patterns_bounds_what_a_run_stores() {
    let data = tempfile::tempdir().unwrap();
    let mut config = Config::default_config();
    config.trials = 300;
    config.max_stored_patterns = 1000;
    let run = run(&RunOptions::new(config, data.path())).unwrap();
    let column = |file: &str| -> Vec<usize> {
        let text = std::fs::read_to_string(run.folder.join(file)).unwrap();
        text.lines()
            .map(|l| l.split(' ').nth(1).unwrap().parse().unwrap())
            .collect()
    };
    let patterns = column("patterns");
    assert_eq!(patterns.len(), 300);
    assert!(patterns.iter().all(|&n| n <= 1000), "{patterns:?}");
    assert!(
        patterns.iter().filter(|&&n| n >= 990).count() > 100,
        "the cap is reached early and held: {patterns:?}"
    );
    assert!(column("bins").iter().zip(&patterns).all(|(b, p)| b <= p));
    assert!(run.summary.patterns <= 1000 && run.summary.patterns >= 990);
}

#[test]
fn failures_are_counted_by_reason_and_a_learner_without_a_tree_prints_none() {
    let data = tempfile::tempdir().unwrap();
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_eyehand"))
        .args([
            "run",
            "--method",
            "kohonen",
            "--trials",
            "500",
            "--no-plot",
            "--data",
        ])
        .arg(data.path())
        .output()
        .unwrap();
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let folder = Path::new(stdout.lines().next().unwrap());
    let json: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(folder.join("summary.json")).unwrap())
            .unwrap();
    let failures = json["failures"].as_u64().unwrap();
    assert!(failures > 0, "kohonen fails trials early: {json}");
    let by_reason = json["failures_by_reason"].as_object().unwrap();
    let sum: u64 = by_reason.values().map(|v| v.as_u64().unwrap()).sum();
    assert_eq!(sum, failures, "{by_reason:?}");
    assert!(stdout.contains(&format!("{failures} failed: ")), "{stdout}");
    assert!(!stdout.contains("tree: "), "kohonen has no tree: {stdout}");
    assert!(
        stdout.contains("\nmap: 16807 cells; "),
        "its own size: {stdout}"
    );
    // --method without --config: the declared defaults, and the run says so.
    assert_eq!(json["config_file"], "defaults", "{json}");
    assert!(
        stdout.contains(
            "kohonen on the kinematic simulator (projection camera), config defaults, seed 1: "
        ),
        "{stdout}"
    );
}

/// Text that cannot reach a full standard output is a failure, `--help` and `--version`
/// included (clap's own printing used to exit 0 there).
#[test]
fn a_full_stdout_fails_the_command() {
    for args in [&["--help"][..], &["--version"], &["config", "defaults"]] {
        let full = std::fs::OpenOptions::new()
            .write(true)
            .open("/dev/full")
            .unwrap();
        let out = std::process::Command::new(env!("CARGO_BIN_EXE_eyehand"))
            .args(args)
            .stdout(full)
            .output()
            .unwrap();
        assert_eq!(out.status.code(), Some(1), "{args:?}");
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert!(stderr.contains("writing to stdout"), "{args:?}: {stderr}");
    }
}
