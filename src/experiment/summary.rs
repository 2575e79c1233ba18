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
    /// Physics steps the simulator took per trial (0 on the kinematic simulator).
    pub physics_steps_per_trial: f64,
    /// Simulated seconds of moves per trial, settling included.
    pub simulated_seconds_per_trial: f64,
    /// Moves, placings and link changes after which the dynamic arm had not settled in time.
    pub settle_timeouts: u64,
    /// Moves stopped by a contact: the floor (both simulators) or another link (dynamic).
    pub stopped_by_contact: u64,
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

/// Distances after each feedback step over the last trials of a run: the last
/// `window_for(trials)` trials of a run that ran them all, the last `window_for(n)` of one
/// stopped after trial n.
#[derive(Debug, Clone, PartialEq)]
pub struct StepFigures {
    /// Trials kept: the window of the whole run.
    capacity: usize,
    /// Slots per trial: a distance after each step, NaN for a step not taken.
    steps: usize,
    /// The kept trials' slots, trial t in row (t − 1) mod `capacity`.
    ring: Vec<f64>,
    /// The number of the last trial recorded (0: none yet).
    last_trial: usize,
}

impl StepFigures {
    /// The window for a run of `trials`: min(1000, trials/10), at least 1.
    pub fn window_for(trials: usize) -> usize {
        (trials / 10).clamp(1, 1000)
    }

    /// Figures for a run of `trials` of up to `steps` feedback steps.
    pub fn new(trials: usize, steps: usize) -> StepFigures {
        let capacity = StepFigures::window_for(trials);
        let steps = steps.max(MAX_RECORDED_STEPS);
        StepFigures {
            capacity,
            steps,
            ring: vec![f64::NAN; capacity * steps],
            last_trial: 0,
        }
    }

    /// Notes the distances of `trial` (trials are recorded in order, from 1).
    pub fn record(&mut self, trial: usize, distances_mm: &[f64]) {
        let row = (trial.max(1) - 1) % self.capacity;
        let slots = &mut self.ring[row * self.steps..(row + 1) * self.steps];
        slots.fill(f64::NAN);
        for (slot, &d) in slots.iter_mut().zip(distances_mm) {
            *slot = d;
        }
        self.last_trial = trial;
    }

    /// The window's length in trials: that of the trials recorded.
    pub fn window(&self) -> usize {
        StepFigures::window_for(self.last_trial).min(self.capacity)
    }

    /// The distances after step `step` (0-based) of the window's trials, oldest first.
    fn after_step(&self, step: usize) -> impl Iterator<Item = f64> + '_ {
        let first = (self.last_trial + 1).saturating_sub(self.window()).max(1);
        (first..=self.last_trial)
            .map(move |t| self.ring[((t - 1) % self.capacity) * self.steps + step])
            .filter(|d| !d.is_nan())
    }

    /// Mean distance after every step (`None` for a step no trial in the window took).
    pub fn all_means(&self) -> Vec<Option<f64>> {
        (0..self.steps)
            .map(|step| {
                let (sum, n) = self
                    .after_step(step)
                    .fold((0.0, 0usize), |(sum, n), d| (sum + d, n + 1));
                (n > 0).then(|| sum / n as f64)
            })
            .collect()
    }

    /// Mean distance after steps 1..5.
    pub fn means(&self) -> [Option<f64>; MAX_RECORDED_STEPS] {
        let all = self.all_means();
        std::array::from_fn(|i| all[i])
    }

    /// Median distance after steps 1..5.
    pub fn medians(&self) -> [Option<f64>; MAX_RECORDED_STEPS] {
        std::array::from_fn(|i| median(&self.after_step(i).collect::<Vec<_>>()))
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
    fn a_run_stopped_early_counts_the_window_of_its_trials() {
        let mut f = StepFigures::new(1_000_000, 5);
        for trial in 1..=3000 {
            f.record(trial, &[trial as f64]);
        }
        assert_eq!(f.window(), 300);
        assert_eq!(
            f.means()[0],
            Some((2701..=3000).sum::<usize>() as f64 / 300.0)
        );
        assert_eq!(f.medians()[1], None);
    }

    #[test]
    fn median_of_odd_and_even_counts() {
        assert_eq!(median(&[3.0, 1.0, 2.0]), Some(2.0));
        assert_eq!(median(&[4.0, 1.0, 2.0, 3.0]), Some(2.5));
    }
}
