//! Continuous against step servoing on the dynamic simulator, measured: lin5 and ik, the
//! camera at 30 frames per second with 0 and 50 ms of latency, beside the study's timing (a
//! frame as each move settles). Prints the markdown table of docs/SENSING.md.
//!
//! `cargo bench --bench servo [-- TRIALS]` (default 5,000 trials per run, seed 1, the
//! default config otherwise). Every run stops a trial at the first frame within ε
//! (`min_feedback_steps` 1), so its seconds are the time to ε; step runs have
//! `feedback_steps` 10 moves, continuous runs 150 frames (5 s). Figures are over the
//! summary's window (the last tenth of the trials).

use eyehand::control::ServoMode;
mod common;

use common::run_in_process;
use eyehand::experiment::{Config, RunSummary, SimKind};
use eyehand::learn::Method;

const TRIALS: usize = 5_000;
const SEED: u64 = 1;
const FPS: f64 = 30.0;

/// One run's servoing: the mode and the camera's clock.
#[derive(Debug, Clone, Copy)]
struct Timing {
    servo: ServoMode,
    fps: f64,
    latency_ms: f64,
}

fn config(method: Method, timing: Timing, trials: usize) -> Config {
    let mut config = Config::default_config();
    config.method = method;
    config.sim = SimKind::Dynamic;
    config.trials = trials;
    config.seed = SEED;
    config.min_feedback_steps = 1;
    config.servo_mode = timing.servo;
    config.camera_fps = timing.fps;
    config.camera_latency_ms = timing.latency_ms;
    config.feedback_steps = match timing.servo {
        ServoMode::Step => 10,
        ServoMode::Continuous => 150,
    };
    config
}

fn figure(value: Option<f64>, digits: usize) -> String {
    value.map_or("-".into(), |v| format!("{v:.digits$}"))
}

fn row(method: Method, timing: Timing, summary: &RunSummary) {
    println!(
        "| {} | {} | {} | {} | {} of {} | {} | {} | {} | {} | {:.0} |",
        method.name(),
        timing.servo,
        timing.fps,
        timing.latency_ms,
        summary.reached_epsilon,
        summary.window,
        figure(summary.mean_seconds_to_epsilon, 3),
        figure(summary.mean_final_distance_mm, 4),
        figure(summary.median_final_distance_mm, 4),
        summary.failures,
        summary.trials_per_second,
    );
}

fn main() {
    let trials = std::env::args()
        .skip(1)
        .find_map(|a| a.parse().ok())
        .unwrap_or(TRIALS);
    println!(
        "| method | servo | fps | latency ms | within ε | s to ε | final mean mm | final median mm | failures | trials/s |"
    );
    println!("|---|---|---|---|---|---|---|---|---|---|");
    let mut verdicts = Vec::new();
    for method in [Method::Ik, Method::Lin5] {
        let study = Timing {
            servo: ServoMode::Step,
            fps: 0.0,
            latency_ms: 0.0,
        };
        row(
            method,
            study,
            &run_in_process(config(method, study, trials)),
        );
        for latency_ms in [0.0, 50.0] {
            let mut seconds = [None; 2];
            for (k, servo) in [ServoMode::Step, ServoMode::Continuous]
                .into_iter()
                .enumerate()
            {
                let timing = Timing {
                    servo,
                    fps: FPS,
                    latency_ms,
                };
                let summary = run_in_process(config(method, timing, trials));
                row(method, timing, &summary);
                seconds[k] = summary.mean_seconds_to_epsilon;
            }
            if let [Some(step), Some(continuous)] = seconds {
                let saved = 100.0 * (1.0 - continuous / step);
                let verdict = if saved >= 30.0 { "met" } else { "missed" };
                verdicts.push(format!(
                    "{} at {latency_ms} ms: continuous takes {saved:.0}% less time to ε than step ({verdict})",
                    method.name()
                ));
            }
        }
    }
    println!();
    for verdict in verdicts {
        println!("- {verdict}");
    }
}
