//! Recovery from a changed robot on the kinematic simulator, seeds 1–3, 4,500 trials, one
//! event before trial 1,500: lin5 under the study's merges (`merge_strategy thesis`, with
//! the shipped `am_error_tresh` 20 and with 12, the value that repeats the study's 90° root
//! merge), lin5 and lin8 under change detection with each `change_recovery` (correct, the
//! default, and forget), LWPR with its forgetting alone and with change detection, and the
//! fixed-model `ik` controller. Prints a markdown table, a row per scenario and learner,
//! each cell the three seeds' figures: the 4-step mean over the 500 trials before the event,
//! trials after the event until the 4-step mean over the last 50 trials is within 1.5× that
//! level (`FourStepTrace::recovered_after`; "never": not by the last trial), the detection
//! delay (trials from the event to the first alarm; alarms before the event are counted
//! apart), the merges by kind, and the 4-step mean over the last 500 trials. Then 50,000
//! trials without an event for lin5 under each strategy and lin8 under change detection:
//! alarms and merges, and the 4-step mean over the last 1,000 trials. Last, lin5 with and
//! without `learn_during_moves` on both simulators (`during_moves`).
//!
//! `cargo bench --bench adaptation`; `cargo bench --bench adaptation -- "lin5
//! change_detection" "lin8 change_detection"` runs only the rows of those learners (labels
//! as in the table); `cargo bench --bench adaptation -- learn_during_moves` only the last
//! table.

mod common;
#[path = "adaptation/during_moves.rs"]
mod during_moves;

use common::recovery::{alarms, detected_after};
use common::run_cli;
use eyehand::experiment::FourStepTrace;
use std::path::Path;

const TRIALS: usize = 4500;
const EVENT_TRIAL: usize = 1500;
const SEEDS: [u64; 3] = [1, 2, 3];
const SCENARIOS: [(&str, &str); 8] = [
    ("camera 90°", "rotate:1500:90"),
    ("camera 30°", "rotate:1500:30"),
    ("link 1 +10 cm", "elongate:1500:1:10"),
    ("link 1 −10 cm", "elongate:1500:1:-10"),
    ("link 2 +10 cm", "elongate:1500:2:10"),
    ("link 2 −10 cm", "elongate:1500:2:-10"),
    ("link 3 +10 cm", "elongate:1500:3:10"),
    ("link 3 −10 cm", "elongate:1500:3:-10"),
];
/// The learners compared: label, config, `--set` values.
const LEARNERS: [(&str, &str, &[&str]); 8] = [
    ("lin5 thesis", "lin5", &["merge_strategy=thesis"]),
    (
        "lin5 thesis, am_error_tresh 12",
        "lin5",
        &["merge_strategy=thesis", "am_error_tresh=12"],
    ),
    (
        "lin5 change_detection",
        "lin5",
        &["merge_strategy=change_detection"],
    ),
    (
        "lin5 change_detection, change_recovery forget",
        "lin5",
        &["merge_strategy=change_detection", "change_recovery=forget"],
    ),
    (
        "lin8 change_detection",
        "lin8",
        &["merge_strategy=change_detection"],
    ),
    ("lwpr (forgetting)", "lwpr", &[]),
    (
        "lwpr change_detection",
        "lwpr",
        &["merge_strategy=change_detection"],
    ),
    ("ik", "ik", &[]),
];
/// Trials of the runs without an event.
const LONG_TRIALS: usize = 50_000;

/// Merges by kind from a run's `merges` file: "absolute,relative,starved".
fn merges(folder: &Path) -> String {
    let text = std::fs::read_to_string(folder.join("merges")).unwrap_or_default();
    let count = |kind: &str| {
        text.lines()
            .filter(|l| l.split(' ').nth(1) == Some(kind))
            .count()
    };
    format!(
        "{},{},{}",
        count("absolute"),
        count("relative"),
        count("starved")
    )
}

struct Recovery {
    before: f64,
    recovered_after: Option<usize>,
    detected_after: String,
    false_alarms: usize,
    merges: String,
    last: f64,
}

fn recovery(folder: &Path) -> Recovery {
    let trace = FourStepTrace::read(folder).expect("4step");
    let alarms = alarms(folder);
    Recovery {
        before: trace.level_before(EVENT_TRIAL).unwrap_or(f64::NAN),
        recovered_after: trace.recovered_after(EVENT_TRIAL),
        detected_after: detected_after(&alarms, EVENT_TRIAL),
        false_alarms: alarms.iter().filter(|&&t| t < EVENT_TRIAL).count(),
        merges: merges(folder),
        last: trace.mean(TRIALS - 499, TRIALS).unwrap_or(f64::NAN),
    }
}

fn config_path(name: &str) -> String {
    format!("{}/configs/{name}.conf", env!("CARGO_MANIFEST_DIR"))
}

/// `--set` flags for `sets`.
fn set_flags<'a>(sets: &[&'a str]) -> Vec<&'a str> {
    sets.iter().flat_map(|s| ["--set", *s]).collect()
}

/// The cells of one learner's row: each figure for seeds 1, 2, 3, separated by " / ".
fn row(runs: &[Recovery]) -> [String; 5] {
    let join = |f: &dyn Fn(&Recovery) -> String| runs.iter().map(f).collect::<Vec<_>>().join(" / ");
    let trials_or = |v: Option<usize>, none: &str| v.map_or(none.to_string(), |t| t.to_string());
    [
        join(&|r| format!("{:.3}", r.before)),
        join(&|r| trials_or(r.recovered_after, "never")),
        join(&|r| match r.false_alarms {
            0 => r.detected_after.clone(),
            n => format!("{} ({n} before)", r.detected_after),
        }),
        join(&|r| r.merges.clone()),
        join(&|r| format!("{:.3}", r.last)),
    ]
}

/// The rows named on the command line (none: all).
fn names() -> Vec<String> {
    std::env::args()
        .skip(1)
        .filter(|a| !a.starts_with("--"))
        .collect()
}

/// The learners whose rows are run: those in `names`, or all if it is empty.
fn chosen(names: &[String]) -> Vec<(&'static str, &'static str, &'static [&'static str])> {
    LEARNERS
        .into_iter()
        .filter(|(label, ..)| names.is_empty() || names.iter().any(|n| n == label))
        .collect()
}

fn main() {
    let names = names();
    let learners = chosen(&names);
    if !learners.is_empty() {
        print_recoveries(&learners);
    }
    if names.is_empty() || names.iter().any(|n| n == during_moves::LABEL) {
        println!();
        during_moves::print(&SEEDS);
    }
}

/// The tables of recovery after each event and of the runs without one, for `learners`.
fn print_recoveries(learners: &[(&str, &str, &[&str])]) {
    let trials = TRIALS.to_string();
    println!("| event at trial {EVENT_TRIAL} | learner | 4-step before (mm) | recovered after (trials to 1.5×) | detected after (trials) | merges abs,rel,starved | 4-step last 500 (mm) |");
    println!("|---|---|---|---|---|---|---|");
    for (name, event) in SCENARIOS {
        // (A data folder per scenario: a method's folder holds at most 36 runs.)
        let data = tempfile::tempdir().expect("a temporary data folder");
        for &(label, config, sets) in learners {
            let runs: Vec<Recovery> = SEEDS
                .iter()
                .map(|seed| {
                    let (config, seed_text) = (config_path(config), seed.to_string());
                    let mut args = vec![
                        "--config", &config, "--trials", &trials, "--seed", &seed_text, "--event",
                        event,
                    ];
                    args.extend(set_flags(sets));
                    recovery(&run_cli(data.path(), &args).folder)
                })
                .collect();
            let [before, recovered, detected, merges, last] = row(&runs);
            println!(
                "| {name} | {label} | {before} | {recovered} | {detected} | {merges} | {last} |"
            );
        }
    }
    println!("\n| no event, {LONG_TRIALS} trials | seed | alarms | merges abs,rel,starved | 4-step last 1,000 (mm) |");
    println!("|---|---|---|---|---|");
    let long = LONG_TRIALS.to_string();
    let data = tempfile::tempdir().expect("a temporary data folder");
    let long_runs = [LEARNERS[0], LEARNERS[2], LEARNERS[4]];
    for (label, config, sets) in long_runs.into_iter().filter(|l| learners.contains(l)) {
        for seed in SEEDS {
            let (config, seed_text) = (config_path(config), seed.to_string());
            let mut args = vec!["--config", &config, "--trials", &long, "--seed", &seed_text];
            args.extend(set_flags(sets));
            let finished = run_cli(data.path(), &args);
            let trace = FourStepTrace::read(&finished.folder).expect("4step");
            println!(
                "| {label} | {seed} | {} | {} | {:.4} |",
                alarms(&finished.folder).len(),
                merges(&finished.folder),
                trace
                    .mean(LONG_TRIALS - 999, LONG_TRIALS)
                    .unwrap_or(f64::NAN)
            );
        }
    }
}
