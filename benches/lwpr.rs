//! LWPR beside the Nested Perceptron on the kinematic simulator. Prints two markdown
//! tables (for docs/LWPR.md):
//! 1. precision and cost: lin5 (split_error 1e-4 and 1e-5), LWPR with its defaults and
//!    with the best `init_D` × `w_gen` of a sweep; mean ± s.d. over the seeds of the mean
//!    distance after steps 1..5 over the last 1,000 trials, trials per second, peak memory,
//!    and nodes (lin5) or receptive fields (LWPR);
//! 2. adaptation: the adaptation benchmark's five events before trial 1,500 of 4,500
//!    trials, for LWPR with forgetting alone, LWPR with change detection and lin5 with
//!    change detection: the 4-step mean before, trials to recover (a 50-trial running
//!    4-step mean back within 1.5× the 500 trials before, `FourStepTrace`), and the
//!    detection delay.
//!
//! `cargo bench --bench lwpr` (seeds 1–3, 50,000 trials), or fewer:
//! `cargo bench --bench lwpr -- --seeds 1 --trials 20000`; `--only precision` or
//! `--only adaptation` runs one table.

mod common;

use common::recovery::{alarms, detected_after};
use common::run_cli;
use eyehand::experiment::FourStepTrace;
use eyehand::experiment::RunSummary;
use std::path::Path;

/// The precision table's rows: label, config, `--set` values.
const PRECISION_ROWS: [(&str, &str, &[&str]); 4] = [
    ("lin5, split_error 1e-4", "lin5", &["split_error=1e-4"]),
    ("lin5, split_error 1e-5", "lin5", &["split_error=1e-5"]),
    ("lwpr, defaults", "lwpr", &[]),
    // The best 4-step mean of `eyehand sweep --config configs/lwpr.conf --set
    // init_D=25,50,100,200 --set w_gen=0.1,0.2 --set trials=10000 --seeds 1` (docs/LWPR.md:
    // 1.76 mm, beside 1.86 for init_D 100, w_gen 0.2 and 3.23 for the defaults).
    (
        "lwpr, init_D 200, w_gen 0.2",
        "lwpr",
        &["init_D=200", "w_gen=0.2"],
    ),
];
const EVENT_TRIAL: usize = 1500;
const ADAPTATION_TRIALS: usize = 4500;
const SCENARIOS: [(&str, &str); 5] = [
    ("camera 30°", "rotate:1500:30"),
    ("camera 90°", "rotate:1500:90"),
    ("link 1 +10 cm", "elongate:1500:1:10"),
    ("link 2 +10 cm", "elongate:1500:2:10"),
    ("link 2 −10 cm", "elongate:1500:2:-10"),
];
const ADAPTATION_ROWS: [(&str, &str, &str); 3] = [
    ("lwpr, forgetting alone", "lwpr", "merge_strategy=thesis"),
    (
        "lwpr, change_detection",
        "lwpr",
        "merge_strategy=change_detection",
    ),
    (
        "lin5, change_detection",
        "lin5",
        "merge_strategy=change_detection",
    ),
];

/// Command-line choices: seeds, trials of the precision runs, which tables.
struct Plan {
    seeds: Vec<u64>,
    trials: usize,
    only: Option<String>,
}

fn plan() -> Plan {
    let args: Vec<String> = std::env::args().collect();
    let value = |flag: &str| {
        args.iter()
            .position(|a| a == flag)
            .and_then(|i| args.get(i + 1).cloned())
    };
    Plan {
        seeds: value("--seeds").map_or(vec![1, 2, 3], |s| {
            s.split(',').map(|v| v.parse().expect("a seed")).collect()
        }),
        trials: value("--trials").map_or(50_000, |t| t.parse().expect("a trial count")),
        only: value("--only"),
    }
}

fn config_path(name: &str) -> String {
    format!("{}/configs/{name}.conf", env!("CARGO_MANIFEST_DIR"))
}

/// `mean ± s.d.` of `values` with `decimals` (the value alone for one run).
fn spread(values: &[f64], decimals: usize) -> String {
    let n = values.len() as f64;
    let m = values.iter().sum::<f64>() / n;
    if values.len() == 1 {
        return format!("{m:.decimals$}");
    }
    let sd = (values.iter().map(|v| (v - m).powi(2)).sum::<f64>() / (n - 1.0).max(1.0)).sqrt();
    format!("{m:.decimals$} ± {sd:.decimals$}")
}

/// Runs `config` with `sets` for each seed, writing into `data`.
fn runs(
    data: &Path,
    config: &str,
    sets: &[&str],
    trials: usize,
    seeds: &[u64],
    extra: &[&str],
) -> Vec<common::Finished> {
    let (config, trials) = (config_path(config), trials.to_string());
    seeds
        .iter()
        .map(|seed| {
            let seed = seed.to_string();
            let mut args = vec!["--config", &config, "--trials", &trials, "--seed", &seed];
            args.extend(sets.iter().flat_map(|s| ["--set", *s]));
            args.extend(extra);
            run_cli(data, &args)
        })
        .collect()
}

fn precision_table(plan: &Plan) {
    println!("| learner | 1 step (mm) | 2 steps | 3 steps | 4 steps | 5 steps | trials/s | peak memory (MB) | nodes / fields |");
    println!("|---|---|---|---|---|---|---|---|---|");
    let data = tempfile::tempdir().expect("a temporary data folder");
    for (label, config, sets) in PRECISION_ROWS {
        let summaries: Vec<RunSummary> =
            runs(data.path(), config, sets, plan.trials, &plan.seeds, &[])
                .into_iter()
                .map(|f| f.summary)
                .collect();
        let column = |f: &dyn Fn(&RunSummary) -> f64| summaries.iter().map(f).collect::<Vec<_>>();
        let steps: Vec<String> = (0..5)
            .map(|i| spread(&column(&|s| s.mean_distance_mm[i].unwrap_or(f64::NAN)), 4))
            .collect();
        println!(
            "| {label} | {} | {} | {} | {} |",
            steps.join(" | "),
            spread(&column(&|s| s.trials_per_second), 0),
            spread(&column(&|s| s.peak_rss_kb as f64 / 1024.0), 1),
            spread(&column(&|s| s.nodes as f64), 0),
        );
    }
    println!(
        "\nkinematic simulator, {} trials, seeds {:?}: mean ± s.d. over the seeds of the mean distance (mm) after each step over the last 1,000 trials",
        plan.trials, plan.seeds
    );
}

fn adaptation_table(plan: &Plan) {
    println!("\n| event at trial {EVENT_TRIAL} | learner | 4-step before (mm) | recovered after (trials) | detected after (trials) | 4-step last 500 (mm) |");
    println!("|---|---|---|---|---|---|");
    for (name, event) in SCENARIOS {
        // (A data folder per scenario: a method's folder holds at most 36 runs.)
        let data = tempfile::tempdir().expect("a temporary data folder");
        for (label, config, strategy) in ADAPTATION_ROWS {
            let finished = runs(
                data.path(),
                config,
                &[strategy],
                ADAPTATION_TRIALS,
                &plan.seeds,
                &["--event", event],
            );
            let cells: Vec<[String; 4]> = finished
                .iter()
                .map(|f| {
                    let trace = FourStepTrace::read(&f.folder).expect("4step");
                    let before = trace.level_before(EVENT_TRIAL).unwrap_or(f64::NAN);
                    [
                        format!("{before:.3}"),
                        trace
                            .recovered_after(EVENT_TRIAL)
                            .map_or("never".into(), |t| t.to_string()),
                        detected_after(&alarms(&f.folder), EVENT_TRIAL),
                        format!(
                            "{:.3}",
                            trace
                                .mean(ADAPTATION_TRIALS - 499, ADAPTATION_TRIALS)
                                .unwrap_or(f64::NAN)
                        ),
                    ]
                })
                .collect();
            let join = |k: usize| {
                cells
                    .iter()
                    .map(|c| c[k].clone())
                    .collect::<Vec<_>>()
                    .join(" / ")
            };
            println!(
                "| {name} | {label} | {} | {} | {} | {} |",
                join(0),
                join(1),
                join(2),
                join(3)
            );
        }
    }
    println!("\nseeds {:?} (one figure per seed), {ADAPTATION_TRIALS} trials, event before trial {EVENT_TRIAL}", plan.seeds);
}

fn main() {
    let plan = plan();
    if plan.only.as_deref() != Some("adaptation") {
        precision_table(&plan);
    }
    if plan.only.as_deref() != Some("precision") {
        adaptation_table(&plan);
    }
}
