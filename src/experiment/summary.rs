//! The run's `summary.json`, and the distance figures over the last trials it reports.

use crate::control::MAX_RECORDED_STEPS;
use serde::{Deserialize, Serialize};
use std::io;
use std::path::Path;

/// What `summary.json` holds. Field names are a public interface.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct RunSummary {
    /// The learning method.
    pub method: String,
    /// The simulator.
    pub sim: String,
    /// The camera model.
    pub camera: String,
    /// The run's seed.
    pub seed: u64,
    /// Trials run.
    pub trials: usize,
    /// Wall-clock seconds of the trials (pre-learning included).
    pub wall_seconds: f64,
    /// Trials per wall-clock second.
    pub trials_per_second: f64,
    /// Peak resident memory of the process (kB).
    pub peak_rss_kb: u64,
    /// Approximators at the end.
    pub nodes: usize,
    /// Bins at the end.
    pub bins: usize,
    /// Stored patterns at the end.
    pub patterns: usize,
    /// Trials that failed (object lost or not seen, unreachable target, bad move).
    pub failures: usize,
    /// The run's events (`rotate:TRIAL:DEG`, `elongate:TRIAL:LINK:CM`), in trial order.
    pub events: Vec<String>,
    /// The number of last trials the distance figures are taken over.
    pub window: usize,
    /// Mean distance (mm) after feedback steps 1..5 over the window (null: no such step).
    pub mean_distance_mm: [Option<f64>; MAX_RECORDED_STEPS],
    /// Median distance (mm) after feedback steps 1..5 over the window.
    pub median_distance_mm: [Option<f64>; MAX_RECORDED_STEPS],
    /// Mean distance (mm) after every feedback step 1..`feedback_steps` over the window,
    /// over the trials that took that step (a trial stops early once within ε).
    pub mean_distance_by_step_mm: Vec<Option<f64>>,
    /// True when SIGINT or SIGTERM stopped the run early: `trials` is then the trials it
    /// finished (absent in summaries written before the field existed: false).
    #[serde(default)]
    pub interrupted: bool,
}

impl RunSummary {
    /// Writes `<folder>/summary.json` under a temporary name and renames it, so the file
    /// is whole or absent.
    pub fn write(&self, folder: &Path) -> io::Result<()> {
        let json = serde_json::to_string_pretty(self).map_err(io::Error::other)?;
        let partial = folder.join(".summary.partial.json");
        std::fs::write(&partial, json + "\n")
            .and_then(|()| std::fs::rename(&partial, folder.join("summary.json")))
            .inspect_err(|_| {
                let _ = std::fs::remove_file(&partial);
            })
    }

    /// A short human-readable report of the run.
    pub fn one_screen(&self) -> String {
        let figure = |v: &Option<f64>| v.map_or("-".to_string(), |v| format!("{v:.4}"));
        let mut text = format!(
            "{} on the {} simulator ({} camera), seed {}: {} trials in {:.2} s ({:.0} trials/s), {} failed\n",
            self.method, self.sim, self.camera, self.seed, self.trials, self.wall_seconds, self.trials_per_second, self.failures
        );
        if self.interrupted {
            text += "interrupted: the trials above are those finished before the signal\n";
        }
        text += &format!(
            "tree: {} nodes, {} bins, {} patterns; peak memory {} kB\n",
            self.nodes, self.bins, self.patterns, self.peak_rss_kb
        );
        text += &format!(
            "distance to target over the last {} trials (mm):\n",
            self.window
        );
        text += "  after step      1         2         3         4         5\n";
        let row = |name: &str, values: &[Option<f64>]| {
            let cells: Vec<String> = values.iter().map(|v| format!("{:>9}", figure(v))).collect();
            format!("  {name:<10}{}\n", cells.join(" "))
        };
        text += &row("mean", &self.mean_distance_mm);
        text += &row("median", &self.median_distance_mm);
        text
    }
}

/// Distances after each of steps 1..5 over the last `window` trials of a run.
#[derive(Debug, Clone, PartialEq)]
pub struct StepFigures {
    window: usize,
    first_counted: usize,
    /// Distances after step 1, 2, … of the trials in the window.
    distances: Vec<Vec<f64>>,
}

impl StepFigures {
    /// The window for a run of `trials`: min(1000, trials/10), at least 1.
    pub fn window_for(trials: usize) -> usize {
        (trials / 10).clamp(1, 1000)
    }

    /// Figures over the last window of a run of `trials` of up to `steps` feedback steps.
    pub fn new(trials: usize, steps: usize) -> StepFigures {
        let window = StepFigures::window_for(trials);
        StepFigures {
            window,
            first_counted: trials + 1 - window,
            distances: vec![Vec::new(); steps.max(MAX_RECORDED_STEPS)],
        }
    }

    /// Notes a trial's distances if it is inside the window.
    pub fn record(&mut self, trial: usize, distances_mm: &[f64]) {
        if trial >= self.first_counted {
            for (bucket, &d) in self.distances.iter_mut().zip(distances_mm) {
                bucket.push(d);
            }
        }
    }

    /// The window's length in trials.
    pub fn window(&self) -> usize {
        self.window
    }

    /// Mean distance after every step (`None` for a step no trial in the window took).
    pub fn all_means(&self) -> Vec<Option<f64>> {
        self.distances
            .iter()
            .map(|d| (!d.is_empty()).then(|| d.iter().sum::<f64>() / d.len() as f64))
            .collect()
    }

    /// Mean distance after steps 1..5.
    pub fn means(&self) -> [Option<f64>; MAX_RECORDED_STEPS] {
        let all = self.all_means();
        std::array::from_fn(|i| all[i])
    }

    /// Median distance after steps 1..5.
    pub fn medians(&self) -> [Option<f64>; MAX_RECORDED_STEPS] {
        std::array::from_fn(|i| median(&self.distances[i]))
    }
}

fn median(values: &[f64]) -> Option<f64> {
    if values.is_empty() {
        return None;
    }
    let mut sorted = values.to_vec();
    sorted.sort_by(f64::total_cmp);
    let mid = sorted.len() / 2;
    Some(if sorted.len() % 2 == 0 {
        0.5 * (sorted[mid - 1] + sorted[mid])
    } else {
        sorted[mid]
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_window_is_the_last_tenth_up_to_1000_trials() {
        assert_eq!(StepFigures::window_for(50_000), 1000);
        assert_eq!(StepFigures::window_for(3_000), 300);
        assert_eq!(StepFigures::window_for(5), 1);
    }

    #[test]
    fn figures_count_only_the_window() {
        let mut f = StepFigures::new(20, 10);
        for trial in 1..=20 {
            f.record(trial, &[trial as f64, 1.0]);
        }
        assert_eq!(f.window(), 2);
        assert_eq!(f.means()[0], Some(19.5));
        assert_eq!(f.medians()[1], Some(1.0));
        assert_eq!(f.means()[2], None);
        assert_eq!(f.all_means().len(), 10);
        assert_eq!(f.all_means()[1], Some(1.0));
    }

    #[test]
    fn median_of_odd_and_even_counts() {
        assert_eq!(median(&[3.0, 1.0, 2.0]), Some(2.0));
        assert_eq!(median(&[4.0, 1.0, 2.0, 3.0]), Some(2.5));
    }
}
