//! The `ik` reference controller on the kinematic simulator: trials per second and the
//! distance after steps 1..5, on the nominal robot, after link 2 is stretched by 10 cm and
//! after the camera is turned by 30° (both from trial 1). Prints a markdown table.
//!
//! `cargo bench --bench ik_reference` (10,000 trials per row, seed 1).

use eyehand::experiment::{run, Config, RunOptions};
use eyehand::learn::Method;

const TRIALS: usize = 10_000;
const SEED: u64 = 1;

fn main() {
    let data = tempfile::tempdir().expect("a temporary data folder");
    println!("| robot | trials/s | 1 | 2 | 3 | 4 | 5 | failures |");
    println!("|---|---|---|---|---|---|---|---|");
    for (label, event) in [
        ("nominal", None),
        ("link 2 +10 cm", Some("elongate:1:2:10")),
        ("camera turned 30°", Some("rotate:1:30")),
    ] {
        let mut config = Config::default_config();
        config.method = Method::Ik;
        config.trials = TRIALS;
        config.seed = SEED;
        let options = RunOptions {
            events: event
                .iter()
                .map(|e| e.parse().expect("a valid event"))
                .collect(),
            ..RunOptions::new(config, data.path())
        };
        let summary = run(&options).expect("the run succeeds").summary;
        let cells: Vec<String> = summary
            .mean_distance_mm
            .iter()
            .map(|d| d.map_or("-".into(), |d| format!("{d:.3}")))
            .collect();
        println!(
            "| {label} | {:.0} | {} | {} |",
            summary.trials_per_second,
            cells.join(" | "),
            summary.failures
        );
    }
    println!("\nmean distance (mm) after each feedback step over the last 1,000 of {TRIALS} trials, seed {SEED}");
}
