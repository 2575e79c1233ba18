//! Which method for what: every method on the kinematic simulator on its shipped config
//! (`configs/<method>.conf`), the learners with a model under `merge_strategy
//! change_detection` (their alarms answered by `change_recovery correct`, the default),
//! seeds 1–3. Per method one row: the mean distance after each feedback step over the last
//! trials of a run without an event (its summary's window, a tenth of the trials up to
//! 1,000; averaged over the seeds), per seed the trials until the 4-step mean over the last
//! 200 trials is at most 1 mm and 0.1 mm (as `compare`), the trials per second of that run
//! (mean over the seeds), and per seed the trials to recover (the 4-step mean over the last
//! 50 trials within 1.5× its level over the 500 before: `FourStepTrace::recovered_after`)
//! after a 30° camera turn and after link 2 +10 cm and −10 cm at a quarter of the trials.
//! A run with an event ends [`RECOVERY_SPAN`] trials after it (or with the run without one,
//! if that is sooner): "never" means not within those trials.
//!
//! The runs (method × seed × {no event, three events}) are seeded and independent; they run
//! as separate processes, as many at once as the machine has cores (`--jobs N` to say
//! otherwise), and the rows are printed in the order of the methods asked for, each as soon
//! as its runs and those of the rows above are done: the table is the one a run after
//! another would print.
//!
//! `cargo bench --bench methods` (20,000 trials, the events at 5,000); `cargo bench --bench
//! methods -- broyden lin5` runs only those methods; `-- --trials N` runs N trials each
//! (the events at N/4).

mod common;

use common::run_cli;
use eyehand::experiment::FourStepTrace;
use eyehand::learn::Method;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::mpsc;

/// Trials per run unless `--trials` says otherwise.
const TRIALS: usize = 20_000;
/// Trials a run with an event goes on after it: its recovery is decided within them.
const RECOVERY_SPAN: usize = 3_000;
const SEEDS: [u64; 3] = [1, 2, 3];
/// The events, as a table column and as `--event` with the trial left for `{}`.
const EVENTS: [(&str, &str); 3] = [
    ("30° turn", "rotate:{}:30"),
    ("link 2 +10 cm", "elongate:{}:2:10"),
    ("link 2 −10 cm", "elongate:{}:2:-10"),
];
/// Runs per method and seed: one without an event, one per event.
const RUNS_PER_SEED: usize = 1 + EVENTS.len();
/// Trials in the running 4-step mean whose first reach of 1 mm and 0.1 mm is counted.
const TRIALS_TO_WINDOW: usize = 200;
/// Feedback steps whose mean distance is tabulated (the shipped `feedback_steps`).
const STEPS: usize = 10;

/// The methods that watch for a change and so run under change detection.
fn watches(method: Method) -> bool {
    !matches!(method, Method::Ik | Method::Broyden)
}

/// One run of the table: a method, a seed, and the index in [`EVENTS`] of its event
/// (`None`: the run without one).
struct Cell {
    method: Method,
    seed: u64,
    event: Option<usize>,
}

/// What one run gave.
enum Outcome {
    /// The run without an event.
    Plain {
        by_step: Vec<Option<f64>>,
        to_1mm: Option<usize>,
        to_01mm: Option<usize>,
        trials_per_second: f64,
    },
    /// A run with an event: the trials to recover from it.
    Recovered(Option<usize>),
}

/// Runs `cell` (`trials` trials without an event; with one, until [`RECOVERY_SPAN`] trials
/// after it) in a data folder of its own.
fn run_cell(cell: &Cell, trials: usize) -> Outcome {
    let config = format!(
        "{}/configs/{}.conf",
        env!("CARGO_MANIFEST_DIR"),
        cell.method
    );
    let event_trial = trials / 4;
    let length = match cell.event {
        None => trials,
        Some(_) => trials.min(event_trial + RECOVERY_SPAN),
    };
    let (length_text, seed_text) = (length.to_string(), cell.seed.to_string());
    let mut args = vec![
        "--config",
        &config,
        "--trials",
        &length_text,
        "--seed",
        &seed_text,
    ];
    if watches(cell.method) {
        args.extend(["--set", "merge_strategy=change_detection"]);
    }
    let event = cell
        .event
        .map(|e| EVENTS[e].1.replace("{}", &event_trial.to_string()));
    if let Some(event) = &event {
        args.extend(["--event", event]);
    }
    let data = tempfile::tempdir().expect("a temporary data folder");
    let run = run_cli(data.path(), &args);
    let trace = FourStepTrace::read(&run.folder).expect("4step");
    match cell.event {
        None => Outcome::Plain {
            by_step: run.summary.mean_distance_by_step_mm.clone(),
            to_1mm: trace.first_within(1.0, TRIALS_TO_WINDOW),
            to_01mm: trace.first_within(0.1, TRIALS_TO_WINDOW),
            trials_per_second: run.summary.trials_per_second,
        },
        Some(_) => Outcome::Recovered(trace.recovered_after(event_trial)),
    }
}

/// What one seed's runs gave.
struct SeedFigures<'a> {
    by_step: &'a [Option<f64>],
    to_1mm: Option<usize>,
    to_01mm: Option<usize>,
    trials_per_second: f64,
    recovered: Vec<Option<usize>>,
}

impl<'a> SeedFigures<'a> {
    /// Gathers a seed's [`RUNS_PER_SEED`] outcomes, the run without an event first.
    fn gather(outcomes: &'a [Outcome]) -> SeedFigures<'a> {
        let Outcome::Plain {
            by_step,
            to_1mm,
            to_01mm,
            trials_per_second,
        } = &outcomes[0]
        else {
            unreachable!("a seed's first run is the one without an event")
        };
        let recovered = outcomes[1..]
            .iter()
            .map(|o| match o {
                Outcome::Recovered(trials) => *trials,
                Outcome::Plain { .. } => unreachable!("a seed's later runs have an event"),
            })
            .collect();
        SeedFigures {
            by_step,
            to_1mm: *to_1mm,
            to_01mm: *to_01mm,
            trials_per_second: *trials_per_second,
            recovered,
        }
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

/// What the command line asks for.
struct Arguments {
    /// The methods named (none: all).
    methods: Vec<Method>,
    /// `--trials N`.
    trials: usize,
    /// `--jobs N`: runs at once (default: the machine's cores).
    jobs: usize,
}

/// Reads the command line.
fn arguments() -> Arguments {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let number_after = |flag: &str| {
        args.iter()
            .position(|a| a == flag)
            .and_then(|i| args.get(i + 1)?.parse::<usize>().ok())
    };
    let named: Vec<Method> = args.iter().filter_map(|a| a.parse().ok()).collect();
    Arguments {
        methods: if named.is_empty() {
            Method::ALL.to_vec()
        } else {
            named
        },
        trials: number_after("--trials").unwrap_or(TRIALS),
        jobs: number_after("--jobs")
            .or_else(|| std::thread::available_parallelism().ok().map(|n| n.get()))
            .unwrap_or(1)
            .max(1),
    }
}

/// The table's header lines.
fn header(trials: usize) -> String {
    let mut columns = String::from("| method |");
    for step in 1..=STEPS {
        columns += &format!(" {step} |");
    }
    columns += " trials to 1 mm (seeds 1 / 2 / 3) | to 0.1 mm | trials/s |";
    for (name, _) in EVENTS {
        columns += &format!(" recover after {name} |");
    }
    let event_trial = trials / 4;
    format!(
        "{trials} trials, events at trial {event_trial} (a run with one ends at trial {}: \
         \"never\" is not by then); distances in mm\n{columns}\n|---{}",
        trials.min(event_trial + RECOVERY_SPAN),
        "|---".repeat(STEPS + 3 + EVENTS.len()) + "|"
    )
}

fn main() {
    let Arguments {
        methods,
        trials,
        jobs,
    } = arguments();
    println!("{}", header(trials));
    let cells: Vec<Cell> = methods
        .iter()
        .flat_map(|&method| {
            SEEDS.iter().flat_map(move |&seed| {
                (0..RUNS_PER_SEED).map(move |run| Cell {
                    method,
                    seed,
                    event: run.checked_sub(1),
                })
            })
        })
        .collect();
    let runs_per_method = SEEDS.len() * RUNS_PER_SEED;
    let next = AtomicUsize::new(0);
    let (sender, receiver) = mpsc::channel();
    std::thread::scope(|scope| {
        for _ in 0..jobs.min(cells.len()) {
            let (sender, cells, next) = (sender.clone(), &cells, &next);
            scope.spawn(move || loop {
                let index = next.fetch_add(1, Ordering::Relaxed);
                let Some(cell) = cells.get(index) else { break };
                sender.send((index, run_cell(cell, trials))).expect("sent");
            });
        }
        drop(sender);
        let mut outcomes: Vec<Option<Outcome>> = cells.iter().map(|_| None).collect();
        let mut printed = 0;
        for (index, outcome) in receiver {
            outcomes[index] = Some(outcome);
            while printed < methods.len() {
                let runs = &mut outcomes[printed * runs_per_method..][..runs_per_method];
                if runs.iter().any(Option::is_none) {
                    break;
                }
                let runs: Vec<Outcome> = runs.iter_mut().filter_map(Option::take).collect();
                let seeds: Vec<SeedFigures> = runs
                    .chunks(RUNS_PER_SEED)
                    .map(SeedFigures::gather)
                    .collect();
                println!("{}", row(methods[printed], &seeds));
                printed += 1;
            }
        }
    });
}
