//! `eyehand run`.

use super::{bad_input, failed, say, Failure};
use crate::experiment::report::ReportOptions;
use crate::experiment::show::TrialRange;
use crate::experiment::{self, CameraKind, Event, RunRequest, RunResult, SimKind, StopRequest};
use crate::learn::Method;
use std::io::IsTerminal;
use std::path::PathBuf;

#[derive(Debug, clap::Args)]
pub(super) struct RunArgs {
    /// The config file; an entry it does not give keeps its default (default: none).
    #[arg(long)]
    config: Option<PathBuf>,
    /// The learning method.
    #[arg(long, value_enum)]
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
    /// Writes the run's report.html (eyehand report) at the end.
    #[arg(long)]
    report: bool,
    #[command(flatten)]
    record: super::show::RecordArgs,
}

/// `--set NAME=VALUE` flags as (name, value) pairs.
pub(super) fn name_values(sets: &[String]) -> Result<Vec<(String, String)>, Failure> {
    sets.iter()
        .map(|set| {
            set.split_once('=')
                .map(|(n, v)| (n.to_string(), v.to_string()))
                .ok_or_else(|| {
                    let shown = experiment::shown(set);
                    bad_input(format!("--set {shown}: expected NAME=VALUE"))
                })
        })
        .collect()
}

impl RunArgs {
    /// The typed run these flags ask for.
    fn request(self) -> Result<RunRequest, Failure> {
        let sets = name_values(&self.sets)?;
        Ok(RunRequest {
            config: self.config,
            sets,
            method: self.method,
            sim: self.sim,
            camera: self.camera,
            trials: self.trials,
            seed: self.seed,
            urdf: self.urdf,
            data: self.data,
            folder: None,
            events: self.events,
            progress: !self.quiet && std::io::stderr().is_terminal(),
            plot: !self.no_plot,
        })
    }
}

pub(super) fn run(args: RunArgs) -> Result<(), Failure> {
    let quiet = args.quiet;
    let report = args.report;
    args.record.check()?;
    let record = args.record.clone();
    let mut options = args.request()?.options().map_err(bad_input)?;
    let stop = StopRequest::on_signals().map_err(|e| failed(format!("signal handlers: {e}")))?;
    options.stop = stop.clone();
    let result = experiment::run(&options).map_err(|e| match e.refused_before_work() {
        true => bad_input(e),
        false => failed(e),
    })?;
    say(&format!("{}\n", result.folder.display()))?;
    if !quiet {
        say(&result.summary.one_screen())?;
    }
    if report {
        super::report::write_and_say(&result.folder, &ReportOptions::default())?;
    }
    outcome(&result, &stop)?;
    let finished = TrialRange {
        first: 1,
        last: result.summary.trials,
    };
    record.write(&result.folder, finished)
}

/// The share of moves stopped by a contact past which a run says so.
const CONTACT_STOPS_WORTH_A_WARNING: f64 = 0.01;
/// Root merges in a run past which the run says that its learner kept starting over.
const ROOT_MERGES_WORTH_A_WARNING: usize = 10;

/// How a finished run exits: 130/143 when a signal stopped it, 1 when it learned nothing
/// (saying why, see [`experiment::NotLearned`]; its reason stands for the warnings), 0
/// otherwise (warning when more than 1% of the moves were stopped by a
/// contact, or the learner's tree kept being cut at its root).
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
    if let Some(not_learned) = &summary.not_learned {
        return Err(failed(format!(
            "nothing was learned: {}; summary.json says \"learned\": false",
            not_learned.reason
        )));
    }
    if summary.stopped_by_contact as f64 > CONTACT_STOPS_WORTH_A_WARNING * summary.moves as f64 {
        eprintln!(
            "eyehand: warning: {} of {} moves ({:.1}%) were stopped by a contact (the floor, an \
             obstacle or another link): starts or targets may be trapped (eyehand reach)",
            summary.stopped_by_contact,
            summary.moves,
            100.0 * summary.stopped_by_contact as f64 / summary.moves.max(1) as f64
        );
    }
    if summary.root_merges >= ROOT_MERGES_WORTH_A_WARNING {
        eprintln!(
            "eyehand: warning: the learner's tree was cut at its root {} times in {} trials, \
             starting over each time: its absolute merges fire while it learns \
             (am_error_tresh, am_error_iters; 20 over 300 patterns does not fire on the OSCAR-6)",
            summary.root_merges, summary.trials
        );
    }
    Ok(())
}
