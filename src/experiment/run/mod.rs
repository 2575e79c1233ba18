//! Running a run: the options it is given and what it gives back, the trial driver, the
//! run's driver that fills its folder and `info` file, the stop request that signals make,
//! and the progress bar with its long-trial line.

pub(super) mod drive;
mod info_file;
pub(super) mod interrupt;
pub(super) mod long_trial;
pub(super) mod progress_bar;
pub(super) mod run_options;
pub(super) mod tree_lines;
pub(super) mod trial_driver;
