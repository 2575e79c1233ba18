//! Records the pattern stream LWPR learns from in a run: the adjusted 5-input patterns
//! (θ2, θ3, cx*, cy*, cz*) → Δθ in the order `Lwpr::learn` trains them, written to stdout
//! one per line (to 6 significant digits, which keeps a fixture small: a replay reads the
//! stream as written) after a header with the run's input boundaries and `norm_out`.
//! `tools/lwpr_reference.sh` feeds the stream to the reference LWPR library to make the
//! fixture of the replay test in `src/learn/lwpr/reference_replay.rs`.
//!
//! ```sh
//! cargo run --release --example lwpr_patterns -- 120 1 > stream.txt   # trials, seed
//! cargo run --release --example lwpr_patterns -- 120 1 init_D=200 w_gen=0.2
//! ```

use eyehand::experiment::setup::lwpr_settings;
use eyehand::learn::{Lwpr, ModelEvent};
use eyehand::prelude::*;
use nalgebra::Vector3;
use std::path::Path;

/// The `lwpr` learner, printing every pattern it trains.
#[derive(Debug)]
struct Recording {
    inner: Lwpr,
    patterns: PatternSettings,
}

impl Learner for Recording {
    fn name(&self) -> &str {
        self.inner.name()
    }

    fn propose(&mut self, query: &Query) -> Vector3<f64> {
        self.inner.propose(query)
    }

    fn learn(&mut self, path: &[Observation]) -> Result<(), LearnError> {
        for (from, to) in self.patterns.pairs(path) {
            let pattern = adjusted_pattern(from, to);
            let values: Vec<f64> = pattern
                .input
                .iter()
                .chain(&pattern.target)
                .copied()
                .collect();
            // Lwpr skips a pattern with a value that is not finite; so does the stream.
            if values.iter().all(|v| v.is_finite()) {
                let line: Vec<String> = values.iter().map(|v| format!("{v:.5e}")).collect();
                println!("p {}", line.join(" "));
            }
        }
        self.inner.learn(path)
    }

    fn stats(&self) -> LearnerStats {
        self.inner.stats()
    }

    fn start_trial(&mut self, trial: usize) {
        self.inner.start_trial(trial);
    }

    fn drain_events(&mut self, sink: &mut Vec<ModelEvent>) {
        self.inner.drain_events(sink);
    }
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let number =
        |i: usize, default: u64| args.get(i).and_then(|a| a.parse().ok()).unwrap_or(default);
    let mut config = Config::default_config();
    config.method = eyehand::learn::Method::Lwpr;
    config.trials = number(0, 120) as usize;
    config.seed = number(1, 1);
    for entry in args.iter().skip(2) {
        let (name, value) = entry.split_once('=').expect("entries are name=value");
        config.set(name, value).expect("a valid entry");
    }
    let bounds = input_bounds::<5>(&config);
    println!(
        "# lwpr pattern stream: {} trials, seed {}",
        config.trials, config.seed
    );
    let bounds_text: Vec<String> = bounds.iter().map(|(l, h)| format!("{l} {h}")).collect();
    println!("bounds {}", bounds_text.join(" "));
    println!("norm_out {}", config.norm_out);
    let learner = Recording {
        inner: Lwpr::new(lwpr_settings(&config), bounds),
        patterns: PatternSettings {
            minimal_joint_move: config.minimal_joint_move,
        },
    };
    let data = tempfile::tempdir().expect("a temporary folder");
    let options = RunOptions::new(config, Path::new(data.path()));
    run_learner(&options, Box::new(learner)).expect("the run runs");
}
