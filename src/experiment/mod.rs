//! Experiments: the config file, events, the run folder and its data files, and the run
//! itself (simulator + camera + learner + trial loop).

mod config;
mod output;
pub mod plot;
pub mod record;
pub mod report;
mod run;
pub mod setup;
pub mod show;
pub mod study;
mod verdict;

pub(crate) use config::entry_name;
pub use config::{
    declarations, defaults_text, docs_table, unused_entries, CameraKind, CameraMount, Config,
    ConfigError, ConfigErrorKind, Declaration, ObstacleBox, PackagePaths, ReachSetting, Rule,
    Scope, SimKind, Source, Sources, UrdfFile, ValueError, DEFAULT_CONFIG_NAME, ENTRY_NAMES,
    REPEATED_ENTRY_NAMES,
};
pub(crate) use config::{shown, SHOWN_CHARS};
pub use output::data_files::DataFiles;
pub use output::process_memory::{peak_rss_kb, resident_kb};
pub use output::run_folder::{allocate_run_folder, fresh_run_folder, RunFolderError, RUN_IDS};
pub use output::summary::{RunSummary, SensorSummary, SpeedFaultSummary};
pub use run::drive::{run, run_learner, run_learner_set_up};
pub use run::interrupt::StopRequest;
pub use run::run_options::{RunError, RunOptions, RunResult};
pub use run::tree_lines::TREE_LINES_FILE;
pub use run::trial_driver::{begin_learner_trial, start_learning};
pub use setup::events::{Event, EventError};
pub use setup::preflight::{
    contact_stopped_moves, preflight, reachable_points, target_poses_in_contact, PreflightError,
    MIN_REACHABLE_SHARE, REACH_SAMPLES,
};
pub use setup::run_request::{RequestError, RunRequest};
pub use setup::run_setup::{fit_reach_space_to_arm, RunSetup};
pub use setup::start_check::PrelearningFault;
pub use verdict::failures::FailureTally;
pub use verdict::learning_verdict::{LearningWatch, NotLearned, NotLearnedKind, RunEnd, STILL_DEG};
pub use verdict::milestones::{
    FourStepTrace, LEVEL_BEFORE_EVENT, RECOVERY_FACTOR, RECOVERY_WINDOW,
};
pub use verdict::root_cuts::{
    root_cuts_in_plain_learning, RootCuts, NNW_PROBE_TRIALS, PROBE_TRIALS,
};
pub use verdict::step_figures::StepFigures;
