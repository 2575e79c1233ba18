//! `eyehand run`.

use super::{bad_input, failed, say, Failure};
use crate::experiment::{
    self, CameraKind, Config, Event, RunError, RunOptions, RunResult, SimKind, StopRequest,
    DEFAULT_CONFIG_NAME,
};
use crate::learn::Method;
use std::io::IsTerminal;
use std::path::{Path, PathBuf};

#[derive(Debug, clap::Args)]
pub(super) struct RunArgs {
    /// The config file (default: the shipped configs/lin5.conf).
    #[arg(long)]
    config: Option<PathBuf>,
    /// The learning method: lin5, lin8, nnw, ffn, kohonen or ik.
    #[arg(long)]
    method: Option<Method>,
    /// The simulator: kinematic or dynamic.
    #[arg(long)]
    sim: Option<SimKind>,
    /// The camera: projection or raycast.
    #[arg(long)]
    camera: Option<CameraKind>,
    /// Trials to run.
    #[arg(long, allow_negative_numbers = true, value_parser = super::count_at_least_1)]
    trials: Option<usize>,
    /// Seed of every random draw.
    #[arg(long, allow_negative_numbers = true, value_parser = super::seed)]
    seed: Option<u64>,
    /// Sets any config entry: NAME=VALUE (repeatable; applied before the flags above).
    #[arg(long = "set", value_name = "NAME=VALUE")]
    sets: Vec<String>,
    /// The URDF (default: the shipped urdf/oscar6.urdf).
    #[arg(long)]
    urdf: Option<PathBuf>,
    /// The data folder.
    #[arg(long, default_value = "data")]
    data: PathBuf,
    /// An event: rotate:TRIAL:DEG or elongate:TRIAL:LINK:CM (repeatable).
    #[arg(long = "event")]
    events: Vec<Event>,
    /// Prints only the run folder, no progress bar.
    #[arg(long)]
    quiet: bool,
    /// Does not draw plot.png at the end.
    #[arg(long)]
    no_plot: bool,
}

/// The config file named (or the shipped default) and the name it is reported under.
pub(super) fn load_config(path: Option<&Path>) -> Result<(Config, String), Failure> {
    match path {
        Some(path) => Ok((
            Config::from_file(path).map_err(bad_input)?,
            path.display().to_string(),
        )),
        None => Ok((Config::default_config(), DEFAULT_CONFIG_NAME.to_string())),
    }
}

/// The config file with every `--set` and flag applied, checked as a whole once the last
/// one is in (so values that depend on each other may be set in any order).
fn resolve_config(args: &RunArgs) -> Result<(Config, String), Failure> {
    let (mut config, name) = load_config(args.config.as_deref())?;
    for set in &args.sets {
        let shown_set = experiment::shown(set);
        let (entry, value) = set
            .split_once('=')
            .ok_or_else(|| bad_input(format!("--set {shown_set}: expected NAME=VALUE")))?;
        config
            .assign(entry, value)
            .map_err(|e| bad_input(format!("--set {shown_set}: {e}")))?;
    }
    config.method = args.method.unwrap_or(config.method);
    config.sim = args.sim.unwrap_or(config.sim);
    config.camera = args.camera.unwrap_or(config.camera);
    config.seed = args.seed.unwrap_or(config.seed);
    config.trials = args.trials.unwrap_or(config.trials);
    config
        .check()
        .map_err(|e| bad_input(format!("{name} with the command line's settings: {e}")))?;
    Ok((config, name))
}

pub(super) fn run(args: RunArgs) -> Result<(), Failure> {
    let (config, config_name) = resolve_config(&args)?;
    let stop = StopRequest::on_signals().map_err(|e| failed(format!("signal handlers: {e}")))?;
    let options = RunOptions {
        config,
        config_name,
        urdf: args.urdf,
        data_dir: args.data,
        events: args.events,
        progress: !args.quiet && std::io::stderr().is_terminal(),
        plot: !args.no_plot,
        stop: stop.clone(),
    };
    let result = experiment::run(&options).map_err(|e| match e {
        RunError::Urdf(_) | RunError::Preflight(_) | RunError::Event { .. } => bad_input(e),
        _ => failed(e),
    })?;
    say(&format!("{}\n", result.folder.display()))?;
    if !args.quiet {
        say(&result.summary.one_screen())?;
    }
    outcome(&result, &stop)
}

/// How a finished run exits: 130/143 when a signal stopped it, 1 when every trial failed
/// (saying why), 0 otherwise.
fn outcome(result: &RunResult, stop: &StopRequest) -> Result<(), Failure> {
    let summary = &result.summary;
    if summary.interrupted {
        let code = stop.exit_code().unwrap_or(130);
        return Err((
            code,
            format!(
                "interrupted after trial {}: {} has the trials finished and summary.json says \"interrupted\": true",
                summary.trials,
                result.folder.display()
            ),
        ));
    }
    if summary.trials > 0 && summary.failures == summary.trials {
        return Err(failed(format!(
            "all {} trials failed ({}): nothing was learned",
            summary.trials, result.failures
        )));
    }
    Ok(())
}
