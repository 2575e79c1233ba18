//! `eyehand plot`, `check-config`, `config defaults` and `fk`.

use super::{angles_in_range, bad_input, failed, print_warnings, say, warned, Failure};
use crate::experiment::plot::plot_run;
use crate::experiment::setup::load_arm;
use crate::experiment::{defaults_text, unused_entries, Config, RunError, RunOptions, Sources};
use crate::robot::Controlled;
use std::path::PathBuf;

#[derive(Debug, clap::Args)]
pub(super) struct PlotArgs {
    /// The run folder (data/<method>/<id>).
    run_dir: PathBuf,
    /// Trials each point is smoothed over.
    #[arg(long, default_value_t = 50, allow_negative_numbers = true, value_parser = super::count_at_least_1)]
    smooth: usize,
}

#[derive(Debug, clap::Args)]
pub(super) struct CheckConfigArgs {
    /// The config file.
    file: PathBuf,
    /// The URDF a run would be given (default: the shipped urdf/oscar6.urdf).
    #[arg(long)]
    urdf: Option<PathBuf>,
    /// Also prints the value of every entry and where it came from (default or file:line).
    #[arg(long)]
    explain: bool,
}

#[derive(Debug, clap::Args)]
pub(super) struct ConfigArgs {
    #[command(subcommand)]
    command: ConfigCommand,
}

#[derive(Debug, clap::Subcommand)]
enum ConfigCommand {
    /// Prints every entry at its default, under a comment with what it does, what it
    /// applies to, its unit and its rule: a complete config to edit.
    Defaults,
}

#[derive(Debug, clap::Args)]
pub(super) struct FkArgs {
    /// θ1,θ2,θ3 (the learned joints) in degrees; the wrist keeps the camera vertical.
    #[arg(
        long,
        value_delimiter = ',',
        allow_hyphen_values = true,
        required = true
    )]
    joints: Vec<f64>,
    /// Prints JSON: {"camera_cm": [x, y, z], "joints_deg": [every joint], "joint_names": [..]}.
    #[arg(long)]
    json: bool,
    /// The URDF (default: the shipped urdf/oscar6.urdf).
    #[arg(long)]
    urdf: Option<PathBuf>,
    #[command(flatten)]
    arm: super::reach::ArmConfigArgs,
}

pub(super) fn plot(args: PlotArgs) -> Result<(), Failure> {
    if !args.run_dir.join("1step").is_file() {
        return Err(bad_input(format!(
            "{} is not a run folder (no 1step file)",
            args.run_dir.display()
        )));
    }
    let png = plot_run(&args.run_dir, args.smooth).map_err(failed)?;
    say(&format!("{}\n", png.display()))
}

/// Checks the file as `run` would: its entries, the arm they pick out of the URDF (the
/// shipped OSCAR-6 without `--urdf`), its events and the arm's reach after them.
pub(super) fn check_config(args: CheckConfigArgs) -> Result<(), Failure> {
    let file = args.file.display().to_string();
    let (config, sources) = Config::read_file(&args.file).map_err(bad_input)?;
    let notes = unused_notes(&sources);
    let options = RunOptions {
        config_name: file.clone(),
        urdf: args.urdf,
        sources,
        ..RunOptions::new(config, ".")
    };
    let setup = options.setup().map_err(|e| match e {
        RunError::Preflight(e) => bad_input(format!("{file}: {e}")),
        e => bad_input(e),
    })?;
    print_warnings(&setup.warnings);
    let explained = match args.explain {
        true => setup.config.explained_text(&setup.sources),
        false => String::new(),
    };
    say(&(explained + &notes + &format!("{file}: ok\n")))
}

/// A note for each entry a file gives that eyehand accepts but does not implement.
fn unused_notes(sources: &Sources) -> String {
    unused_entries()
        .into_iter()
        .filter_map(|name| Some((name, sources.of(name)?)))
        .map(|(name, source)| {
            format!("note: {source}: {name} is accepted and recorded, but unused (eyehand does not implement it)\n")
        })
        .collect()
}

/// `eyehand config …`.
pub(super) fn config(args: ConfigArgs) -> Result<(), Failure> {
    match args.command {
        ConfigCommand::Defaults => say(&defaults_text()),
    }
}

pub(super) fn fk(args: FkArgs) -> Result<(), Failure> {
    let config = args.arm.config()?;
    let model = warned(load_arm(&config, args.urdf.as_deref()).map_err(bad_input)?);
    let [t1, t2, t3] = args.joints[..] else {
        return Err(bad_input("--joints takes three angles: t1,t2,t3"));
    };
    angles_in_range("--joints", "t", &args.joints)?;
    let pose = model.pose_of(&Controlled::new(t1, t2, t3).map(f64::to_radians));
    let q = pose.joints;
    let camera = model.camera_position(&q).coords * 100.0;
    let joints_deg: Vec<f64> = q.iter().map(|v| v.to_degrees()).collect();
    let names: Vec<&str> = model.joints().iter().map(|j| j.name.as_str()).collect();
    if args.json {
        let value = serde_json::json!({ "camera_cm": [camera.x, camera.y, camera.z], "joints_deg": joints_deg, "joint_names": names });
        return say(&format!("{value}\n"));
    }
    let text: Vec<String> = joints_deg.iter().map(|v| format!("{v:.4}")).collect();
    let mut report = format!(
        "camera_cm  {:.4} {:.4} {:.4}\njoints_deg {}\njoint_names {}\n",
        camera.x,
        camera.y,
        camera.z,
        text.join(" "),
        names.join(" ")
    );
    if !pose.wrist_found {
        report += "warning: no wrist pose keeps the camera looking down there\n";
    }
    if let Some(joint) = model.violated_limit(&q) {
        report += &format!("warning: joint {} is outside its limits\n", joint + 1);
    }
    say(&report)
}
