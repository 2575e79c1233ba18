//! Stopping a run cleanly: SIGINT or SIGTERM asks the run to stop after the trial it is in,
//! which is cut short (its remaining feedback steps and learning; see [`crate::cancel`]);
//! the run then writes its summary, marked interrupted. A second signal ends the process at
//! once, with the shell's code for that signal.

use signal_hook::consts::{SIGINT, SIGTERM};
use std::io;
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::sync::Arc;

/// A request to stop a run after its current trial, shared with the signal handlers.
#[derive(Debug, Clone, Default)]
pub struct StopRequest {
    requested: Arc<AtomicBool>,
    signal: Arc<AtomicUsize>,
}

impl StopRequest {
    /// A request nothing makes but [`request`](StopRequest::request).
    pub fn new() -> StopRequest {
        StopRequest::default()
    }

    /// A request that SIGINT and SIGTERM make; a second of either while the run finishes
    /// its trial ends the process at once with exit code 128 + the signal.
    pub fn on_signals() -> io::Result<StopRequest> {
        let stop = StopRequest::new();
        for signal in [SIGINT, SIGTERM] {
            signal_hook::flag::register_conditional_shutdown(
                signal,
                128 + signal,
                Arc::clone(&stop.requested),
            )?;
            signal_hook::flag::register_usize(signal, Arc::clone(&stop.signal), signal as usize)?;
            signal_hook::flag::register(signal, Arc::clone(&stop.requested))?;
            signal_hook::flag::register(signal, crate::cancel::flag())?;
        }
        Ok(stop)
    }

    /// Asks for a stop as `signal` would.
    pub fn request(&self, signal: i32) {
        self.signal.store(signal as usize, Ordering::SeqCst);
        self.requested.store(true, Ordering::SeqCst);
    }

    /// The signal that asked for a stop, if one did.
    pub fn signal(&self) -> Option<i32> {
        if self.requested.load(Ordering::SeqCst) {
            Some(self.signal.load(Ordering::SeqCst) as i32)
        } else {
            None
        }
    }

    /// The exit code of a process stopped this way: 128 + the signal (130 for SIGINT, 143
    /// for SIGTERM).
    pub fn exit_code(&self) -> Option<u8> {
        self.signal().map(|s| (128 + s).clamp(0, 255) as u8)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_request_carries_its_signal_and_exit_code() {
        let stop = StopRequest::new();
        assert_eq!(stop.signal(), None);
        let shared = stop.clone();
        shared.request(SIGTERM);
        assert_eq!(stop.signal(), Some(SIGTERM));
        assert_eq!(stop.exit_code(), Some(143));
    }
}
