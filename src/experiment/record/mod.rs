//! Rerun recordings of a run's trials (`--record FILE.rrd` on `run` and `show`): the trials
//! are re-simulated from the run folder (runs are deterministic) and logged on a `sim_time`
//! timeline: the arm's links as capsules with their transforms (every physics tick on the
//! dynamic simulator, every move on the kinematic one), the camera as a pinhole with its
//! image, the target, the camera centre's path and the distance after each step. Built
//! only with the `rerun` cargo feature; without it `--record` is refused before any work.

#[cfg(feature = "rerun")]
mod rerun_log;

use crate::experiment::show::{ShowError, TrialRange};
use std::path::Path;

/// What a recording holds.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct RecordReport {
    /// Trials recorded.
    pub trials: usize,
    /// Arm transforms logged (one per physics tick or move, and one per trial's start).
    pub arm_transforms: usize,
    /// Camera images logged.
    pub images: usize,
}

/// Re-simulates trials `range` of the run in `run_dir` and writes them to the Rerun
/// recording `out`.
pub fn record_trials(
    run_dir: &Path,
    range: TrialRange,
    out: &Path,
) -> Result<RecordReport, ShowError> {
    #[cfg(feature = "rerun")]
    {
        rerun_log::record(run_dir, range, out)
    }
    #[cfg(not(feature = "rerun"))]
    {
        let _ = (run_dir, range, out);
        Err(ShowError::NoRecorder)
    }
}
