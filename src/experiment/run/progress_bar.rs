//! The progress bar of a run (indicatif): trials done, trials per second, the current
//! 4-step mean and the learner's size. It appears once a run has taken a second, only when
//! stderr is a terminal, and never with `--quiet`. Lines printed meanwhile (a long trial's,
//! from another thread: [`LinePrinter`]) go above it.

use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Arc;
use std::time::{Duration, Instant};

/// Trials the "current" 4-step mean is taken over.
const RECENT: usize = 100;
const SHOW_AFTER: Duration = Duration::from_secs(1);
/// A run's progress bar.
#[derive(Debug)]
pub(in crate::experiment) struct RunProgress {
    bar: ProgressBar,
    enabled: bool,
    shown: Arc<AtomicBool>,
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
            shown: Arc::new(AtomicBool::new(false)),
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
        if !self.shown.load(Ordering::Relaxed) && self.started.elapsed() >= SHOW_AFTER {
            self.bar.set_draw_target(ProgressDrawTarget::stderr());
            self.shown.store(true, Ordering::Relaxed);
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
        self.printer().println(line);
    }

    /// A printer of lines above the bar that another thread may use.
    pub(in crate::experiment) fn printer(&self) -> LinePrinter {
        LinePrinter {
            bar: self.bar.clone(),
            shown: Arc::clone(&self.shown),
        }
    }

    /// Removes the bar.
    pub(in crate::experiment) fn finish(&self) {
        self.bar.finish_and_clear();
    }
}

/// Prints lines to stderr above a run's bar, or plainly while it is hidden.
#[derive(Debug, Clone)]
pub(in crate::experiment) struct LinePrinter {
    bar: ProgressBar,
    shown: Arc<AtomicBool>,
}

impl LinePrinter {
    /// Prints `line`.
    pub(in crate::experiment) fn println(&self, line: &str) {
        if self.shown.load(Ordering::Relaxed) {
            self.bar.println(line);
        } else {
            eprintln!("{line}");
        }
    }
}
