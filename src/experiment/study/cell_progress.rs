//! The progress of a study's local cells: a bar (cells done, cells running, trials per
//! second over the finished cells) when stderr is a terminal, and above it, or alone
//! otherwise, one line per finished cell.

use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
use std::io::IsTerminal;
use std::time::{Duration, Instant};

/// How often the bar redraws itself between cells (for its clock).
const TICK: Duration = Duration::from_millis(500);

/// What the study says on stderr while its cells run.
#[derive(Debug)]
pub(super) struct StudyProgress {
    bar: Option<ProgressBar>,
    started: Instant,
    trials: u64,
}

impl StudyProgress {
    /// Progress of `cells` cells, with a bar only when stderr is a terminal.
    pub(super) fn new(cells: usize) -> StudyProgress {
        let bar = std::io::stderr().is_terminal().then(|| bar(cells));
        StudyProgress {
            bar,
            started: Instant::now(),
            trials: 0,
        }
    }

    /// Notes that `running` cells are under way now.
    pub(super) fn running(&self, running: usize) {
        if let Some(bar) = &self.bar {
            bar.set_message(self.message(running));
        }
    }

    /// Says `line` of a cell that ended after `trials` trials (0 when unknown), with
    /// `running` cells still under way.
    pub(super) fn cell_done(&mut self, line: &str, trials: u64, running: usize) {
        self.trials += trials;
        match &self.bar {
            Some(bar) => {
                bar.println(line);
                bar.inc(1);
                bar.set_message(self.message(running));
            }
            None => eprintln!("{line}"),
        }
    }

    /// Removes the bar.
    pub(super) fn finish(&self) {
        if let Some(bar) = &self.bar {
            bar.finish_and_clear();
        }
    }

    fn message(&self, running: usize) -> String {
        let seconds = self.started.elapsed().as_secs_f64().max(1e-3);
        let per_second = self.trials as f64 / seconds;
        format!("{running} running, {per_second:.0} trials/s")
    }
}

fn bar(cells: usize) -> ProgressBar {
    let bar = ProgressBar::with_draw_target(Some(cells as u64), ProgressDrawTarget::stderr());
    let style = ProgressStyle::with_template("{bar:30} {pos}/{len} cells  {msg}  eta {eta}")
        .unwrap_or_else(|_| ProgressStyle::default_bar());
    bar.set_style(style);
    bar.enable_steady_tick(TICK);
    bar
}
