//! The process's request to cut long work short: SIGINT or SIGTERM sets it (through
//! `experiment::StopRequest::on_signals`, the command line's runs), and the loops that can
//! take seconds within one trial — the feedback steps of a trial, a net's training
//! iterations, an mlp trial's Adam steps, the dynamic arm's settling — poll it, so the run
//! stops within a second of the signal wherever its time goes. Nothing in the library sets
//! it otherwise: a run stopped by [`StopRequest::request`](crate::experiment::StopRequest::request)
//! finishes its trial.

use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Arc, LazyLock};

static REQUESTED: LazyLock<Arc<AtomicBool>> = LazyLock::new(|| Arc::new(AtomicBool::new(false)));

/// True once a signal asked the process to stop.
pub fn requested() -> bool {
    REQUESTED.load(Ordering::Relaxed)
}

/// The flag itself, for a signal handler to set.
pub(crate) fn flag() -> Arc<AtomicBool> {
    Arc::clone(&REQUESTED)
}
