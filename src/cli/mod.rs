//! The command line: `eyehand run`, `plot`, `compare`, `sweep`, `check-config` and `fk`.
//! Flags are parsed here (validation only); each command hands resolved values to the
//! library and turns the outcome into an exit code: 2 for bad input, 1 for a failed run.

mod run;
mod study;
mod tools;

use clap::{Parser, Subcommand};
use std::process::ExitCode;

/// A camera-in-hand OSCAR-6 arm that learns its own eye-hand mapping.
#[derive(Debug, Parser)]
#[command(name = "eyehand", version, about)]
pub struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Debug, Subcommand)]
enum Command {
    /// Runs trials of a learner and writes data/<method>/<id>/.
    Run(run::RunArgs),
    /// Draws RUN_DIR/plot.png from a run's data files.
    Plot(tools::PlotArgs),
    /// Runs several methods on the same seeds side by side and tabulates them.
    Compare(study::CompareArgs),
    /// Runs the cross product of config settings and seeds (or writes a Slurm script).
    Sweep(study::SweepArgs),
    /// Checks a config file and reports the first error as file:line: reason.
    CheckConfig(tools::CheckConfigArgs),
    /// Prints the camera centre (cm, world frame) and all six joint angles (°) of a pose.
    Fk(tools::FkArgs),
}

/// What a command's failure exits with, and says.
type Failure = (u8, String);

fn bad_input(e: impl std::fmt::Display) -> Failure {
    (2, e.to_string())
}

fn failed(e: impl std::fmt::Display) -> Failure {
    (1, e.to_string())
}

/// Carries out a parsed command line.
pub fn execute(cli: Cli) -> ExitCode {
    let result = match cli.command {
        Command::Run(args) => run::run(args),
        Command::Plot(args) => tools::plot(args),
        Command::Compare(args) => study::compare(args),
        Command::Sweep(args) => study::sweep(args),
        Command::CheckConfig(args) => tools::check_config(args),
        Command::Fk(args) => tools::fk(args),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err((code, message)) => {
            eprintln!("eyehand: {message}");
            ExitCode::from(code)
        }
    }
}
