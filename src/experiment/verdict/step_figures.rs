//! Distances after each feedback step over the last trials of a run (the `window`), the
//! distance each trial ended at, and how long the trials that reached ε took.

use crate::control::MAX_RECORDED_STEPS;

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
    /// The kept trials' simulated seconds to ε, NaN for a trial that did not reach it;
    /// trial t in slot (t − 1) mod `capacity`.
    to_epsilon: Vec<f64>,
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
            to_epsilon: vec![f64::NAN; capacity],
            last_trial: 0,
        }
    }

    /// Notes the distances of `trial` (trials are recorded in order, from 1) and the
    /// simulated seconds it took to come within ε, if it did.
    pub fn record(&mut self, trial: usize, distances_mm: &[f64], to_epsilon: Option<f64>) {
        let row = (trial.max(1) - 1) % self.capacity;
        self.to_epsilon[row] = to_epsilon.unwrap_or(f64::NAN);
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

    /// The rows of the window's trials, oldest first.
    fn window_rows(&self) -> impl Iterator<Item = usize> + '_ {
        let first = (self.last_trial + 1).saturating_sub(self.window()).max(1);
        (first..=self.last_trial).map(move |t| (t - 1) % self.capacity)
    }

    /// The distances after step `step` (0-based) of the window's trials, oldest first.
    fn after_step(&self, step: usize) -> impl Iterator<Item = f64> + '_ {
        self.window_rows()
            .map(move |row| self.ring[row * self.steps + step])
            .filter(|d| !d.is_nan())
    }

    /// The distance after each window trial's last step (trials that took none left out).
    fn final_distances(&self) -> Vec<f64> {
        self.window_rows()
            .filter_map(|row| {
                let slots = &self.ring[row * self.steps..(row + 1) * self.steps];
                slots.iter().rev().copied().find(|d| !d.is_nan())
            })
            .collect()
    }

    /// Mean and median distance (mm) after the window trials' last steps.
    pub fn final_distance(&self) -> (Option<f64>, Option<f64>) {
        let last = self.final_distances();
        (mean(&last), median(&last))
    }

    /// The window's trials that came within ε, and their mean simulated seconds to it.
    pub fn reaching(&self) -> (usize, Option<f64>) {
        let seconds: Vec<f64> = self
            .window_rows()
            .map(|row| self.to_epsilon[row])
            .filter(|s| !s.is_nan())
            .collect();
        (seconds.len(), mean(&seconds))
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

fn mean(values: &[f64]) -> Option<f64> {
    (!values.is_empty()).then(|| values.iter().sum::<f64>() / values.len() as f64)
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
            f.record(trial, &[trial as f64, 1.0], None);
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
            f.record(trial, &[trial as f64], None);
        }
        assert_eq!(f.window(), 300);
        assert_eq!(
            f.means()[0],
            Some((2701..=3000).sum::<usize>() as f64 / 300.0)
        );
        assert_eq!(f.medians()[1], None);
    }

    #[test]
    fn final_distances_and_time_to_epsilon_count_the_window() {
        let mut f = StepFigures::new(30, 5);
        for trial in 1..=27 {
            f.record(trial, &[9.0, 0.1], Some(100.0));
        }
        f.record(28, &[7.0, 3.0, 0.4], Some(2.0));
        f.record(29, &[8.0, 5.0, 4.0], None);
        f.record(30, &[6.0, 0.2], Some(1.0));
        assert_eq!(f.window(), 3);
        assert_eq!(
            f.final_distance(),
            (Some((0.4 + 4.0 + 0.2) / 3.0), Some(0.4))
        );
        assert_eq!(f.reaching(), (2, Some(1.5)));
    }

    #[test]
    fn median_of_odd_and_even_counts() {
        assert_eq!(median(&[3.0, 1.0, 2.0]), Some(2.0));
        assert_eq!(median(&[4.0, 1.0, 2.0, 3.0]), Some(2.5));
    }
}
