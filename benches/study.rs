//! Every result of the study's chapters 3 and 5 beside ours: each file of `configs/study/`
//! (the study's appendix A.2 listing with the entries that result changes) is run for
//! seeds 1–3 on the kinematic OSCAR-6, and a markdown table prints, per result, the
//! study's figure from its text, ours as mean ± s.d. over the three seeds, and their ratio.
//! Where the study gives no number the row says "shape only" and shows ours beside what
//! the study says happened.
//!
//! `cargo bench --bench study`; `cargo bench --bench study -- fig5.5 fig5.14` runs only the
//! files whose names contain one of the words.

mod common;

use common::Finished;
use std::path::{Path, PathBuf};
use std::process::Command;

const SEEDS: [u64; 3] = [1, 2, 3];

/// What a row measures in one run.
#[derive(Clone, Copy)]
enum Measure {
    /// Mean distance (mm) after `step` steps over trials `from..to` (steps 1–5).
    Distance { step: usize, from: usize, to: usize },
    /// Mean distance (mm) after `step` steps over the run's last trials (`summary.json`).
    FinalDistance { step: usize },
    /// Nodes (approximators) at the end.
    Nodes,
    /// Bins at the end.
    Bins,
    /// Trials an hour over the whole run.
    TrialsPerHour,
    /// The trial of the first root merge (none: the run's trials + 1).
    FirstRootCut,
    /// 1 when the run learned, 0 when it ended with "nothing was learned".
    Learned,
}

/// One row: what is measured, the study's figure (`None`: shape only) and what the study
/// says.
struct Row {
    measure: Measure,
    label: &'static str,
    study: Option<f64>,
    says: &'static str,
}

const fn row(measure: Measure, label: &'static str, study: Option<f64>, says: &'static str) -> Row {
    Row {
        measure,
        label,
        study,
        says,
    }
}

const fn d(step: usize, from: usize, to: usize) -> Measure {
    Measure::Distance { step, from, to }
}

/// The rows of the runs with an event at trial 1,500: the level before, right after and at
/// the end, after steps 1, 3 and 4.
const EVENT_ROWS: [(Measure, &str); 7] = [
    (d(4, 1000, 1500), "4-step mm, trials 1000-1499"),
    (d(4, 1500, 1600), "4-step mm, trials 1500-1599"),
    (d(4, 2500, 3001), "4-step mm, trials 2500-3000"),
    (d(3, 2500, 3001), "3-step mm, trials 2500-3000"),
    (d(1, 2500, 3001), "1-step mm, trials 2500-3000"),
    (Measure::FirstRootCut, "first root cut (trial)"),
    (Measure::Learned, "runs that learned (share)"),
];

/// The results: configs/study/ file, the study's rows.
fn results() -> Vec<(&'static str, Vec<Row>)> {
    let long = |four: f64, one: f64, nodes: f64, speed: Option<f64>| {
        let mut rows = vec![
            row(
                d(4, 49_000, 50_001),
                "4-step mm, last 1,000 trials",
                Some(four),
                "about 70 µm",
            ),
            row(
                d(1, 49_000, 50_001),
                "1-step mm, last 1,000 trials",
                Some(one),
                "",
            ),
            row(Measure::Nodes, "approximators at 50,000", Some(nodes), ""),
        ];
        if let Some(speed) = speed {
            rows.push(row(
                Measure::TrialsPerHour,
                "trials an hour",
                Some(speed),
                "SPARCstation 20/51",
            ));
        }
        rows
    };
    let shape = |says: &'static str| -> Vec<Row> {
        EVENT_ROWS
            .iter()
            .map(|&(m, label)| row(m, label, None, says))
            .collect()
    };
    let mut turn =
        shape("tree thrown away at 1,504 (threshold 0.15); the last 1,500 trials like the first");
    turn[5] = row(
        Measure::FirstRootCut,
        "first root cut (trial)",
        Some(1504.0),
        "",
    );
    let shaped_long = |says: &'static str| -> Vec<Row> {
        [
            (d(4, 49_000, 50_001), "4-step mm, last 1,000 trials"),
            (d(1, 49_000, 50_001), "1-step mm, last 1,000 trials"),
            (Measure::Nodes, "approximators at 50,000"),
        ]
        .into_iter()
        .map(|(m, label)| row(m, label, None, says))
        .collect()
    };
    vec![
        (
            "fig3.1_ffn",
            vec![
                row(
                    Measure::FinalDistance { step: 8 },
                    "8-step mm, last trials",
                    Some(4.0),
                    "about 4 mm",
                ),
                row(
                    d(1, 1500, 2001),
                    "1-step mm, trials 1500-2000",
                    None,
                    "shape only",
                ),
            ],
        ),
        (
            "fig3.1_ffn_45",
            vec![row(
                Measure::FinalDistance { step: 8 },
                "8-step mm, last trials",
                Some(4.0),
                "no better than 25 units",
            )],
        ),
        (
            "fig3.2_kohonen",
            vec![
                row(
                    d(2, 19_000, 20_001),
                    "2-step mm, last 1,000 trials",
                    Some(5.0),
                    "about 5 mm, its best",
                ),
                row(
                    d(1, 19_000, 20_001),
                    "1-step mm, last 1,000 trials",
                    None,
                    "shape only",
                ),
            ],
        ),
        (
            "sec3.2.3_nnw",
            vec![
                row(
                    d(3, 1100, 1301),
                    "3-step mm, trials 1100-1300",
                    Some(1.0),
                    "1 mm after ~1,200 trials",
                ),
                row(
                    d(1, 1900, 2001),
                    "1-step mm, trials 1900-2000",
                    Some(30.0),
                    "30 mm at 2,000",
                ),
                row(
                    Measure::Nodes,
                    "networks at 2,000",
                    Some(1800.0),
                    "about 1,800",
                ),
                row(Measure::Bins, "bins at 2,000", Some(8000.0), "about 8,000"),
            ],
        ),
        (
            "fig5.1_lin5_split_1e-4",
            long(0.070, 24.0, 1960.0, Some(41_400.0)),
        ),
        ("fig5.2_lin5_split_1e-5", long(0.070, 15.0, 2427.0, None)),
        ("fig5.5_lin5_camera_90", turn),
        (
            "fig5.6_lin5_camera_30",
            shape("no recovery within 1,500 trials; few relative merges"),
        ),
        ("fig5.7_lin5_link1_plus10cm", shape("handled well")),
        (
            "fig5.8_lin5_link2_plus10cm",
            shape("steps 3 and 4 crippled, no recovery in 1,500 trials"),
        ),
        (
            "fig5.9_lin5_link2_minus10cm",
            shape("recovers almost entirely"),
        ),
        (
            "fig5.10_lin8_split_1e-4",
            shaped_long("worse than lin5 at 1e-4"),
        ),
        (
            "fig5.11_lin8_split_1e-5",
            shaped_long("comparable to lin5 at 1e-4"),
        ),
        ("fig5.14_lin8_camera_90", shape("as lin5's (fig. 5.5)")),
        ("fig5.15_lin8_camera_30", shape("as lin5's (fig. 5.6)")),
        ("fig5.16_lin8_link1_plus10cm", shape("as lin5's (fig. 5.7)")),
        ("fig5.17_lin8_link2_plus10cm", shape("as lin5's (fig. 5.8)")),
        (
            "fig5.18_lin8_link2_minus10cm",
            shape("as lin5's (fig. 5.9)"),
        ),
    ]
}

/// The mean distance after `step` steps over trials `from..to` of a run folder.
fn distance(folder: &Path, step: usize, from: usize, to: usize) -> f64 {
    let text = std::fs::read_to_string(folder.join(format!("{step}step"))).expect("a step file");
    let values: Vec<f64> = text
        .lines()
        .filter_map(|l| {
            let mut fields = l.split_whitespace();
            let trial: usize = fields.next()?.parse().ok()?;
            let mm: f64 = fields.next()?.parse().ok()?;
            (from..to).contains(&trial).then_some(mm)
        })
        .collect();
    values.iter().sum::<f64>() / values.len().max(1) as f64
}

/// The trial of the run's first root merge, or its trials + 1.
fn first_root_cut(folder: &Path, trials: usize) -> f64 {
    let text = std::fs::read_to_string(folder.join("merges")).unwrap_or_default();
    text.lines()
        .map(|l| l.split_whitespace().collect::<Vec<_>>())
        .find(|fields| fields.get(2) == Some(&"0"))
        .and_then(|fields| fields[0].parse().ok())
        .unwrap_or(trials as f64 + 1.0)
}

/// Runs `eyehand run --config FILE --seed SEED` into `data` and reads its summary; a run
/// that ended with "nothing was learned" (exit 1, its files complete) counts as well.
fn run_figure(data: &Path, file: &Path, seed: u64) -> Finished {
    let output = Command::new(env!("CARGO_BIN_EXE_eyehand"))
        .arg("run")
        .arg("--config")
        .arg(file)
        .args(["--seed", &seed.to_string(), "--quiet", "--no-plot"])
        .arg("--data")
        .arg(data)
        .output()
        .expect("eyehand runs");
    let folder = PathBuf::from(String::from_utf8_lossy(&output.stdout).trim());
    let json = std::fs::read_to_string(folder.join("summary.json")).unwrap_or_else(|e| {
        panic!(
            "{}: {e}: {}",
            file.display(),
            String::from_utf8_lossy(&output.stderr)
        )
    });
    Finished {
        summary: serde_json::from_str(&json).expect("a valid summary"),
        folder,
    }
}

fn measured(measure: Measure, run: &Finished) -> f64 {
    let summary = &run.summary;
    match measure {
        Measure::Distance { step, from, to } => distance(&run.folder, step, from, to),
        Measure::FinalDistance { step } => summary
            .mean_distance_by_step_mm
            .get(step - 1)
            .copied()
            .flatten()
            .unwrap_or(f64::NAN),
        Measure::Nodes => summary.nodes as f64,
        Measure::Bins => summary.bins as f64,
        Measure::TrialsPerHour => summary.trials_per_second * 3600.0,
        Measure::FirstRootCut => first_root_cut(&run.folder, summary.trials),
        Measure::Learned => f64::from(u8::from(summary.learned)),
    }
}

fn mean_sd(values: &[f64]) -> (f64, f64) {
    let n = values.len() as f64;
    let mean = values.iter().sum::<f64>() / n;
    let var = values.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / (n - 1.0).max(1.0);
    (mean, var.sqrt())
}

/// A figure in the table: 4 significant digits.
fn figure(v: f64) -> String {
    match v.abs() {
        a if a >= 1000.0 => format!("{v:.0}"),
        a if a >= 1.0 => format!("{v:.2}"),
        _ => format!("{v:.4}"),
    }
}

fn main() {
    let words: Vec<String> = std::env::args()
        .skip(1)
        .filter(|a| !a.starts_with("--"))
        .collect();
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("configs/study");
    let data = tempfile::tempdir().expect("a data folder");
    println!("| result | measure | study | ours (seeds 1-3) | ours / study | the study says |");
    println!("|---|---|---|---|---|---|");
    for (name, rows) in results() {
        if !words.is_empty() && !words.iter().any(|w| name.contains(w.as_str())) {
            continue;
        }
        let file = root.join(format!("{name}.conf"));
        let runs: Vec<Finished> = SEEDS
            .iter()
            .map(|&seed| run_figure(data.path(), &file, seed))
            .collect();
        for row in rows {
            let values: Vec<f64> = runs.iter().map(|r| measured(row.measure, r)).collect();
            let (mean, sd) = mean_sd(&values);
            let (study, ratio) = match row.study {
                Some(s) => (figure(s), format!("{:.2}", mean / s)),
                None => ("shape only".into(), "-".into()),
            };
            println!(
                "| {name} | {} | {study} | {} ± {} | {ratio} | {} |",
                row.label,
                figure(mean),
                figure(sd),
                row.says
            );
        }
    }
}
