//! SIGINT and SIGTERM while a study runs its cells here: collected (not fatal), so the
//! study can pass each one on to every running cell and wait for them before it exits.

use signal_hook::consts::{SIGINT, SIGTERM};
use signal_hook::iterator::Signals;
use std::io;

/// The interrupt signals received since [`Interrupts::catch`].
#[derive(Debug)]
pub(super) struct Interrupts(Signals);

impl Interrupts {
    /// Collects SIGINT and SIGTERM from now on instead of dying of them.
    pub(super) fn catch() -> io::Result<Interrupts> {
        Signals::new([SIGINT, SIGTERM]).map(Interrupts)
    }

    /// The signals received since the last call, oldest first.
    pub(super) fn received(&mut self) -> Vec<i32> {
        self.0.pending().collect()
    }
}

/// Sends `signal` to the process `pid` (a cell this process started and has not reaped).
pub(super) fn forward(pid: u32, signal: i32) {
    // SAFETY: kill(2) on a child of ours; if it has just exited there is nothing to stop.
    unsafe {
        libc::kill(pid as libc::pid_t, signal);
    }
}
