//! Running a run: the trial driver, the stop request that signals make, and the progress
//! bar with its long-trial line.

pub(super) mod drive;
pub(super) mod interrupt;
pub(super) mod long_trial;
pub(super) mod progress_bar;
