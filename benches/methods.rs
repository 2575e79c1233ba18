//! Which method for what: every method on the kinematic simulator on its shipped config
//! (`configs/<method>.conf`), the learners with a model under `merge_strategy
//! change_detection` (their alarms answered by `change_recovery correct`, the default),
//! seeds 1–3. Per method one row: the mean distance after each feedback step over the last
//! trials of a run without an event (its summary's window, a tenth of the trials up to
//! 1,000; averaged over the seeds), per seed the trials until the 4-step mean over the last
//! 200 trials is at most 1 mm and 0.1 mm (as `compare`), the trials per second of that run
//! (mean over the seeds), and per seed the trials to recover (the 4-step mean over the last
//! 50 trials within 1.5× its level over the 500 before: `FourStepTrace::recovered_after`;
//! "never": not by the last trial) after a 30° camera turn and after link 2 +10 cm and
//! −10 cm at a quarter of the trials.
//!
//! `cargo bench --bench methods` (20,000 trials, the events at 5,000); `cargo bench --bench
//! methods -- broyden lin5` runs only those methods; `-- --trials N` runs N trials each
//! (the events at N/4).

mod common;

use common::run_cli;
use eyehand::experiment::FourStepTrace;
use eyehand::learn::Method;
use std::path::Path;

/// Trials per run unless `--trials` says otherwise.
const TRIALS: usize = 20_000;
const SEEDS: [u64; 3] = [1, 2, 3];
/// The events, as a table column and as `--event` with the trial left for `{}`.
const EVENTS: [(&str, &str); 3] = [
    ("30° turn", "rotate:{}:30"),
    ("link 2 +10 cm", "elongate:{}:2:10"),
    ("link 2 −10 cm", "elongate:{}:2:-10"),
];
/// Trials in the running 4-step mean whose first reach of 1 mm and 0.1 mm is counted.
const TRIALS_TO_WINDOW: usize = 200;
/// Feedback steps whose mean distance is tabulated (the shipped `feedback_steps`).
const STEPS: usize = 10;

/// The methods that watch for a change and so run under change detection.
fn watches(method: Method) -> bool {
    !matches!(method, Method::Ik | Method::Broyden)
}

/// What one seed's runs gave.
struct SeedFigures {
    by_step: Vec<Option<f64>>,
    to_1mm: Option<usize>,
    to_01mm: Option<usize>,
    trials_per_second: f64,
    recovered: Vec<Option<usize>>,
}

/// Runs `method` with `seed` for `trials` trials: once without an event, once per event.
fn seed_figures(method: Method, seed: u64, trials: usize, data: &Path) -> SeedFigures {
    let config = format!("{}/configs/{method}.conf", env!("CARGO_MANIFEST_DIR"));
    let (trials_text, seed_text) = (trials.to_string(), seed.to_string());
    let mut base = vec![
        "--config",
        &config,
        "--trials",
        &trials_text,
        "--seed",
        &seed_text,
    ];
    if watches(method) {
        base.extend(["--set", "merge_strategy=change_detection"]);
    }
    let plain = run_cli(data, &base);
    let trace = FourStepTrace::read(&plain.folder).expect("4step");
    let event_trial = trials / 4;
    let recovered = EVENTS
        .iter()
        .map(|(_, event)| {
            let event = event.replace("{}", &event_trial.to_string());
            let mut args = base.clone();
            args.extend(["--event", &event]);
            let folder = run_cli(data, &args).folder;
            FourStepTrace::read(&folder)
                .expect("4step")
                .recovered_after(event_trial)
        })
        .collect();
    SeedFigures {
        by_step: plain.summary.mean_distance_by_step_mm.clone(),
        to_1mm: trace.first_within(1.0, TRIALS_TO_WINDOW),
        to_01mm: trace.first_within(0.1, TRIALS_TO_WINDOW),
        trials_per_second: plain.summary.trials_per_second,
        recovered,
    }
}

/// Each seed's count, " / "-separated ("never" for none).
fn per_seed(seeds: &[SeedFigures], count: impl Fn(&SeedFigures) -> Option<usize>) -> String {
    let counts: Vec<String> = seeds
        .iter()
        .map(|s| count(s).map_or("never".into(), |n| n.to_string()))
        .collect();
    counts.join(" / ")
}

/// The mean of the seeds' values that exist (`-`: none).
fn mean_cell(values: impl Iterator<Item = Option<f64>>, digits: usize) -> String {
    let present: Vec<f64> = values.flatten().collect();
    if present.is_empty() {
        return "-".into();
    }
    format!(
        "{:.digits$}",
        present.iter().sum::<f64>() / present.len() as f64
    )
}

/// The table's row of `method`.
fn row(method: Method, seeds: &[SeedFigures]) -> String {
    let mut row = format!("| {method} |");
    for step in 0..STEPS {
        let values = seeds.iter().map(|s| s.by_step.get(step).copied().flatten());
        row += &format!(" {} |", mean_cell(values, 4));
    }
    row += &format!(" {} |", per_seed(seeds, |s| s.to_1mm));
    row += &format!(" {} |", per_seed(seeds, |s| s.to_01mm));
    let rates = seeds.iter().map(|s| Some(s.trials_per_second));
    row += &format!(" {} |", mean_cell(rates, 0));
    for event in 0..EVENTS.len() {
        row += &format!(" {} |", per_seed(seeds, |s| s.recovered[event]));
    }
    row
}

/// The methods named on the command line (none: all), and `--trials N`.
fn arguments() -> (Vec<Method>, usize) {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let trials = args
        .iter()
        .position(|a| a == "--trials")
        .and_then(|i| args.get(i + 1)?.parse().ok())
        .unwrap_or(TRIALS);
    let named: Vec<Method> = args.iter().filter_map(|a| a.parse().ok()).collect();
    let methods = if named.is_empty() {
        Method::ALL.to_vec()
    } else {
        named
    };
    (methods, trials)
}

fn main() {
    let (methods, trials) = arguments();
    let mut header = String::from("| method |");
    for step in 1..=STEPS {
        header += &format!(" {step} |");
    }
    header += " trials to 1 mm (seeds 1 / 2 / 3) | to 0.1 mm | trials/s |";
    for (name, _) in EVENTS {
        header += &format!(" recover after {name} |");
    }
    println!(
        "{trials} trials, events at trial {}; distances in mm",
        trials / 4
    );
    println!("{header}");
    println!("|---{}", "|---".repeat(STEPS + 3 + EVENTS.len()) + "|");
    for method in methods {
        // (A data folder per method: a method's folder holds at most 36 runs.)
        let data = tempfile::tempdir().expect("a temporary data folder");
        let seeds: Vec<SeedFigures> = SEEDS
            .iter()
            .map(|&seed| seed_figures(method, seed, trials, data.path()))
            .collect();
        println!("{}", row(method, &seeds));
    }
}
