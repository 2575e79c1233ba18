//! `eyehand show`: a run's trials re-simulated and drawn, and the `--record` flag shared with
//! `eyehand run`.

use super::{bad_input, failed, say, Failure};
use crate::experiment::record::record_trials;
use crate::experiment::show::{show_trials, ShowError, TrialRange};
use std::path::{Path, PathBuf};

#[derive(Debug, clap::Args)]
#[command(group(clap::ArgGroup::new("which").required(true).args(["trial", "trials"])))]
pub(super) struct ShowArgs {
    /// The run folder (data/<method>/<id>).
    run_dir: PathBuf,
    /// The trial to show.
    #[arg(long)]
    trial: Option<usize>,
    /// The trials to show: A..B (both included).
    #[arg(long)]
    trials: Option<TrialRange>,
    #[command(flatten)]
    record: RecordArgs,
}

/// `--record FILE.rrd` and `--record-trials A..B`.
#[derive(Debug, Clone, clap::Args)]
pub(super) struct RecordArgs {
    /// Writes a Rerun recording of the trials to this file (needs the `rerun` feature).
    #[arg(long, value_name = "FILE.rrd")]
    record: Option<PathBuf>,
    /// The trials recorded: A..B (default: every trial of a run, the shown ones of show).
    #[arg(long, value_name = "A..B", requires = "record")]
    record_trials: Option<TrialRange>,
}

impl RecordArgs {
    /// Refuses `--record` before any work when the recorder is not built in.
    pub(super) fn check(&self) -> Result<(), Failure> {
        if self.record.is_some() && !cfg!(feature = "rerun") {
            return Err(bad_input(ShowError::NoRecorder));
        }
        Ok(())
    }

    /// Records trials of the run in `run_dir` if asked: `--record-trials`, else `default`.
    pub(super) fn write(&self, run_dir: &Path, default: TrialRange) -> Result<(), Failure> {
        let Some(path) = &self.record else {
            return Ok(());
        };
        let range = self.record_trials.unwrap_or(default);
        record_trials(run_dir, range, path).map_err(show_failure)?;
        say(&format!("{}\n", path.display()))
    }
}

fn show_failure(e: ShowError) -> Failure {
    match e {
        ShowError::Write { .. } | ShowError::Replay(_) => failed(e),
        _ => bad_input(e),
    }
}

pub(super) fn show(args: ShowArgs) -> Result<(), Failure> {
    args.record.check()?;
    let range = match (args.trial, args.trials) {
        (Some(trial), _) => TrialRange::single(trial),
        (None, Some(range)) => range,
        (None, None) => return Err(bad_input("give --trial N or --trials A..B")),
    };
    let report = show_trials(&args.run_dir, range).map_err(show_failure)?;
    for folder in &report.folders {
        say(&format!("{}\n", folder.display()))?;
    }
    args.record.write(&args.run_dir, range)
}
