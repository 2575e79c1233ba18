//! The `eyehand` command: parse the flags, run, turn the outcome into an exit code.

use clap::Parser;

fn main() -> std::process::ExitCode {
    let cli = eyehand::cli::Cli::parse();
    eyehand::cli::execute(cli)
}
