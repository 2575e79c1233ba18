//! What a run is given besides its config's entries (`RunOptions`), what a finished one
//! gives back (`RunResult`), and why one could not start or go on (`RunError`).

use crate::experiment::output::summary::RunSummary;
use crate::experiment::plot::PlotError;
use crate::experiment::run::interrupt::StopRequest;
use crate::experiment::setup::{NoOtherMount, OtherMount};
use crate::experiment::verdict::failures::FailureTally;
use crate::experiment::{Config, Event, PreflightError, RunFolderError, RunSetup, Sources};
use crate::learn::LearnError;
use crate::robot::{DescriptionError, RobotError};
use std::io;
use std::path::PathBuf;

/// Everything a run needs besides the config's entries.
#[derive(Debug, Clone)]
pub struct RunOptions {
    /// The run's settings (flags already applied).
    pub config: Config,
    /// Where the config came from, for the `info` file.
    pub config_name: String,
    /// Where each of its values came from, for the `info` file (a value not recorded is
    /// its default, or was set by the program).
    pub sources: Sources,
    /// The URDF to load; `None` for the shipped `urdf/oscar6.urdf`.
    pub urdf: Option<PathBuf>,
    /// The data folder; runs land in `<data>/<method>/<id>/`.
    pub data_dir: PathBuf,
    /// Events given on the command line, on top of the config's.
    pub events: Vec<Event>,
    /// Show a progress bar (on a terminal, for runs longer than a second).
    pub progress: bool,
    /// Draw `plot.png` at the end.
    pub plot: bool,
    /// Stops the run after its current trial when made (by SIGINT or SIGTERM, see
    /// [`StopRequest::on_signals`]).
    pub stop: StopRequest,
    /// A fixed run folder (a sweep's cell), emptied first; `None` for the first free id.
    pub folder: Option<PathBuf>,
}

impl RunOptions {
    /// Options for a run of `config` into `data_dir`: the shipped URDF, no events beyond the
    /// config's, no progress bar, no plot.
    pub fn new(config: Config, data_dir: impl Into<PathBuf>) -> RunOptions {
        RunOptions {
            config,
            config_name: "(given in code)".into(),
            sources: Sources::default(),
            urdf: None,
            data_dir: data_dir.into(),
            events: Vec::new(),
            progress: false,
            plot: false,
            stop: StopRequest::new(),
            folder: None,
        }
    }
}

impl RunOptions {
    /// The run these options ask for, put together: the arm its URDF and the config's arm
    /// entries give, the reach space, the config's events and the options', once all of
    /// them pass the checks made before a run starts.
    pub fn setup(&self) -> Result<RunSetup, RunError> {
        let events = Event::of_run(&self.config, &self.events);
        let urdf = self.urdf.as_deref();
        RunSetup::new(self.config.clone(), urdf, events, &self.sources)
    }

    /// [`setup`](RunOptions::setup), its URDF's warnings printed to stderr.
    pub fn warned_setup(&self) -> Result<RunSetup, RunError> {
        let setup = self.setup()?;
        for warning in &setup.warnings {
            eprintln!("eyehand: warning: {warning}");
        }
        Ok(setup)
    }
}

/// Why a run could not start or go on.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum RunError {
    /// The URDF is broken, or the arm the config's entries pick out of it cannot be built.
    #[error(transparent)]
    Urdf(#[from] DescriptionError),
    /// The config's `camera_link` or `learned_joints` names no such part of the URDF.
    #[error("{at}: {entry}: {source}")]
    ArmEntry {
        /// `file:line` of the entry, or `--set` when the command line gave it.
        at: String,
        /// The entry.
        entry: &'static str,
        /// What the URDF says to it.
        source: Box<DescriptionError>,
    },
    /// The config, an event or the arm fails the checks made before the run starts.
    #[error(transparent)]
    Preflight(#[from] PreflightError),
    /// The camera, looking along its link's z axis (`camera_mount` left at its default),
    /// is refused, and looking along another axis of the link it would pass.
    #[error("{refusal}; {other}")]
    OtherMount {
        /// Why the arm is refused as its camera is mounted.
        refusal: Box<RunError>,
        /// The mount with which it passes.
        other: Box<OtherMount>,
    },
    /// The camera, looking along its link's z axis (`camera_mount` left at its default),
    /// is refused, and so it is along every other axis of the link tried.
    #[error("{refusal}; {search}")]
    NoOtherMount {
        /// Why the arm is refused as its camera is mounted.
        refusal: Box<RunError>,
        /// The other mounts tried and why each did not do.
        search: NoOtherMount,
    },
    /// No run folder could be made.
    #[error(transparent)]
    Folder(#[from] RunFolderError),
    /// The learner could not be built or failed.
    #[error(transparent)]
    Learner(#[from] LearnError),
    /// A learner's name that cannot name a folder (letters, digits, `_` and `-` only).
    #[error("a learner's name must be letters, digits, `_` or `-`, not `{0}`")]
    LearnerName(String),
    /// An event the robot cannot undergo.
    #[error("event {event}: {source}")]
    Event {
        /// The event.
        event: Event,
        /// Why it failed.
        source: RobotError,
    },
    /// Writing the run's files failed; what was written before stays.
    #[error("writing the run's files: {0}")]
    Io(#[from] io::Error),
    /// The run's plot could not be drawn; its data files are complete.
    #[error(transparent)]
    Plot(#[from] PlotError),
}

impl RunError {
    /// True when the run was refused before any work, for its input: its URDF, an arm
    /// entry, a check made before a run (with or without another camera mount to propose)
    /// or an event the robot cannot undergo. The command line calls these bad input.
    pub fn refused_before_work(&self) -> bool {
        matches!(
            self,
            RunError::Urdf(_)
                | RunError::ArmEntry { .. }
                | RunError::Preflight(_)
                | RunError::OtherMount { .. }
                | RunError::NoOtherMount { .. }
                | RunError::Event { .. }
        )
    }
}

/// A finished run: where its files are, and its summary.
#[derive(Debug, Clone)]
pub struct RunResult {
    /// The run folder.
    pub folder: PathBuf,
    /// What `summary.json` says.
    pub summary: RunSummary,
    /// The failed trials by reason.
    pub failures: FailureTally,
}
