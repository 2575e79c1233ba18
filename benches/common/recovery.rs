//! Reading recovery after an event from a run's files: the 4-step distance per trial, the
//! detector's alarms, and when the 4-step mean came back.

use std::path::Path;

/// Trials in the sliding window that decides recovery.
pub const RECOVERY_WINDOW: usize = 100;

/// The 4-step distance of every trial up to `trials` (NaN where the trial had no 4th step).
pub fn four_step(folder: &Path, trials: usize) -> Vec<f64> {
    let mut by_trial = vec![f64::NAN; trials + 1];
    let text = std::fs::read_to_string(folder.join("4step")).expect("4step");
    for line in text.lines() {
        let mut fields = line.split(' ');
        let trial: usize = fields.next().and_then(|t| t.parse().ok()).expect("a trial");
        by_trial[trial] = fields
            .next()
            .and_then(|d| d.parse().ok())
            .expect("a distance");
    }
    by_trial
}

/// The mean of the finite values.
pub fn mean(values: &[f64]) -> f64 {
    let finite: Vec<f64> = values.iter().copied().filter(|v| v.is_finite()).collect();
    finite.iter().sum::<f64>() / finite.len().max(1) as f64
}

/// The trials of the alarms in a run's `changes` file.
pub fn alarms(folder: &Path) -> Vec<usize> {
    let changes = std::fs::read_to_string(folder.join("changes")).unwrap_or_default();
    changes
        .lines()
        .filter_map(|l| l.split(' ').next()?.parse().ok())
        .collect()
}

/// Trials after `event` until the 4-step mean over a sliding window of
/// [`RECOVERY_WINDOW`] trials is back within 2× `before` (`None`: never, up to the last
/// trial of `d`).
pub fn recovered_after(d: &[f64], event: usize, before: f64) -> Option<usize> {
    (event + RECOVERY_WINDOW..d.len())
        .find(|&t| mean(&d[t + 1 - RECOVERY_WINDOW..=t]) <= 2.0 * before)
        .map(|t| t - event)
}
