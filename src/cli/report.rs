//! `eyehand report DIR`: the run's (or study's) page, DIR/report.html.

use super::{bad_input, failed, say, Failure};
use crate::experiment::report::{write_report, ReportError, ReportOptions};
use std::path::{Path, PathBuf};

#[derive(Debug, clap::Args)]
pub(super) struct ReportArgs {
    /// A run folder (data/<method>/<id>) or a compare/sweep folder.
    dir: PathBuf,
    /// A trial the 3-D view replays (repeatable; default: the first, each event's and the
    /// last).
    #[arg(long = "trial", value_parser = super::count_at_least_1)]
    trials: Vec<usize>,
    /// Trials the distance curves are smoothed over (a trailing mean).
    #[arg(long, default_value_t = 50, allow_negative_numbers = true, value_parser = super::count_at_least_1)]
    smooth: usize,
}

pub(super) fn report(args: ReportArgs) -> Result<(), Failure> {
    let options = ReportOptions {
        trials: args.trials,
        smooth: args.smooth,
    };
    write_and_say(&args.dir, &options)
}

/// Writes the report of `dir` and prints its path.
pub(super) fn write_and_say(dir: &Path, options: &ReportOptions) -> Result<(), Failure> {
    let path = write_report(dir, options).map_err(|e: ReportError| {
        if e.is_bad_input() {
            bad_input(e)
        } else {
            failed(e)
        }
    })?;
    say(&format!("{}\n", path.display()))
}
