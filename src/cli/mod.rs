//! The command line: `eyehand run`, `plot`, `compare`, `sweep`, `check-config`, `config`, `fk`,
//! `reach`, `simulate`, `show` and `report`.
//! Flags are parsed here (validation only); each command hands resolved values to the
//! library and turns the outcome into an exit code: 2 for bad input, 1 for a failed run,
//! 130/143 for a run stopped by SIGINT/SIGTERM. Output goes through `say`, so a closed
//! pipe or a full disk behind stdout ends the program with a code, never a panic.

mod method_arg;
mod reach;
mod report;
mod run;
mod show;
mod simulate;
mod study;
mod tools;

use crate::experiment::setup::LoadedArm;
use crate::robot::ArmModel;
use clap::{Parser, Subcommand};
use std::io::{self, Write};
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
    /// Prints the config's entries: `config defaults`, every entry at its default.
    Config(tools::ConfigArgs),
    /// Prints the camera centre (cm, world frame) and every joint angle (°) of a pose.
    Fk(tools::FkArgs),
    /// Prints an arm's reach space, how much of it the arm covers and the pre-learning pose.
    Reach(reach::ReachArgs),
    /// Runs the dynamic arm free from a pose (servos off or holding) and prints every tick.
    Simulate(simulate::SimulateArgs),
    /// Re-simulates trials of a run and draws them into RUN_DIR/show/N/.
    Show(show::ShowArgs),
    /// Writes DIR/report.html: a run's (or a compare/sweep's) page for the browser.
    Report(report::ReportArgs),
}

/// What a command's failure exits with, and says.
type Failure = (u8, String);

fn bad_input(e: impl std::fmt::Display) -> Failure {
    (2, e.to_string())
}

fn failed(e: impl std::fmt::Display) -> Failure {
    (1, e.to_string())
}

/// The model of an arm read for a command, its URDF's warnings printed to stderr.
fn warned(arm: LoadedArm) -> ArmModel {
    print_warnings(&arm.warnings);
    arm.model
}

/// Prints each warning to stderr, one a line.
fn print_warnings(warnings: &[String]) {
    for warning in warnings {
        eprintln!("eyehand: warning: {warning}");
    }
}

/// Exit code of a program whose reader closed the pipe (as if SIGPIPE had ended it).
const BROKEN_PIPE_EXIT: u8 = 141;

/// Writes `text` to stdout. A reader that went away ends the program quietly with 141; any
/// other failure to write (a full disk) is an error that says so.
fn say(text: &str) -> Result<(), Failure> {
    let mut out = io::stdout().lock();
    out.write_all(text.as_bytes())
        .and_then(|()| out.flush())
        .map_err(|e| match e.kind() {
            io::ErrorKind::BrokenPipe => (BROKEN_PIPE_EXIT, String::new()),
            _ => failed(format!("writing to stdout: {e}")),
        })
}

/// `--seed`: an unsigned 64-bit integer.
fn seed(text: &str) -> Result<u64, String> {
    text.parse()
        .map_err(|_| format!("a seed is an integer from 0 to {}", u64::MAX))
}

/// `--trials`, `--smooth`: an integer of at least 1.
fn count_at_least_1(text: &str) -> Result<usize, String> {
    match text.parse::<usize>() {
        Ok(n) if n >= 1 => Ok(n),
        _ => Err(format!("must be an integer from 1 to {}", usize::MAX)),
    }
}

/// The largest joint angle a command takes (degrees): one turn either way holds every pose.
const MAX_ANGLE_DEG: f64 = 360.0;

/// Refuses the first of `flag`'s joint angles (degrees, named `name1`, `name2`, …) that is
/// not a number within ±[`MAX_ANGLE_DEG`].
fn angles_in_range(flag: &str, name: &str, angles: &[f64]) -> Result<(), Failure> {
    match angles.iter().position(|a| a.is_nan() || a.abs() > MAX_ANGLE_DEG) {
        None => Ok(()),
        Some(i) => Err(bad_input(format!(
            "{flag}: {name}{} is {}: a joint angle must be a finite number within ±{MAX_ANGLE_DEG}°",
            i + 1,
            crate::experiment::shown(&angles[i].to_string())
        ))),
    }
}

/// `message` with every word longer than 60 characters that is not a path (a number of 300
/// digits, a value pasted in) cut short as config values are, wherever it came from.
fn long_words_cut(message: &str) -> String {
    let mut out = String::with_capacity(message.len());
    let mut rest = message;
    while let Some(start) = rest.find(|c: char| !c.is_whitespace()) {
        out.push_str(&rest[..start]);
        rest = &rest[start..];
        let end = rest.find(char::is_whitespace).unwrap_or(rest.len());
        let word = &rest[..end];
        let long = word.chars().count() > crate::experiment::SHOWN_CHARS;
        if long && !word.contains(['/', '…']) {
            out.push_str(&crate::experiment::shown(word));
        } else {
            out.push_str(word);
        }
        rest = &rest[end..];
    }
    out.push_str(rest);
    out
}

/// Carries out a parsed command line.
pub fn execute(cli: Cli) -> ExitCode {
    let result = match cli.command {
        Command::Run(args) => run::run(args),
        Command::Plot(args) => tools::plot(args),
        Command::Compare(args) => study::compare(args),
        Command::Sweep(args) => study::sweep(args),
        Command::CheckConfig(args) => tools::check_config(args),
        Command::Config(args) => tools::config(args),
        Command::Fk(args) => tools::fk(args),
        Command::Reach(args) => reach::reach(args),
        Command::Simulate(args) => simulate::simulate(args),
        Command::Show(args) => show::show(args),
        Command::Report(args) => report::report(args),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err((code, message)) => {
            if !message.is_empty() {
                let _ = writeln!(io::stderr(), "eyehand: {}", long_words_cut(&message));
            }
            ExitCode::from(code)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn long_words_but_paths_are_cut_and_the_layout_kept() {
        let digits = "9".repeat(302);
        let message = format!("fk: x is {digits} cm\n  at /{}/a.urdf", "p".repeat(70));
        let cut = long_words_cut(&message);
        assert!(
            cut.starts_with(&format!(
                "fk: x is {}… (302 characters) cm\n  at /",
                &digits[..60]
            )),
            "{cut}"
        );
        assert!(cut.ends_with("/a.urdf"));
        assert_eq!(long_words_cut(" a  b "), " a  b ");
    }
}
