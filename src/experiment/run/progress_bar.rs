//! The progress bar of a run (indicatif): trials done, trials per second, the current
//! 4-step mean and the learner's size. It appears once a run has taken a second, only when
//! stderr is a terminal, and never with `--quiet`. A trial that runs long (a slow dynamic
//! arm) says where it stands every [`LONG_TRIAL`], bar or not.

use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
use std::time::{Duration, Instant};

/// Trials the "current" 4-step mean is taken over.
const RECENT: usize = 100;
const SHOW_AFTER: Duration = Duration::from_secs(1);
/// Wall-clock time a trial runs before it says where it stands, and between two such lines.
pub(in crate::experiment) const LONG_TRIAL: Duration = Duration::from_secs(10);

/// The clock of the trial going on, for a line on where a long one stands.
#[derive(Debug)]
pub(in crate::experiment) struct LongTrialWatch {
    trial: usize,
    started: Instant,
    last_said: Instant,
}

impl LongTrialWatch {
    /// A watch on no trial yet.
    pub(in crate::experiment) fn new() -> LongTrialWatch {
        let now = Instant::now();
        LongTrialWatch {
            trial: 0,
            started: now,
            last_said: now,
        }
    }

    /// Notes that `trial` took feedback step `step`, `simulated` seconds into it, at `now`;
    /// the line to print when the trial has run [`LONG_TRIAL`] since it began or since the
    /// last line.
    pub(in crate::experiment) fn step_done(
        &mut self,
        trial: usize,
        step: usize,
        simulated: f64,
        now: Instant,
    ) -> Option<String> {
        if trial != self.trial {
            (self.trial, self.started, self.last_said) = (trial, now, now);
        }
        if now.duration_since(self.last_said) < LONG_TRIAL {
            return None;
        }
        self.last_said = now;
        Some(format!(
            "eyehand: trial {trial} is long: {step} steps, {simulated:.1} simulated s in {:.0} s so far (feedback_steps, dt, robot_speed, settle_timeout, camera_fps)",
            now.duration_since(self.started).as_secs_f64()
        ))
    }
}

/// A run's progress bar.
#[derive(Debug)]
pub(in crate::experiment) struct RunProgress {
    bar: ProgressBar,
    enabled: bool,
    shown: bool,
    started: Instant,
    recent: [f64; RECENT],
    recent_count: usize,
}

impl RunProgress {
    /// A bar for `trials` trials; `enabled` false keeps it hidden for good.
    pub(in crate::experiment) fn new(trials: usize, enabled: bool) -> RunProgress {
        let bar = ProgressBar::with_draw_target(Some(trials as u64), ProgressDrawTarget::hidden());
        let style = ProgressStyle::with_template(
            "{bar:30} {pos}/{len} trials  {per_sec}  {msg}  eta {eta}",
        )
        .unwrap_or_else(|_| ProgressStyle::default_bar());
        bar.set_style(style);
        RunProgress {
            bar,
            enabled,
            shown: false,
            started: Instant::now(),
            recent: [0.0; RECENT],
            recent_count: 0,
        }
    }

    /// Notes a finished trial: its distances after each step and the learner's nodes.
    pub(in crate::experiment) fn trial_done(
        &mut self,
        trial: usize,
        distances_mm: &[f64],
        nodes: usize,
    ) {
        if let Some(&four) = distances_mm.get(3) {
            self.recent[self.recent_count % RECENT] = four;
            self.recent_count += 1;
        }
        if !self.enabled {
            return;
        }
        if !self.shown && self.started.elapsed() >= SHOW_AFTER {
            self.bar.set_draw_target(ProgressDrawTarget::stderr());
            self.shown = true;
        }
        self.bar.set_position(trial as u64);
        if trial % RECENT == 0 {
            let n = self.recent_count.min(RECENT);
            let mean = self.recent[..n].iter().sum::<f64>() / n.max(1) as f64;
            self.bar
                .set_message(format!("4-step {mean:.4} mm  {nodes} nodes"));
        }
    }

    /// Prints a line to stderr above the bar (or plainly while it is hidden).
    pub(in crate::experiment) fn println(&self, line: &str) {
        if self.shown {
            self.bar.println(line);
        } else {
            eprintln!("{line}");
        }
    }

    /// Removes the bar.
    pub(in crate::experiment) fn finish(&self) {
        self.bar.finish_and_clear();
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_trial_says_where_it_stands_once_per_long_interval() {
        let mut watch = LongTrialWatch::new();
        let start = Instant::now();
        assert_eq!(watch.step_done(3, 1, 0.5, start), None);
        assert_eq!(watch.step_done(3, 2, 1.0, start + LONG_TRIAL / 2), None);
        let line = watch.step_done(3, 3, 900.0, start + LONG_TRIAL).unwrap();
        assert!(
            line.starts_with("eyehand: trial 3 is long: 3 steps, 900.0 simulated s in 10 s so far"),
            "{line}"
        );
        assert_eq!(
            watch.step_done(3, 4, 901.0, start + LONG_TRIAL * 3 / 2),
            None
        );
        assert!(watch
            .step_done(3, 5, 902.0, start + LONG_TRIAL * 2)
            .is_some());
        let next = start + LONG_TRIAL * 3;
        assert_eq!(
            watch.step_done(4, 1, 0.5, next),
            None,
            "a new trial starts its clock"
        );
    }
}
