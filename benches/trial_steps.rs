//! The trial loop driven in pieces (begin, one feedback step at a time, finish) as the
//! Python `Testbed` drives it, in Rust alone: feedback steps and trials per second on the
//! kinematic simulator with the `ik` controller, and whole runs through `run_learner` with
//! a learner that never moves. The Rust side of docs/PYTHON.md's boundary table.
//!
//! `cargo bench --bench trial_steps` (20,000 trials per row, seed 1, configs/ik.conf).

use eyehand::experiment::{run_learner, Config, RunOptions};
use eyehand::learn::{IkLearner, LearnError, Learner, Observation, Query};
use eyehand::robot::ArmModel;
use nalgebra::Vector3;
use std::path::Path;
use std::time::Instant;

const TRIALS: usize = 20_000;
const SEED: u64 = 1;

/// A learner that proposes no move and learns nothing: the loop's own cost.
#[derive(Debug)]
struct StandStill;

impl Learner for StandStill {
    fn name(&self) -> &str {
        "standstill"
    }

    fn propose(&mut self, _query: &Query) -> Vector3<f64> {
        Vector3::zeros()
    }

    fn learn(&mut self, _path: &[Observation]) -> Result<(), LearnError> {
        Ok(())
    }
}

/// Feedback steps and seconds of `TRIALS` trials driven step by step with `learner`.
fn drive_in_pieces(config: &Config, learner: &mut dyn Learner) -> (usize, f64) {
    let setup = RunOptions::new(config.clone(), ".")
        .setup()
        .expect("the config and arm pass the run's checks");
    let mut trials = setup.trial_loop();
    let mut steps = 0;
    let started = Instant::now();
    for _ in 0..TRIALS {
        let Ok(mut here) = trials.begin_trial() else {
            continue;
        };
        loop {
            let report = trials
                .step_trial(&learner.propose(&here.query()))
                .expect("a finite move");
            steps += 1;
            match (report.end, report.reading) {
                (None, Ok(c)) => {
                    here = Observation {
                        theta_deg: report.theta_deg,
                        c,
                    }
                }
                _ => break,
            }
        }
        trials.finish_trial(learner).expect("learning succeeds");
    }
    (steps, started.elapsed().as_secs_f64())
}

fn main() {
    let config = Config::from_file(Path::new("configs/ik.conf")).expect("configs/ik.conf");
    println!("| Rust loop (kinematic, configs/ik.conf) | steps/s | trials/s |");
    println!("|---|---|---|");
    let mut ik = IkLearner::new(ArmModel::oscar6(), Default::default());
    for (label, learner) in [
        ("pieces, ik", &mut ik as &mut dyn Learner),
        ("pieces, no move", &mut StandStill),
    ] {
        let (steps, seconds) = drive_in_pieces(&config, learner);
        println!(
            "| {label} | {:.0} | {:.0} |",
            steps as f64 / seconds,
            TRIALS as f64 / seconds
        );
    }
    let data = tempfile::tempdir().expect("a temporary data folder");
    let options = RunOptions::new(
        Config {
            trials: TRIALS,
            seed: SEED,
            ..config
        },
        data.path(),
    );
    let summary = run_learner(&options, Box::new(StandStill))
        .expect("the run succeeds")
        .summary;
    println!(
        "| run_learner, no move (files written) | - | {:.0} |",
        summary.trials_per_second
    );
    println!("\n{TRIALS} trials a row, seed {SEED}");
}
