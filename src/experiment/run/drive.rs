//! A run: the robot from its URDF, a simulator, a camera and a learner put together, the
//! trial loop driven through every trial and event, and the run folder filled as it goes.

use crate::control::{TrialLoop, TrialObserver, TrialOutcome};
use crate::experiment::output::data_files::DataFiles;
use crate::experiment::output::info_file::{write_info_header, write_info_tail};
use crate::experiment::output::summary::{RunSummary, SensorSummary};
use crate::experiment::plot::{plot_run, PlotError};
use crate::experiment::run::interrupt::StopRequest;
use crate::experiment::run::long_trial::LongTrialWatch;
use crate::experiment::run::progress_bar::RunProgress;
use crate::experiment::run::tree_lines::TreeLines;
use crate::experiment::verdict::failures::FailureTally;
use crate::experiment::verdict::learning_progress::learner_entries;
use crate::experiment::verdict::learning_verdict::{LearningWatch, RunEnd};
use crate::experiment::StepFigures;
use crate::experiment::{
    allocate_run_folder, fresh_run_folder, peak_rss_kb, resident_kb, Config, Event, PreflightError,
    RunFolderError, RunSetup, Sources,
};
use crate::learn::{LearnError, Learner};
use crate::robot::{DescriptionError, RobotError};
use std::io;
use std::path::PathBuf;
use std::time::Instant;

/// Trials the run's plot is smoothed over.
const PLOT_SMOOTHING: usize = 50;

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

/// Runs every trial of a run of the config's learner (or those before a stop request) and
/// fills its folder (`<data>/<method>/<id>/`). The config, events and arm are checked
/// before the folder is made.
pub fn run(options: &RunOptions) -> Result<RunResult, RunError> {
    let setup = options.warned_setup()?;
    let folder = run_folder(options, options.config.method.name())?;
    let learner = setup.learner(Some(&folder))?;
    drive(options, setup, folder, learner)
}

/// Runs every trial of a run with a learner the caller built (one written outside the
/// crate, say): the same trial loop, data files and summary as [`run`], in
/// `<data>/<learner name>/<id>/`. The config's `method` entry is not used.
pub fn run_learner(options: &RunOptions, learner: Box<dyn Learner>) -> Result<RunResult, RunError> {
    check_learner_name(learner.name())?;
    let setup = options.warned_setup()?;
    run_learner_set_up(options, setup, learner)
}

/// [`run_learner`] on `setup`, the run [`RunOptions::setup`] (or
/// [`RunOptions::warned_setup`]) put together from `options`: for a caller that hands its
/// learner something of the run first, such as the resolved config.
pub fn run_learner_set_up(
    options: &RunOptions,
    setup: RunSetup,
    learner: Box<dyn Learner>,
) -> Result<RunResult, RunError> {
    check_learner_name(learner.name())?;
    let folder = run_folder(options, learner.name())?;
    drive(options, setup, folder, learner)
}

/// A learner's name is a folder's: letters, digits, `_` and `-`, not empty.
fn check_learner_name(name: &str) -> Result<(), RunError> {
    let plain = |c: char| c.is_ascii_alphanumeric() || c == '_' || c == '-';
    if name.is_empty() || !name.chars().all(plain) {
        return Err(RunError::LearnerName(name.to_string()));
    }
    Ok(())
}

/// The run's fixed folder (emptied), or the first free `<data>/<name>/<id>/`.
fn run_folder(options: &RunOptions, name: &str) -> Result<PathBuf, RunFolderError> {
    match &options.folder {
        Some(fixed) => fresh_run_folder(fixed),
        None => allocate_run_folder(&options.data_dir, name),
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

/// Drives `learner` through the run's trials and events, filling `folder`.
fn drive(
    options: &RunOptions,
    setup: RunSetup,
    folder: PathBuf,
    mut learner: Box<dyn Learner>,
) -> Result<RunResult, RunError> {
    let config = &setup.config;
    let events = &setup.events;
    write_info_header(&folder, options, &setup)?;

    let mut trials = setup.trial_loop();
    let mut files = DataFiles::create(&folder)?;
    let mut figures = StepFigures::new(config.trials, config.feedback_steps);
    let mut failures = FailureTally::default();
    let mut watch = LearningWatch::for_trials(config.trials);
    let mut finished = 0;
    let mut progress = RunProgress::new(config.trials, options.progress);
    let mut tree_lines = TreeLines::new(&folder, options.progress);
    let long = LongTrialWatch::start(progress.printer(), config.method);
    let started = Instant::now();
    let mut model_events = Vec::new();
    let mut root_merges = 0;
    learner.start_trial(0);
    trials.prelearn(learner.as_mut())?;
    for trial in 1..=config.trials {
        if options.stop.signal().is_some() {
            break;
        }
        long.trial_begins(trial);
        let outcome = next_trial(
            &mut trials,
            learner.as_mut(),
            events,
            trial,
            &mut long.observer(),
        )?;
        long.trial_begins(0);
        learner.drain_events(&mut model_events);
        files.record_model_events(trial, &model_events)?;
        root_merges += model_events.iter().filter(|e| e.is_root_merge()).count();
        model_events.clear();
        if let Some(failure) = outcome.failure {
            failures.count(failure);
        }
        watch.trial_done(trial, &outcome, trials.path(), config.minimal_joint_move);
        let to_epsilon = outcome.reached.then_some(outcome.seconds);
        figures.record(trial, &outcome.distances_mm, to_epsilon);
        let stats = learner.stats();
        files.record_trial(trial, &outcome, &stats)?;
        progress.trial_done(trial, &outcome.distances_mm, stats.nodes);
        if trial % config.depth_info == 0 || trial == config.trials {
            files.record_depth_info(trial, resident_kb(), &stats)?;
            if config.verbose_output != 0 {
                tree_lines.write(trial, &stats, &progress)?;
            }
        }
        finished = trial;
    }
    files.flush()?;
    tree_lines.flush()?;
    progress.finish();
    let wall_seconds = started.elapsed().as_secs_f64();
    let stats = learner.stats();
    let work = trials.sim().work();
    let per_trial = |v: f64| v / config.trials as f64;
    let (mean_final_distance_mm, median_final_distance_mm) = figures.final_distance();
    let (reached_epsilon, mean_seconds_to_epsilon) = figures.reaching();
    let not_learned = watch.verdict(&RunEnd {
        failures: &failures,
        window: figures.window(),
        moves: work.moves,
        contact_stops: work.contact_stops,
        settle_timeouts: work.settle_timeouts,
        patterns: stats.patterns,
        minimal_joint_move: config.minimal_joint_move,
        learner_settings: &learner_entries(config, learner.name()),
    });
    let summary = RunSummary {
        method: learner.name().to_string(),
        sim: config.sim.to_string(),
        camera: config.camera.to_string(),
        config_file: options.config_name.clone(),
        seed: config.seed,
        trials: finished,
        wall_seconds,
        trials_per_second: finished as f64 / wall_seconds.max(1e-9),
        peak_rss_kb: peak_rss_kb(),
        nodes: stats.nodes,
        bins: stats.bins,
        patterns: stats.patterns,
        failures: failures.total(),
        failures_by_reason: failures,
        physics_steps_per_trial: per_trial(work.physics_steps as f64),
        simulated_seconds_per_trial: per_trial(work.simulated_seconds),
        settle_timeouts: work.settle_timeouts,
        stopped_by_contact: work.contact_stops,
        moves: work.moves,
        speed_faults: work.speed_faults,
        worst_speed_fault: work.worst_speed_fault.map(Into::into),
        root_merges,
        events: events.iter().map(Event::to_string).collect(),
        obstacles: config
            .obstacle
            .iter()
            .map(|o| o.centre_and_size())
            .collect(),
        window: figures.window(),
        mean_distance_mm: figures.means(),
        median_distance_mm: figures.medians(),
        mean_distance_by_step_mm: figures.all_means(),
        interrupted: finished < config.trials,
        mean_final_distance_mm,
        median_final_distance_mm,
        reached_epsilon,
        mean_seconds_to_epsilon,
        sensors: SensorSummary::of(config),
        learned: not_learned.is_none(),
        not_learned,
    };
    write_info_tail(&folder, &summary, &stats)?;
    summary.write(&folder)?;
    if options.plot {
        plot_run(&folder, PLOT_SMOOTHING)?;
    }
    Ok(RunResult {
        folder,
        summary,
        failures,
    })
}

/// Trial `trial` of a run: the events due before it applied, the learner told, pre-learning
/// repeated if the learner asks, then the trial run and learned (`observer` told of every
/// feedback step and of the learning: see [`TrialLoop::run_trial_observed`]). A replay of a run goes
/// through the same steps, so it reproduces the run exactly.
pub(crate) fn next_trial(
    trials: &mut TrialLoop,
    learner: &mut dyn Learner,
    events: &[Event],
    trial: usize,
    observer: &mut dyn TrialObserver,
) -> Result<TrialOutcome, RunError> {
    for event in events.iter().filter(|e| e.trial() == trial) {
        event
            .apply(trials.sim_mut())
            .map_err(|source| RunError::Event {
                event: *event,
                source,
            })?;
    }
    learner.start_trial(trial);
    if learner.take_relearn_request() {
        trials.prelearn(learner)?;
    }
    Ok(trials.run_trial_observed(learner, observer)?)
}
