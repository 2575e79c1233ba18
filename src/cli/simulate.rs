//! `eyehand simulate`: the dynamic arm run free from a pose — servos off or holding it —
//! printing the joint angles and speeds every tick, to hold the simulator against another
//! engine.

use super::{bad_input, failed, Failure};
use crate::robot::{load_urdf, ArmModel, Drive, DynamicSettings, FreeArm, Joints};
use clap::Args;
use std::io::Write;
use std::path::PathBuf;

/// The shortest and longest time step accepted (s), as for the config's `dt`.
const DT_RANGE: (f64, f64) = (1e-5, 0.1);
/// The most ticks one command may print.
const MAX_TICKS: f64 = 1e7;

#[derive(Debug, Args)]
pub(super) struct SimulateArgs {
    /// The URDF (default: the shipped urdf/oscar6.urdf).
    #[arg(long)]
    urdf: Option<PathBuf>,
    /// The start pose: all six joint angles θ1..θ6 in degrees.
    #[arg(
        long,
        value_delimiter = ',',
        allow_negative_numbers = true,
        required = true
    )]
    from: Vec<f64>,
    /// Simulated time (s).
    #[arg(long)]
    duration: f64,
    /// Physics time step (s); default the dynamic simulator's 0.005.
    #[arg(long, default_value_t = DynamicSettings::default().dt)]
    dt: f64,
    /// Servos off, no gravity feed-forward: the arm swings under its weight (the default).
    #[arg(long, conflicts_with = "hold")]
    passive: bool,
    /// The servos and the gravity feed-forward hold the start pose.
    #[arg(long)]
    hold: bool,
    /// The joints turn past their URDF limits.
    #[arg(long)]
    no_limits: bool,
    /// No contacts: the links pass through the floor (by default at −22 cm, the config's
    /// `floor_z` default) and each other.
    #[arg(long)]
    no_contacts: bool,
    /// Prints one JSON document: {"dt_s", "ticks": [{"t_s", "joints_deg", "speeds_deg_s"}]}.
    #[arg(long, conflicts_with = "csv")]
    json: bool,
    /// Prints CSV: t_s, q1_deg..q6_deg, v1_deg_s..v6_deg_s.
    #[arg(long)]
    csv: bool,
}

pub(super) fn simulate(args: SimulateArgs) -> Result<(), Failure> {
    let ticks = check(&args)?;
    let model = match &args.urdf {
        Some(path) => load_urdf(path).map_err(bad_input)?,
        None => ArmModel::oscar6(),
    };
    let start = Joints::from_slice(&args.from).map(f64::to_radians);
    let drive = if args.hold {
        Drive::Hold
    } else {
        Drive::Passive
    };
    let settings = DynamicSettings {
        dt: args.dt,
        ..DynamicSettings::default()
    };
    let mut arm = FreeArm::new(
        model,
        &start,
        settings,
        drive,
        !args.no_limits,
        !args.no_contacts,
    )
    .map_err(bad_input)?;
    let mut out = std::io::BufWriter::new(std::io::stdout().lock());
    let write = |out: &mut dyn Write, arm: &FreeArm, first: bool| {
        let (q, v) = (arm.joints(), arm.speeds());
        let deg = |x: &Joints| x.iter().map(|a| a.to_degrees()).collect::<Vec<_>>();
        if args.json {
            let tick = serde_json::json!({"t_s": arm.time(), "joints_deg": deg(&q), "speeds_deg_s": deg(&v)});
            write!(out, "{}{tick}", if first { "" } else { "," })
        } else {
            let sep = if args.csv { "," } else { " " };
            let values: Vec<String> = std::iter::once(arm.time())
                .chain(deg(&q))
                .chain(deg(&v))
                .map(|x| format!("{x:.9}"))
                .collect();
            writeln!(out, "{}", values.join(sep))
        }
    };
    let header = if args.json {
        format!("{{\"dt_s\":{},\"ticks\":[", args.dt)
    } else {
        let names = ["t_s"]
            .into_iter()
            .map(String::from)
            .chain((1..=6).map(|i| format!("q{i}_deg")))
            .chain((1..=6).map(|i| format!("v{i}_deg_s")))
            .collect::<Vec<_>>();
        format!("{}\n", names.join(if args.csv { "," } else { " " }))
    };
    let printed = (|| {
        write!(out, "{header}")?;
        write(&mut out, &arm, true)?;
        for _ in 0..ticks {
            arm.step();
            write(&mut out, &arm, false)?;
        }
        if args.json {
            writeln!(out, "]}}")?;
        }
        out.flush()
    })();
    printed.map_err(|e| failed(format!("cannot write the ticks: {e}")))
}

/// Checks the numbers before any work: the ticks to run.
fn check(args: &SimulateArgs) -> Result<u64, Failure> {
    if args.from.len() != 6 || args.from.iter().any(|a| !a.is_finite()) {
        return Err(bad_input(
            "--from takes six finite joint angles in degrees: q1,q2,q3,q4,q5,q6",
        ));
    }
    if !(args.dt >= DT_RANGE.0 && args.dt <= DT_RANGE.1) {
        return Err(bad_input(format!(
            "--dt {:e} s is outside [{:e}, {:e}] s",
            args.dt, DT_RANGE.0, DT_RANGE.1
        )));
    }
    let ticks = (args.duration / args.dt).round();
    if !(args.duration > 0.0 && ticks <= MAX_TICKS) {
        return Err(bad_input(format!(
            "--duration {} s must be positive and at most {MAX_TICKS} ticks of {} s",
            args.duration, args.dt
        )));
    }
    Ok(ticks as u64)
}
