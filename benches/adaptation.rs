//! Recovery from a changed robot: lin5 on the kinematic simulator, seeds 1–3, 4,500 trials,
//! one event before trial 1,500, for the study's merges (`merge_strategy thesis`) and for
//! change detection, beside the fixed-model `ik` controller. Prints a markdown table per
//! scenario: the 4-step mean over trials 1,000–1,500 (before), trials after the event until
//! the 4-step mean over a sliding window of 100 trials is back within 2× that level (or
//! "never"), the detection delay (trials from the event to the first alarm), and the 4-step
//! mean over the last 500 trials.
//!
//! `cargo bench --bench adaptation`

mod common;

use common::run_cli;
use std::path::Path;

const TRIALS: usize = 4500;
const EVENT_TRIAL: usize = 1500;
const SEEDS: [u64; 3] = [1, 2, 3];
const SCENARIOS: [(&str, &str); 5] = [
    ("camera 90°", "rotate:1500:90"),
    ("camera 30°", "rotate:1500:30"),
    ("link 1 +10 cm", "elongate:1500:1:10"),
    ("link 2 +10 cm", "elongate:1500:2:10"),
    ("link 2 −10 cm", "elongate:1500:2:-10"),
];

/// The 4-step distance of every trial (NaN where the trial had no 4th step).
fn four_step(folder: &Path) -> Vec<f64> {
    let mut by_trial = vec![f64::NAN; TRIALS + 1];
    let text = std::fs::read_to_string(folder.join("4step")).expect("4step");
    for line in text.lines() {
        let mut fields = line.split(' ');
        let trial: usize = fields.next().and_then(|t| t.parse().ok()).expect("a trial");
        by_trial[trial] = fields
            .next()
            .and_then(|d| d.parse().ok())
            .expect("a distance");
    }
    by_trial
}

fn mean(values: &[f64]) -> f64 {
    let finite: Vec<f64> = values.iter().copied().filter(|v| v.is_finite()).collect();
    finite.iter().sum::<f64>() / finite.len().max(1) as f64
}

struct Recovery {
    before: f64,
    recovered_after: Option<usize>,
    detected_after: Option<usize>,
    last: f64,
}

fn recovery(folder: &Path) -> Recovery {
    let d = four_step(folder);
    let before = mean(&d[1000..=EVENT_TRIAL - 1]);
    let recovered_after = (EVENT_TRIAL + 100..=TRIALS)
        .find(|&t| mean(&d[t - 99..=t]) <= 2.0 * before)
        .map(|t| t - EVENT_TRIAL);
    let changes = std::fs::read_to_string(folder.join("changes")).unwrap_or_default();
    let detected_after = changes
        .lines()
        .filter_map(|l| l.split(' ').next()?.parse::<usize>().ok())
        .find(|&t| t >= EVENT_TRIAL)
        .map(|t| t - EVENT_TRIAL);
    Recovery {
        before,
        recovered_after,
        detected_after,
        last: mean(&d[TRIALS - 499..=TRIALS]),
    }
}

fn main() {
    let data = tempfile::tempdir().expect("a temporary data folder");
    let lin5 = concat!(env!("CARGO_MANIFEST_DIR"), "/configs/lin5.conf");
    let ik = concat!(env!("CARGO_MANIFEST_DIR"), "/configs/ik.conf");
    let trials = TRIALS.to_string();
    for (name, event) in SCENARIOS {
        println!("\n#### {name} at trial {EVENT_TRIAL}\n");
        println!("| learner | seed | 4-step before (mm) | recovered after (trials) | detected after (trials) | 4-step last 500 (mm) |");
        println!("|---|---|---|---|---|---|");
        for (label, config, strategy) in [
            ("lin5 thesis", lin5, "thesis"),
            ("lin5 change_detection", lin5, "change_detection"),
            ("ik", ik, "thesis"),
        ] {
            for seed in SEEDS {
                let seed_text = seed.to_string();
                let set = format!("merge_strategy={strategy}");
                let args = [
                    "--config", config, "--trials", &trials, "--seed", &seed_text, "--event",
                    event, "--set", &set,
                ];
                let r = recovery(&run_cli(data.path(), &args).folder);
                let trials_or =
                    |v: Option<usize>, none: &str| v.map_or(none.to_string(), |t| t.to_string());
                println!(
                    "| {label} | {seed} | {:.4} | {} | {} | {:.4} |",
                    r.before,
                    trials_or(r.recovered_after, "never"),
                    trials_or(r.detected_after, "-"),
                    r.last
                );
            }
        }
    }
}
