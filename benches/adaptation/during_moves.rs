//! Item 2 of issue 30 in the adaptation bench: lin5 with and without `learn_during_moves`
//! (`camera_fps` 30, `move_frames_learned` at its default), the same seeds, at
//! `robot_speed` 10 and 1, on the kinematic simulator (20,000 trials) and the dynamic one
//! (2,000 trials: its moves cost physics steps in proportion to their time). Trials to a
//! 4-step mean are counted on the running mean of the last 500 trials
//! ([`FourStepTrace::first_within`]), so 1 mm is reached as soon as the window fills.

use crate::common::run_cli;
use eyehand::experiment::FourStepTrace;

/// The label that picks this section on the command line.
pub const LABEL: &str = "learn_during_moves";
/// Simulator, robot_speed (°/s) and trials of each cell.
const CELLS: [(&str, &str, usize); 4] = [
    ("kinematic", "10", 20_000),
    ("kinematic", "1", 20_000),
    ("dynamic", "10", 2_000),
    ("dynamic", "1", 2_000),
];
/// The 4-step means whose first trial is counted (mm).
const GOALS: [f64; 3] = [1.0, 0.1, 0.05];
/// Trials in the running mean that decides a goal.
const WINDOW: usize = 500;

/// Prints the table, a row per cell, setting and seed.
pub fn print(seeds: &[u64]) {
    println!("| simulator | robot_speed (°/s) | learn_during_moves | seed | trials to 1 / 0.1 / 0.05 mm (4-step mean) | 4-step mean at the end (mm) | stored patterns per trial | trials/s |");
    println!("|---|---|---|---|---|---|---|---|");
    for (sim, speed, trials) in CELLS {
        for learn in ["0", "1"] {
            for &seed in seeds {
                println!(
                    "| {sim} | {speed} | {learn} | {seed} | {} |",
                    cells(sim, speed, trials, learn, seed)
                );
            }
        }
    }
}

/// The figures of one run, joined as table cells.
fn cells(sim: &str, speed: &str, trials: usize, learn: &str, seed: u64) -> String {
    let data = tempfile::tempdir().expect("a temporary data folder");
    let fps = if learn == "1" {
        "camera_fps=30"
    } else {
        "camera_fps=0"
    };
    let (trials, seed) = (trials.to_string(), seed.to_string());
    let speed = format!("robot_speed={speed}");
    let learn = format!("learn_during_moves={learn}");
    let args = [
        "--sim", sim, "--trials", &trials, "--seed", &seed, "--set", &speed, "--set", &learn,
        "--set", fps,
    ];
    let finished = run_cli(data.path(), &args);
    let trace = FourStepTrace::read(&finished.folder).expect("4step");
    let reached: Vec<String> = GOALS
        .iter()
        .map(|&goal| {
            trace
                .first_within(goal, WINDOW)
                .map_or("-".into(), thousands)
        })
        .collect();
    let summary = &finished.summary;
    let end = summary.mean_distance_mm[3].unwrap_or(f64::NAN);
    let per_trial = summary.patterns as f64 / summary.trials as f64;
    format!(
        "{} | {end:.4} | {per_trial:.1} | {}",
        reached.join(" / "),
        thousands(summary.trials_per_second.round() as usize)
    )
}

/// `n` with a comma between thousands.
fn thousands(n: usize) -> String {
    let digits = n.to_string();
    let mut out = String::new();
    for (i, d) in digits.chars().enumerate() {
        if i > 0 && (digits.len() - i) % 3 == 0 {
            out.push(',');
        }
        out.push(d);
    }
    out
}
