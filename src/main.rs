//! The `eyehand` command: parse the flags, run, turn the outcome into an exit code.

use clap::Parser;
use std::io::Write;

fn main() -> std::process::ExitCode {
    let cli = match eyehand::cli::Cli::try_parse() {
        Ok(cli) => cli,
        Err(error) if !error.use_stderr() => {
            // --help and --version: their text must reach stdout, or the command failed.
            let written = error.print().and_then(|()| std::io::stdout().flush());
            return match written {
                Ok(()) => std::process::ExitCode::SUCCESS,
                Err(e) => {
                    eprintln!("eyehand: writing to stdout: {e}");
                    std::process::ExitCode::FAILURE
                }
            };
        }
        Err(error) => error.exit(),
    };
    eyehand::cli::execute(cli)
}
