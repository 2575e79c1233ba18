//! What the benchmarks share: running `eyehand run` as its own process (so memory
//! figures are the run's own) and reading back its summary and data files.

#![allow(dead_code)]

pub mod recovery;

use eyehand::experiment::{run, Config, RunOptions, RunSummary};
use std::path::{Path, PathBuf};
use std::process::Command;

/// A finished run: its folder and summary.
pub struct Finished {
    pub folder: PathBuf,
    pub summary: RunSummary,
}

/// Runs `eyehand run ARGS --data DATA --quiet --no-plot` and reads its summary.
pub fn run_cli(data: &Path, args: &[&str]) -> Finished {
    let output = Command::new(env!("CARGO_BIN_EXE_eyehand"))
        .arg("run")
        .args(args)
        .arg("--data")
        .arg(data)
        .args(["--quiet", "--no-plot"])
        .output()
        .expect("eyehand runs");
    assert!(
        output.status.success(),
        "{}",
        String::from_utf8_lossy(&output.stderr)
    );
    let folder = PathBuf::from(String::from_utf8_lossy(&output.stdout).trim());
    let json = std::fs::read_to_string(folder.join("summary.json")).expect("summary.json");
    Finished {
        summary: serde_json::from_str(&json).expect("a valid summary"),
        folder,
    }
}

/// Runs `config` in this process, into a temporary data folder, and returns its summary.
pub fn run_in_process(config: Config) -> RunSummary {
    let data = tempfile::tempdir().expect("a temporary data folder");
    run(&RunOptions::new(config, data.path()))
        .expect("the run succeeds")
        .summary
}

/// Trials per second over trials (from, to] from the minutes column of `nodes`.
pub fn rate_between(folder: &Path, from: usize, to: usize) -> f64 {
    let text = std::fs::read_to_string(folder.join("nodes")).expect("nodes");
    let minutes_at = |trial: usize| -> f64 {
        if trial == 0 {
            return 0.0;
        }
        let line = text.lines().nth(trial - 1).expect("the trial was run");
        line.split(' ')
            .nth(2)
            .expect("a minutes column")
            .parse()
            .expect("minutes")
    };
    (to - from) as f64 / ((minutes_at(to) - minutes_at(from)) * 60.0).max(1e-9)
}

/// A distance cell: 4 decimals, or `-` for a step never taken.
pub fn mm(value: Option<f64>) -> String {
    value.map_or("-".into(), |v| format!("{v:.4}"))
}
