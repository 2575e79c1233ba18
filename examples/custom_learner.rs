//! A learner written outside the crate, run through the same trial loop, run folder, data
//! files and summary as the built-in ones.
//!
//! The learner is a nearest-neighbour table: it keeps the latest adjusted learning
//! patterns (θ2, θ3, c*) → Δθ, as lin5 sees them, and answers a query with the mean move of
//! the `K` stored patterns nearest to it (inputs scaled by the config's boundaries).
//!
//! ```sh
//! cargo run --release --example custom_learner -- 2000   # trials; prints the run folder
//! ```

use eyehand::prelude::*;
use nalgebra::{SVector, Vector3};

/// Patterns averaged per answer.
const K: usize = 4;

/// A table of the latest patterns; the `K` nearest answer a query.
#[derive(Debug)]
struct NearestNeighbours {
    /// Each input's (low, high), to scale the inputs alike.
    bounds: [(f64, f64); 5],
    /// The stored patterns, inputs already scaled; the oldest is overwritten when full.
    table: Vec<Pattern5>,
    capacity: usize,
    next: usize,
    patterns: PatternSettings,
}

impl NearestNeighbours {
    fn new(config: &Config, capacity: usize) -> NearestNeighbours {
        NearestNeighbours {
            bounds: input_bounds(config),
            table: Vec::with_capacity(capacity),
            capacity,
            next: 0,
            patterns: PatternSettings {
                minimal_joint_move: config.minimal_joint_move,
            },
        }
    }

    /// `x` with every input mapped onto [0, 1] by the bounds.
    fn scaled(&self, x: &SVector<f64, 5>) -> SVector<f64, 5> {
        SVector::from_fn(|i, _| (x[i] - self.bounds[i].0) / (self.bounds[i].1 - self.bounds[i].0))
    }
}

impl Learner for NearestNeighbours {
    fn name(&self) -> &str {
        "knn"
    }

    fn propose(&mut self, query: &Query) -> Vector3<f64> {
        let x = self.scaled(&query.five_inputs());
        let mut nearest: [(f64, Vector3<f64>); K] = [(f64::INFINITY, Vector3::zeros()); K];
        for pattern in &self.table {
            let d = (pattern.input - x).norm_squared();
            if d < nearest[K - 1].0 {
                nearest[K - 1] = (d, pattern.target);
                nearest.sort_by(|a, b| a.0.total_cmp(&b.0));
            }
        }
        let found: Vec<_> = nearest.iter().filter(|(d, _)| d.is_finite()).collect();
        if found.is_empty() {
            return Vector3::zeros();
        }
        let sum: Vector3<f64> = found.iter().map(|(_, t)| t).sum();
        sum / found.len() as f64
    }

    fn learn(&mut self, path: &[Observation]) -> Result<(), LearnError> {
        for (from, to) in self.patterns.pairs(path) {
            let pattern = adjusted_pattern(from, to);
            let stored = Pattern5 {
                input: self.scaled(&pattern.input),
                target: pattern.target,
            };
            if self.table.len() < self.capacity {
                self.table.push(stored);
            } else {
                self.table[self.next] = stored;
            }
            self.next = (self.next + 1) % self.capacity;
        }
        Ok(())
    }

    fn stats(&self) -> LearnerStats {
        LearnerStats {
            patterns: self.table.len(),
            ..LearnerStats::default()
        }
    }
}

/// A run of the nearest-neighbour learner over `trials` trials of the shipped default
/// config, seed 1, into `data`.
fn run_knn(trials: usize, data: &std::path::Path) -> RunResult {
    let mut config = Config::default_config();
    config.trials = trials;
    let learner = NearestNeighbours::new(&config, 20_000);
    let options = RunOptions::new(config, data);
    run_learner(&options, Box::new(learner)).expect("the run runs")
}

fn main() {
    let trials = std::env::args()
        .nth(1)
        .and_then(|t| t.parse().ok())
        .unwrap_or(1000);
    let result = run_knn(trials, std::path::Path::new("data"));
    println!("{}", result.folder.display());
    print!("{}", result.summary.one_screen());
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_nearest_neighbour_learner_runs_and_learns_through_the_trial_loop() {
        let data = tempfile::tempdir().unwrap();
        let result = run_knn(400, data.path());
        assert!(result.folder.starts_with(data.path().join("knn")));
        for name in ["1step", "5step", "patterns", "summary.json"] {
            assert!(result.folder.join(name).is_file(), "{name} written");
        }
        let summary = &result.summary;
        assert_eq!(summary.method, "knn");
        let [first, .., fifth] = summary.mean_distance_mm;
        let (first, fifth) = (first.unwrap(), fifth.unwrap());
        assert!(
            fifth < 0.5 * first,
            "feedback closes in: {first} mm → {fifth} mm"
        );
    }
}
