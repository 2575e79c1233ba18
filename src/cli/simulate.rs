//! `eyehand simulate`: the dynamic arm run from a pose — servos off, holding it, or moving
//! it to another — printing the joint angles and speeds every tick, to hold the simulator
//! against another engine.

use super::{angles_in_range, bad_input, failed, warned, Failure};
use crate::experiment::setup::{dynamic_settings, load_arm};
use crate::experiment::shown;
use crate::robot::{Drive, DynamicSettings, Energy, FreeArm, Joints};
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
    /// The start pose: every joint angle of the chain in degrees, q1,q2,… (as many as the
    /// arm has; a leading minus needs no `=`).
    #[arg(
        long,
        value_delimiter = ',',
        allow_hyphen_values = true,
        required = true
    )]
    from: Vec<f64>,
    /// Simulated time (s).
    #[arg(long)]
    duration: f64,
    /// Physics time step (s); default the config's `dt` (0.005).
    #[arg(long, allow_hyphen_values = true)]
    dt: Option<f64>,
    /// Servos off, no gravity feed-forward: the arm swings under its weight (the default).
    #[arg(long, conflicts_with = "hold")]
    passive: bool,
    /// The servos and the gravity feed-forward hold the start pose.
    #[arg(long)]
    hold: bool,
    /// A servoed move: every joint from `--from` to these angles (degrees, q1,q2,…, as
    /// many as the arm has) along the straight joint-space line, under the trapezoidal
    /// profile of the config's `robot_speed` and `robot_accel` for the joint with the
    /// farthest to go, with its velocity and acceleration fed forward; then held there.
    #[arg(
        long,
        value_delimiter = ',',
        allow_hyphen_values = true,
        conflicts_with_all = ["hold", "passive"]
    )]
    to: Option<Vec<f64>>,
    /// The joints turn past their URDF limits.
    #[arg(long)]
    no_limits: bool,
    /// No contacts: the links pass through the floor (by default at −22 cm, the config's
    /// `floor_z` default) and each other.
    #[arg(long)]
    no_contacts: bool,
    /// Adds the arm's energy to every tick (kinetic_J, potential_J, total_J: from the
    /// model's kinematics and masses, the potential zero at z = 0) and says on stderr how
    /// far the total drifted from the start.
    #[arg(long)]
    energy: bool,
    /// Adds the torque each joint took in the tick (tau1_Nm..tauN_Nm: the model's inverse
    /// dynamics at the tick's start with its change of speed; servos, feed-forward,
    /// damping and friction together; 0 at the start).
    #[arg(long)]
    torques: bool,
    /// Prints one JSON document: {"dt_s", "ticks": [{"t_s", "joints_deg", "speeds_deg_s"}]}
    /// (with `--energy`, each tick's "kinetic_J", "potential_J", "total_J"; with
    /// `--torques`, "torques_Nm").
    #[arg(long, conflicts_with = "csv")]
    json: bool,
    /// Prints CSV: t_s, q1_deg..qN_deg, v1_deg_s..vN_deg_s (then kinetic_J, potential_J,
    /// total_J with `--energy`, tau1_Nm..tauN_Nm with `--torques`).
    #[arg(long)]
    csv: bool,
    #[command(flatten)]
    arm: super::reach::ArmConfigArgs,
}

pub(super) fn simulate(args: SimulateArgs) -> Result<(), Failure> {
    let config = args.arm.config()?;
    let model = warned(load_arm(&config, args.urdf.as_deref()).map_err(bad_input)?);
    let dt = args.dt.unwrap_or(config.dt);
    let ticks = check(&args, model.joints().len(), dt)?;
    let start = Joints::from_slice(&args.from).map(f64::to_radians);
    let drive = match &args.to {
        Some(goal) => Drive::MoveTo(Joints::from_slice(goal).map(f64::to_radians)),
        None if args.hold => Drive::Hold,
        None => Drive::Passive,
    };
    let settings = DynamicSettings {
        dt,
        ..dynamic_settings(&config)
    };
    let joints = model.joints().len();
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
    // Writes a tick, and gives back the energy it wrote (with `--energy`).
    let write = |out: &mut dyn Write,
                 arm: &FreeArm,
                 first: bool|
     -> std::io::Result<Option<Energy>> {
        let (q, v) = (arm.joints(), arm.speeds());
        let deg = |x: &Joints| x.iter().map(|a| a.to_degrees()).collect::<Vec<_>>();
        let energy = args.energy.then(|| arm.energy());
        let joules = energy.map(|e| [e.kinetic, e.potential, e.total()]);
        let torques = args.torques.then(|| arm.torques());
        if args.json {
            let mut tick = serde_json::json!({"t_s": arm.time(), "joints_deg": deg(&q), "speeds_deg_s": deg(&v)});
            if let Some([kinetic, potential, total]) = joules {
                tick["kinetic_J"] = kinetic.into();
                tick["potential_J"] = potential.into();
                tick["total_J"] = total.into();
            }
            if let Some(torques) = &torques {
                tick["torques_Nm"] = torques.iter().copied().collect::<Vec<f64>>().into();
            }
            write!(out, "{}{tick}", if first { "" } else { "," })?;
        } else {
            let sep = if args.csv { "," } else { " " };
            let values: Vec<String> = std::iter::once(arm.time())
                .chain(deg(&q))
                .chain(deg(&v))
                .chain(joules.into_iter().flatten())
                .chain(torques.iter().flat_map(|t| t.iter().copied()))
                .map(|x| format!("{x:.9}"))
                .collect();
            writeln!(out, "{}", values.join(sep))?;
        }
        Ok(energy)
    };
    let header = if args.json {
        format!("{{\"dt_s\":{dt},\"ticks\":[")
    } else {
        let names = ["t_s"]
            .into_iter()
            .map(String::from)
            .chain((1..=joints).map(|i| format!("q{i}_deg")))
            .chain((1..=joints).map(|i| format!("v{i}_deg_s")))
            .chain(
                ["kinetic_J", "potential_J", "total_J"]
                    .into_iter()
                    .filter(|_| args.energy)
                    .map(String::from),
            )
            .chain(
                (1..=joints)
                    .filter(|_| args.torques)
                    .map(|i| format!("tau{i}_Nm")),
            )
            .collect::<Vec<_>>();
        format!("{}\n", names.join(if args.csv { "," } else { " " }))
    };
    let printed = (|| {
        write!(out, "{header}")?;
        let start = write(&mut out, &arm, true)?;
        let (mut last, mut peak_kinetic) = (start, 0.0f64);
        for _ in 0..ticks {
            arm.step();
            last = write(&mut out, &arm, false)?;
            peak_kinetic = last.map_or(peak_kinetic, |e| peak_kinetic.max(e.kinetic));
        }
        if args.json {
            writeln!(out, "]}}")?;
        }
        out.flush()?;
        Ok(start
            .zip(last)
            .map(|(s, e)| (e.total() - s.total(), peak_kinetic)))
    })();
    let drift =
        printed.map_err(|e: std::io::Error| failed(format!("cannot write the ticks: {e}")))?;
    if let Some((drift, peak_kinetic)) = drift {
        eprintln!("{}", energy_drift_line(drift, peak_kinetic, arm.time()));
    }
    Ok(())
}

/// How far the total energy drifted (J) over a run of `seconds` in which the kinetic
/// energy reached at most `peak_kinetic` (J): the drift's measure, the potential energy
/// having no natural zero.
fn energy_drift_line(drift: f64, peak_kinetic: f64, seconds: f64) -> String {
    let share = if peak_kinetic > 0.0 {
        format!("{:+.3}%", 100.0 * drift / peak_kinetic)
    } else {
        "-".to_string()
    };
    format!(
        "energy: the total drifted {drift:+.6} J in {seconds} s ({share} of the largest \
         kinetic energy, {peak_kinetic:.6} J)"
    )
}

/// Checks the numbers before any work, for an arm of `joints` joints stepped by `dt`: the
/// ticks to run.
fn check(args: &SimulateArgs, joints: usize, dt: f64) -> Result<u64, Failure> {
    let poses =
        std::iter::once(("--from", &args.from)).chain(args.to.iter().map(|to| ("--to", to)));
    for (flag, pose) in poses {
        if pose.len() != joints {
            return Err(bad_input(format!(
                "{flag} takes {joints} joint angles in degrees (one per joint of this \
                 arm: q1,..,q{joints}), not {}",
                pose.len()
            )));
        }
        angles_in_range(flag, "q", pose)?;
    }
    if !(dt >= DT_RANGE.0 && dt <= DT_RANGE.1) {
        return Err(bad_input(format!(
            "--dt {dt:e} s is outside [{:e}, {:e}] s",
            DT_RANGE.0, DT_RANGE.1
        )));
    }
    let ticks = (args.duration / dt).round();
    if !(1.0..=MAX_TICKS).contains(&ticks) {
        return Err(bad_input(format!(
            "--duration {} s must be from one tick to {MAX_TICKS} ticks of {dt} s",
            shown(&args.duration.to_string())
        )));
    }
    Ok(ticks as u64)
}
