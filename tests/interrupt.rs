//! Runs killed at random (seeded) moments: after SIGKILL every data file holds whole lines
//! that parse and `summary.json` is absent or valid; after SIGINT or SIGTERM the run ends
//! its trial, writes `summary.json` with `"interrupted": true` and exits 130 or 143.

use eyehand::experiment::plot::Series;
use eyehand::experiment::{RunSummary, StepFigures};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use std::path::{Path, PathBuf};
use std::process::{Child, Command, ExitStatus, Stdio};
use std::time::Duration;

const KILLS: usize = 10;
/// Files of `trial value minutes` lines.
const SERIES_FILES: [&str; 9] = [
    "1step", "2step", "3step", "4step", "5step", "nodes", "bins", "patterns", "mem",
];

/// A long lin5 run into `data` (it never ends on its own within the test).
fn start_run(data: &Path, plot: bool) -> Child {
    let mut command = Command::new(env!("CARGO_BIN_EXE_eyehand"));
    command
        .args(["run", "--trials", "1000000", "--quiet", "--data"])
        .arg(data)
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .stdout(Stdio::null())
        .stderr(Stdio::null());
    if !plot {
        command.arg("--no-plot");
    }
    command.spawn().unwrap()
}

fn signal(child: &Child, name: &str) {
    let status = Command::new("kill")
        .args([format!("-{name}"), child.id().to_string()])
        .status()
        .unwrap();
    assert!(status.success(), "kill -{name}");
}

/// The run folder, if the run got as far as making it.
fn run_folder(data: &Path) -> Option<PathBuf> {
    let folder = data.join("lin5").join("0");
    folder.is_dir().then_some(folder)
}

/// Checks that every data file in `folder` is whole lines that parse; returns the trials
/// recorded in `nodes`.
fn check_data_files(folder: &Path) -> usize {
    for name in SERIES_FILES.iter().chain(&["abs_err", "merges", "changes"]) {
        let text = std::fs::read_to_string(folder.join(name)).unwrap_or_default();
        let tail = &text[whole_lines(&text).len()..];
        assert!(
            tail.len() < MAX_LINE,
            "{name} ends in more than a torn line: `{tail}`"
        );
    }
    for name in SERIES_FILES {
        Series::read(&folder.join(name)).unwrap_or_else(|e| panic!("{name}: {e}"));
    }
    let abs_err = std::fs::read_to_string(folder.join("abs_err")).unwrap_or_default();
    for line in whole_lines(&abs_err).lines() {
        let mut fields = line.split(' ');
        assert!(
            fields.next().unwrap().parse::<usize>().is_ok(),
            "abs_err `{line}`"
        );
        assert!(
            fields.all(|f| f == "-" || f.parse::<f64>().is_ok()),
            "abs_err `{line}`"
        );
    }
    Series::read(&folder.join("nodes")).unwrap().points.len()
}

/// The longest line a data file holds (bytes): `abs_err` with every tree level.
const MAX_LINE: usize = 256;

/// `text` up to its last newline. A kill can tear a file's last line: Linux writes a regular
/// file page by page and stops at the next page once the process is killed, so a flush of
/// whole lines may end mid-line. The readers ignore such a tail; the lines before it are
/// whole.
fn whole_lines(text: &str) -> &str {
    text.rfind('\n').map_or("", |end| &text[..=end])
}

/// `summary.json`, if there is one (it must parse).
fn summary(folder: &Path) -> Option<RunSummary> {
    let text = std::fs::read_to_string(folder.join("summary.json")).ok()?;
    Some(serde_json::from_str(&text).expect("summary.json parses"))
}

fn wait(child: &mut Child) -> ExitStatus {
    for _ in 0..600 {
        if let Some(status) = child.try_wait().unwrap() {
            return status;
        }
        std::thread::sleep(Duration::from_millis(50));
    }
    child.kill().unwrap();
    panic!("the run did not stop within 30 s of the signal");
}

#[test]
fn sigkill_at_random_moments_leaves_whole_lines() {
    let mut rng = ChaCha8Rng::seed_from_u64(12);
    let (mut folders, mut with_summary) = (0, 0);
    for _ in 0..KILLS {
        let data = tempfile::tempdir().unwrap();
        let mut child = start_run(data.path(), false);
        std::thread::sleep(Duration::from_millis(rng.random_range(100..2500)));
        child.kill().unwrap();
        child.wait().unwrap();
        if let Some(folder) = run_folder(data.path()) {
            folders += 1;
            check_data_files(&folder);
            with_summary += usize::from(summary(&folder).is_some());
        }
    }
    println!(
        "{KILLS} SIGKILLs, {folders} after the run folder was made: every data file whole \
         lines; {with_summary} summaries (valid)"
    );
    assert!(
        folders >= KILLS / 2,
        "most kills come after the folder is made"
    );
}

#[test]
fn sigint_and_sigterm_finish_the_trial_and_write_an_interrupted_summary() {
    let mut rng = ChaCha8Rng::seed_from_u64(21);
    let mut trials_done = Vec::new();
    for kill in 0..KILLS {
        let (name, code) = if kill % 2 == 0 {
            ("INT", 130)
        } else {
            ("TERM", 143)
        };
        let data = tempfile::tempdir().unwrap();
        let mut child = start_run(data.path(), kill % 3 == 0);
        std::thread::sleep(Duration::from_millis(rng.random_range(300..2500)));
        signal(&child, name);
        let status = wait(&mut child);
        assert_eq!(status.code(), Some(code), "SIG{name}: {status}");
        let folder = run_folder(data.path()).expect("the run made its folder");
        let recorded = check_data_files(&folder);
        let summary = summary(&folder).expect("an interrupted run writes summary.json");
        assert!(summary.interrupted, "SIG{name}");
        assert_eq!(
            summary.trials, recorded,
            "SIG{name}: summary and nodes agree"
        );
        assert_eq!(summary.window, StepFigures::window_for(recorded));
        assert!(
            summary.mean_distance_mm[0].is_some(),
            "figures over its last trials"
        );
        let info = std::fs::read_to_string(folder.join("info")).unwrap();
        assert!(info.contains(&format!("interrupted after trial {recorded}")));
        trials_done.push(recorded);
    }
    println!(
        "{KILLS} SIGINT/SIGTERMs: exit 130/143, summaries interrupted after {trials_done:?} trials"
    );
}

/// A run whose one trial takes tens of seconds (the dynamic arm servoed continuously at one
/// frame a second for up to 1,000 steps) stops within a couple of seconds of SIGTERM: the
/// trial is cut short, the summary written.
#[test]
fn a_signal_cuts_a_long_trial_short() {
    let data = tempfile::tempdir().unwrap();
    let mut child = Command::new(env!("CARGO_BIN_EXE_eyehand"))
        .args([
            "run",
            "--trials",
            "3",
            "--quiet",
            "--no-plot",
            "--sim",
            "dynamic",
        ])
        .args(["--set", "servo_mode=continuous", "--set", "camera_fps=1"])
        .args([
            "--set",
            "feedback_steps=1000",
            "--set",
            "dt=0.0005",
            "--data",
        ])
        .arg(data.path())
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .spawn()
        .unwrap();
    std::thread::sleep(Duration::from_secs(4));
    assert!(
        child.try_wait().unwrap().is_none(),
        "trial 1 is still going"
    );
    let sent = std::time::Instant::now();
    signal(&child, "TERM");
    let status = wait(&mut child);
    let took = sent.elapsed();
    assert_eq!(status.code(), Some(143));
    assert!(
        took < Duration::from_secs(3),
        "stopped {took:?} after SIGTERM"
    );
    let summary = summary(&data.path().join("lin5").join("0")).expect("a summary");
    assert!(summary.interrupted, "{summary:?}");
    println!(
        "stopped {took:?} after SIGTERM, after {} trials",
        summary.trials
    );
}
