//! A run: the robot from its URDF, a simulator, a camera and a learner put together, the
//! trials driven through every event, and the run folder filled as it goes.

use super::info_file::{write_info_header, write_info_tail};
use super::run_options::{RunError, RunOptions, RunResult};
use super::trial_driver::TrialDriver;
use crate::experiment::output::data_files::DataFiles;
use crate::experiment::output::summary::{RunSummary, SensorSummary};
use crate::experiment::plot::plot_run;
use crate::experiment::run::long_trial::LongTrialWatch;
use crate::experiment::run::progress_bar::RunProgress;
use crate::experiment::run::tree_lines::TreeLines;
use crate::experiment::verdict::failures::FailureTally;
use crate::experiment::verdict::learning_progress::learner_entries;
use crate::experiment::verdict::learning_verdict::{LearningWatch, RunEnd};
use crate::experiment::StepFigures;
use crate::experiment::{
    allocate_run_folder, fresh_run_folder, peak_rss_kb, resident_kb, Event, RunFolderError,
    RunSetup,
};
use crate::learn::Learner;
use std::path::PathBuf;
use std::time::Instant;

/// Trials the run's plot is smoothed over.
const PLOT_SMOOTHING: usize = 50;

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

/// Drives `learner` through the run's trials and events, filling `folder`.
fn drive(
    options: &RunOptions,
    setup: RunSetup,
    folder: PathBuf,
    learner: Box<dyn Learner>,
) -> Result<RunResult, RunError> {
    let config = &setup.config;
    write_info_header(&folder, options, &setup)?;

    let mut files = DataFiles::create(&folder)?;
    let mut figures = StepFigures::new(config.trials, config.feedback_steps);
    let mut failures = FailureTally::default();
    let mut watch = LearningWatch::for_trials(config.trials);
    let mut finished = 0;
    let mut progress = RunProgress::new(config.trials, options.progress);
    let mut tree_lines = TreeLines::new(&folder, options.progress);
    let long = LongTrialWatch::start(progress.printer(), config.method);
    let started = Instant::now();
    let mut root_merges = 0;
    let mut driver = TrialDriver::start(setup.trial_loop(), learner, setup.events.clone())?;
    for trial in 1..=config.trials {
        if options.stop.signal().is_some() {
            break;
        }
        long.trial_begins(trial);
        let outcome = driver.next(trial, &mut long.observer())?;
        long.trial_begins(0);
        let model_events = driver.model_events();
        files.record_model_events(trial, model_events)?;
        root_merges += model_events.iter().filter(|e| e.is_root_merge()).count();
        if let Some(failure) = outcome.failure {
            failures.count(failure);
        }
        let path = driver.trials().path();
        watch.trial_done(trial, &outcome, path, config.minimal_joint_move);
        let to_epsilon = outcome.reached.then_some(outcome.seconds);
        figures.record(trial, &outcome.distances_mm, to_epsilon);
        let stats = driver.learner().stats();
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
    let learner = driver.learner();
    let stats = learner.stats();
    let work = driver.trials().sim().work();
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
        events: setup.events.iter().map(Event::to_string).collect(),
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
