//! Experiments: the config file, events, the run folder and its data files, and the run
//! itself (simulator + camera + learner + trial loop).

mod config;
mod config_values;
mod events;
mod memory;
mod output;
mod run;
mod run_folder;
mod summary;

pub use config::{Config, ConfigError, DEFAULT_CONFIG_NAME, ENTRY_NAMES};
pub use config_values::{CameraKind, SimKind};
pub use events::{Event, EventError};
pub use memory::{peak_rss_kb, resident_kb};
pub use output::DataFiles;
pub use run::{run, RunError, RunOptions, RunResult};
pub use run_folder::{allocate_run_folder, RunFolderError, RUN_IDS};
pub use summary::{RunSummary, StepFigures};
