//! How far a replay has come: reaching a late trial means replaying every trial before it,
//! so once that has taken a second a bar on stderr (a terminal only) says which trial the
//! replay is at, of how many.

use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
use std::io::IsTerminal;
use std::time::{Duration, Instant};

/// Time a replay runs before its bar appears.
const SHOW_AFTER: Duration = Duration::from_secs(1);

/// The bar of a replay of trials 1..=last.
#[derive(Debug)]
pub(super) struct ReplayBar {
    bar: ProgressBar,
    started: Instant,
    shown: bool,
}

impl ReplayBar {
    /// A hidden bar for a replay up to trial `last`.
    pub(super) fn new(last: usize) -> ReplayBar {
        let bar = ProgressBar::with_draw_target(Some(last as u64), ProgressDrawTarget::hidden());
        let style = ProgressStyle::with_template(
            "replaying the run: {bar:30} trial {pos}/{len}  {per_sec}  eta {eta}",
        )
        .unwrap_or_else(|_| ProgressStyle::default_bar());
        bar.set_style(style);
        ReplayBar {
            bar,
            started: Instant::now(),
            // Never shown when stderr is no terminal.
            shown: !std::io::stderr().is_terminal(),
        }
    }

    /// Notes that trial `trial` has been replayed.
    pub(super) fn done(&mut self, trial: usize) {
        self.bar.set_position(trial as u64);
        if !self.shown && self.started.elapsed() >= SHOW_AFTER {
            self.shown = true;
            self.bar.set_draw_target(ProgressDrawTarget::stderr());
        }
    }
}

impl Drop for ReplayBar {
    fn drop(&mut self) {
        self.bar.finish_and_clear();
    }
}
