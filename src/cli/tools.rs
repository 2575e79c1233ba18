//! `eyehand plot`, `check-config` and `fk`.

use super::{bad_input, failed, say, warned, Failure};
use crate::experiment::plot::plot_run;
use crate::experiment::setup::load_arm;
use crate::experiment::{check_arm, Config, RunError, RunOptions};
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
    let config = Config::from_file(&args.file).map_err(bad_input)?;
    let options = RunOptions {
        config_name: file.clone(),
        urdf: args.urdf,
        ..RunOptions::new(config, ".")
    };
    let arm = check_arm(&options).map_err(|e| match e {
        RunError::Preflight(e) => bad_input(format!("{file}: {e}")),
        e => bad_input(e),
    })?;
    warned(arm);
    say(&format!("{file}: ok\n"))
}

pub(super) fn fk(args: FkArgs) -> Result<(), Failure> {
    let config = args.arm.config()?;
    let model = warned(load_arm(&config, args.urdf.as_deref()).map_err(bad_input)?);
    let [t1, t2, t3] = args.joints[..] else {
        return Err(bad_input("--joints takes three angles: t1,t2,t3"));
    };
    if let Some(bad) = args.joints.iter().find(|v| !v.is_finite()) {
        return Err(bad_input(format!("--joints: {bad} is not a finite angle")));
    }
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
