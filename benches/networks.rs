//! The network learners on the kinematic simulator, seed 1, each as the study ran it:
//! `nnw` over 2,000 trials, `ffn` (25 hidden units) and `kohonen` over 20,000. Prints a
//! markdown table: mean distance (mm) after steps 1..5 and 8 over the last 10% of the
//! trials, trials per second, peak memory.
//!
//! `cargo bench --bench networks` (all rows, about 12 minutes on one core), or name rows:
//! `cargo bench --bench networks -- ffn kohonen`.

mod common;

use common::{mm, run_cli};

const ROWS: [(&str, &str, &str); 3] = [
    ("nnw", "nnw.conf", "2000"),
    ("ffn", "ffn.conf", "20000"),
    ("kohonen", "kohonen.conf", "20000"),
];

fn main() {
    let wanted: Vec<String> = std::env::args()
        .skip(1)
        .filter(|a| !a.starts_with('-'))
        .collect();
    let data = tempfile::tempdir().expect("a temporary data folder");
    println!("| method | trials | 1 | 2 | 3 | 4 | 5 | 8 | trials/s | peak MB | nodes |");
    println!("|---|---|---|---|---|---|---|---|---|---|---|");
    for (method, config, trials) in ROWS {
        if !wanted.is_empty() && !wanted.iter().any(|w| w == method) {
            continue;
        }
        let config = format!("{}/configs/{config}", env!("CARGO_MANIFEST_DIR"));
        let run = run_cli(
            data.path(),
            &["--config", &config, "--trials", trials, "--seed", "1"],
        );
        let s = &run.summary;
        let steps: Vec<String> = s.mean_distance_mm.iter().map(|d| mm(*d)).collect();
        let eighth = s.mean_distance_by_step_mm.get(7).copied().flatten();
        println!(
            "| {method} | {trials} | {} | {} | {:.1} | {:.0} | {} |",
            steps.join(" | "),
            mm(eighth),
            s.trials_per_second,
            s.peak_rss_kb as f64 / 1024.0,
            s.nodes
        );
    }
    println!(
        "\nmean distance (mm) after each feedback step over the last 10% of the trials, seed 1"
    );
}
