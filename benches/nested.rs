//! The Nested Perceptron on the kinematic simulator as the study ran it — `lin5` (input
//! adjustment) and `lin8` (without) — 50,000 trials, seed 1, their shipped configs with
//! split_error 1e-4 and 1e-5. Prints a markdown table: mean distance after steps 1..5 over
//! the last 1,000 trials, trials per second overall and over the first and last 10,000
//! trials, peak memory, nodes, bins, patterns.
//!
//! `cargo bench --bench nested`

mod common;

use common::{mm, rate_between, run_cli};

fn main() {
    let data = tempfile::tempdir().expect("a temporary data folder");
    println!("| method | split_error | 1 | 2 | 3 | 4 | 5 | trials/s | first 10k | last 10k | peak MB | nodes | bins | patterns |");
    println!("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|");
    for (method, split_error) in [
        ("lin5", "1e-4"),
        ("lin5", "1e-5"),
        ("lin8", "1e-4"),
        ("lin8", "1e-5"),
    ] {
        let config = format!("{}/configs/{method}.conf", env!("CARGO_MANIFEST_DIR"));
        let set = format!("split_error={split_error}");
        let run = run_cli(
            data.path(),
            &[
                "--config", &config, "--trials", "50000", "--seed", "1", "--set", &set,
            ],
        );
        let s = &run.summary;
        let steps: Vec<String> = s.mean_distance_mm.iter().map(|d| mm(*d)).collect();
        println!(
            "| {method} | {split_error} | {} | {:.0} | {:.0} | {:.0} | {:.0} | {} | {} | {} |",
            steps.join(" | "),
            s.trials_per_second,
            rate_between(&run.folder, 0, 10_000),
            rate_between(&run.folder, 40_000, 50_000),
            s.peak_rss_kb as f64 / 1024.0,
            s.nodes,
            s.bins,
            s.patterns
        );
    }
    println!("\nmean distance (mm) after each feedback step over the last 1,000 of 50,000 trials, seed 1");
}
