//! The network learners on the kinematic simulator, seed 1, each as the study ran it:
//! `nnw` over 2,000 trials, `ffn` (25 hidden units) and `kohonen` over 20,000. Prints a
//! markdown table: mean distance (mm) after steps 1..5 and 8 over the last 10% of the
//! trials, trials per second, peak memory.
//!
//! A second table runs `nnw` over seeds 1–40 (one seed's 3-step distance moves by ±0.1 mm
//! with any change of its trajectory, so precision is judged by the seeds' mean).
//!
//! `cargo bench --bench networks` (all rows, about 6 minutes on a quiet core), or name rows:
//! `cargo bench --bench networks -- ffn kohonen nnw-seeds`.

mod common;

use common::{mm, run_cli};
use std::path::Path;

/// The seeds of the `nnw-seeds` table.
const NNW_SEEDS: std::ops::RangeInclusive<u64> = 1..=40;

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
    let asked = |row: &str| wanted.is_empty() || wanted.iter().any(|w| w == row);
    let data = tempfile::tempdir().expect("a temporary data folder");
    let rows: Vec<_> = ROWS.iter().filter(|(method, ..)| asked(method)).collect();
    if !rows.is_empty() {
        println!("| method | trials | 1 | 2 | 3 | 4 | 5 | 8 | trials/s | peak MB | nodes |");
        println!("|---|---|---|---|---|---|---|---|---|---|---|");
    }
    for &(method, config, trials) in rows.iter().copied() {
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
    if !rows.is_empty() {
        println!(
            "\nmean distance (mm) after each feedback step over the last 10% of the trials, \
             seed 1"
        );
    }
    if asked("nnw-seeds") {
        nnw_over_seeds(data.path());
    }
}

/// Mean and standard deviation of `values`.
fn mean_sd(values: &[f64]) -> (f64, f64) {
    let n = values.len() as f64;
    let mean = values.iter().sum::<f64>() / n;
    let var = values.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / (n - 1.0).max(1.0);
    (mean, var.sqrt())
}

/// `nnw` over 2,000 trials of each of [`NNW_SEEDS`]: the seeds' mean ± standard deviation
/// of the mean distance after steps 1, 3 and 5, of the failures and of trials/s.
fn nnw_over_seeds(data: &Path) {
    let config = format!("{}/configs/nnw.conf", env!("CARGO_MANIFEST_DIR"));
    let mut columns: [Vec<f64>; 5] = Default::default();
    for seed in NNW_SEEDS {
        let seed = seed.to_string();
        let run = run_cli(
            data,
            &["--config", &config, "--trials", "2000", "--seed", &seed],
        );
        let s = &run.summary;
        // (A method's data folder holds 36 runs: each is dropped once read.)
        std::fs::remove_dir_all(&run.folder).expect("the run's folder is removed");
        let step = |i: usize| s.mean_distance_mm[i].expect("every run takes five steps");
        let figures = [
            step(0),
            step(2),
            step(4),
            s.failures as f64,
            s.trials_per_second,
        ];
        columns.iter_mut().zip(figures).for_each(|(c, f)| c.push(f));
    }
    // (Distances to 4 decimals, failures and trials/s to 1.)
    let decimals = [4, 4, 4, 1, 1];
    let cells: Vec<String> = columns
        .iter()
        .zip(decimals)
        .map(|(c, d)| {
            let (mean, sd) = mean_sd(c);
            format!("{mean:.d$} ± {sd:.d$}")
        })
        .collect();
    println!("\n| method | seeds | 1 | 3 | 5 | failures | trials/s |");
    println!("|---|---|---|---|---|---|---|");
    let (first, last) = (NNW_SEEDS.start(), NNW_SEEDS.end());
    println!("| nnw | {first}–{last} | {} |", cells.join(" | "));
    println!(
        "\nmean ± standard deviation over the seeds of the mean distance (mm) after steps 1, 3 \
         and 5 over each run's last 200 trials, of its failures and of its trials/s"
    );
}
