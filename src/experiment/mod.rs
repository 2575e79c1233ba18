//! Experiments: the config file, events, the run folder and its data files, and the run
//! itself (simulator + camera + learner + trial loop).

mod config;
mod events;
mod failures;
mod fixed_six;
mod interrupt;
mod learning_verdict;
mod memory;
mod milestones;
mod output;
pub mod plot;
mod preflight;
mod progress;
pub mod record;
pub mod report;
mod run;
mod run_folder;
mod run_request;
mod run_setup;
pub mod setup;
pub mod show;
mod start_check;
mod step_figures;
pub mod study;
mod summary;

pub(crate) use config::entry_name;
pub(crate) use config::shown;
pub use config::{
    declarations, defaults_text, docs_table, unused_entries, CameraKind, Config, ConfigError,
    ConfigErrorKind, Declaration, ObstacleBox, PackagePaths, ReachSetting, Rule, Scope, SimKind,
    Source, Sources, UrdfFile, ValueError, DEFAULT_CONFIG_NAME, ENTRY_NAMES, REPEATED_ENTRY_NAMES,
};
pub use events::{Event, EventError};
pub use failures::FailureTally;
pub use interrupt::StopRequest;
pub use learning_verdict::{LearningWatch, NotLearned, NotLearnedKind, RunEnd, STILL_DEG};
pub use memory::{peak_rss_kb, resident_kb};
pub use milestones::{FourStepTrace, LEVEL_BEFORE_EVENT, RECOVERY_FACTOR, RECOVERY_WINDOW};
pub use output::DataFiles;
pub use preflight::{
    contact_stopped_moves, preflight, reachable_points, target_poses_in_contact, PreflightError,
    MIN_REACHABLE_SHARE, REACH_SAMPLES,
};
pub use run::{run, run_learner, run_learner_set_up, RunError, RunOptions, RunResult};
pub use run_folder::{allocate_run_folder, fresh_run_folder, RunFolderError, RUN_IDS};
pub use run_request::{RequestError, RunRequest};
pub use run_setup::{fit_reach_space_to_arm, RunSetup};
pub use start_check::PrelearningFault;
pub use step_figures::StepFigures;
pub use summary::{RunSummary, SensorSummary};
