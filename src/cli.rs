//! The command line: `eyehand run`, `eyehand check-config` and `eyehand fk`.

use crate::experiment::{
    self, CameraKind, Config, Event, RunOptions, SimKind, DEFAULT_CONFIG_NAME,
};
use crate::learn::Method;
use crate::robot::{load_urdf, ArmModel, Controlled};
use clap::{Parser, Subcommand};
use std::path::{Path, PathBuf};
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
    Run(RunArgs),
    /// Checks a config file and reports the first error as file:line: reason.
    CheckConfig {
        /// The config file.
        file: PathBuf,
    },
    /// Prints the camera centre (cm, world frame) and all six joint angles (°) of a pose.
    Fk {
        /// θ1,θ2,θ3 in degrees (θ4 = θ6 = 0, θ5 keeps the camera vertical).
        #[arg(
            long,
            value_delimiter = ',',
            allow_negative_numbers = true,
            required = true
        )]
        joints: Vec<f64>,
        /// Prints JSON: {"camera_cm": [x, y, z], "joints_deg": [6 values]}.
        #[arg(long)]
        json: bool,
        /// The URDF (default: the shipped urdf/oscar6.urdf).
        #[arg(long)]
        urdf: Option<PathBuf>,
    },
}

#[derive(Debug, clap::Args)]
struct RunArgs {
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
    #[arg(long)]
    trials: Option<usize>,
    /// Seed of every random draw.
    #[arg(long)]
    seed: Option<u64>,
    /// The URDF (default: the shipped urdf/oscar6.urdf).
    #[arg(long)]
    urdf: Option<PathBuf>,
    /// The data folder.
    #[arg(long, default_value = "data")]
    data: PathBuf,
    /// An event: rotate:TRIAL:DEG or elongate:TRIAL:LINK:CM (repeatable).
    #[arg(long = "event")]
    events: Vec<Event>,
    /// Prints only the run folder.
    #[arg(long)]
    quiet: bool,
}

/// Carries out a parsed command line; exit code 2 for bad input, 1 for a failed run.
pub fn execute(cli: Cli) -> ExitCode {
    let result = match cli.command {
        Command::Run(args) => run(args),
        Command::CheckConfig { file } => check_config(&file),
        Command::Fk { joints, json, urdf } => fk(&joints, json, urdf.as_deref()),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err((code, message)) => {
            eprintln!("eyehand: {message}");
            ExitCode::from(code)
        }
    }
}

type CliResult = Result<(), (u8, String)>;

fn bad_input(e: impl std::fmt::Display) -> (u8, String) {
    (2, e.to_string())
}

fn load_config(path: Option<&Path>) -> Result<(Config, String), (u8, String)> {
    match path {
        Some(path) => Ok((
            Config::from_file(path).map_err(bad_input)?,
            path.display().to_string(),
        )),
        None => Ok((Config::default_config(), DEFAULT_CONFIG_NAME.to_string())),
    }
}

fn run(args: RunArgs) -> CliResult {
    let (mut config, config_name) = load_config(args.config.as_deref())?;
    config.method = args.method.unwrap_or(config.method);
    config.sim = args.sim.unwrap_or(config.sim);
    config.camera = args.camera.unwrap_or(config.camera);
    config.trials = args.trials.unwrap_or(config.trials);
    config.seed = args.seed.unwrap_or(config.seed);
    if config.trials == 0 {
        return Err(bad_input("--trials must be at least 1"));
    }
    let options = RunOptions {
        config,
        config_name,
        urdf: args.urdf,
        data_dir: args.data,
        events: args.events,
    };
    let result = experiment::run(&options).map_err(|e| {
        let code = match e {
            experiment::RunError::Urdf(_) | experiment::RunError::Unavailable(_) => 2,
            _ => 1,
        };
        (code, e.to_string())
    })?;
    println!("{}", result.folder.display());
    if !args.quiet {
        print!("{}", result.summary.one_screen());
    }
    Ok(())
}

fn check_config(file: &Path) -> CliResult {
    Config::from_file(file).map_err(bad_input)?;
    println!("{}: ok", file.display());
    Ok(())
}

fn fk(joints: &[f64], json: bool, urdf: Option<&Path>) -> CliResult {
    let model = match urdf {
        Some(path) => load_urdf(path).map_err(bad_input)?,
        None => ArmModel::oscar6(),
    };
    let [t1, t2, t3] = joints else {
        return Err(bad_input("--joints takes three angles: t1,t2,t3"));
    };
    let theta = Controlled::new(*t1, *t2, *t3).map(f64::to_radians);
    let q = model.full_pose(&theta);
    let camera = model.camera_position(&q).coords * 100.0;
    let joints_deg: Vec<f64> = q.iter().map(|v| v.to_degrees()).collect();
    if json {
        let value = serde_json::json!({ "camera_cm": [camera.x, camera.y, camera.z], "joints_deg": joints_deg });
        println!("{value}");
    } else {
        println!("camera_cm  {:.4} {:.4} {:.4}", camera.x, camera.y, camera.z);
        let text: Vec<String> = joints_deg.iter().map(|v| format!("{v:.4}")).collect();
        println!("joints_deg {}", text.join(" "));
        if let Some(joint) = model.violated_limit(&q) {
            println!("warning: joint {} is outside its limits", joint + 1);
        }
    }
    Ok(())
}
