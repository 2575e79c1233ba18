//! The dynamic simulator on both engines (`rk4`, `rapier`), on the OSCAR-6 and the Panda
//! (configs/arms/panda.conf). Every run goes through `eyehand run`'s own door — a
//! `RunRequest`, its `RunSetup` and the run's trial driver — so each row is what
//! `eyehand run [--config configs/arms/panda.conf] --sim S --method M --trials N --seed 1
//! --set engine=E` gives: `ik` over 1,000 trials on the OSCAR-6 (what the servos and
//! settling cost in precision) and `lin5` over 2,000 on each arm — mean distance after
//! feedback steps 1..5 over the last tenth of the trials, trials per second, physics steps
//! per trial, settle time-outs, contact stops, steps with a joint beyond its velocity
//! limit, failures. Then the engines side by side on both arms: tick cost, where a dynamic
//! trial's time goes, each arm against MuJoCo (tests/data/mujoco_*): accelerations and
//! passive swings at 0.2 / 0.5 / 1 s (the OSCAR-6 and its held-out variants), servoed
//! moves (both arms) with their gaps at 0.2 / 0.5 / 1 s and settle ticks, and the energy
//! drift of a 20 s undamped swing. Prints markdown tables.
//!
//! `cargo bench --bench dynamic`

use eyehand::camera::{Camera, CameraModel, ProjectionCamera, RaycastCamera};
use eyehand::experiment::setup::dynamic_settings;
use eyehand::experiment::{run, Config, RunRequest, RunSummary, SimKind};
use eyehand::learn::Method;
use eyehand::robot::{ArmModel, DynamicSettings, DynamicSim, Engine, Joints, Simulator};
use nalgebra::{Point3, Vector3};
use std::path::PathBuf;
use std::time::Instant;

#[path = "../tests/mujoco/mod.rs"]
mod mujoco;
#[path = "../tests/common/test_arms.rs"]
mod test_arms;

const SEED: u64 = 1;
const IK_TRIALS: usize = 1_000;
const LIN5_TRIALS: usize = 2_000;
/// What a cell shows where no reference exists.
const NONE: &str = "–";

/// An arm the bench runs: its config, its model and its MuJoCo references.
struct BenchArm {
    name: &'static str,
    /// The config a run of it reads (none: the defaults, the OSCAR-6).
    config: Option<PathBuf>,
    model: ArmModel,
    /// The prefix of its servoed moves' references (tests/data/PREFIXmove_N.csv).
    prefix: &'static str,
    /// The joint its third servoed move stops on.
    limited: &'static str,
    /// Where its undamped swing starts (rad).
    swing_start: Joints,
}

fn arms() -> [BenchArm; 2] {
    let panda = test_arms::PANDA.model();
    let (panda_swing, _) = mujoco::move_ends("mujoco_panda_", 2, panda.dof());
    [
        BenchArm {
            name: "OSCAR-6",
            config: None,
            model: ArmModel::oscar6(),
            prefix: "mujoco_",
            limited: "joint 3",
            swing_start: mujoco::oscar6_swing_start(),
        },
        BenchArm {
            name: "Panda",
            config: Some(
                [env!("CARGO_MANIFEST_DIR"), "configs/arms/panda.conf"]
                    .iter()
                    .collect(),
            ),
            model: panda,
            prefix: "mujoco_panda_",
            limited: "joint 4",
            swing_start: panda_swing,
        },
    ]
}

/// The summary of `eyehand run` of `method` on `arm`'s config, simulator `sim`, `engine`,
/// `trials` trials, seed 1, into a scratch folder.
fn run_of(
    arm: &BenchArm,
    method: Method,
    sim: SimKind,
    engine: Engine,
    trials: usize,
) -> RunSummary {
    let data = tempfile::tempdir().expect("a scratch folder");
    let request = RunRequest {
        config: arm.config.clone(),
        sets: vec![("engine".into(), engine.to_string())],
        method: Some(method),
        sim: Some(sim),
        trials: Some(trials),
        seed: Some(SEED),
        data: data.path().to_path_buf(),
        plot: false,
        ..RunRequest::default()
    };
    let options = request.options().expect("a valid request");
    run(&options).expect("the run runs").summary
}

fn print_header(what: &str) {
    println!("\n{what}\n");
    println!("| run | trials/s | 1 | 2 | 3 | 4 | 5 | physics steps/trial | settle time-outs | contact stops | speed faults | failures |");
    println!("|---|---|---|---|---|---|---|---|---|---|---|---|");
}

fn print_row(label: &str, summary: &RunSummary) {
    let dynamic = summary.sim == "dynamic";
    let or_dash = |v: String| if dynamic { v } else { "-".into() };
    let means: Vec<String> = summary
        .mean_distance_mm
        .iter()
        .map(|d| d.map_or("-".into(), |d| format!("{d:.4}")))
        .collect();
    println!(
        "| {label} | {:.0} | {} | {} | {} | {} | {} | {} |",
        summary.trials_per_second,
        means.join(" | "),
        or_dash(format!("{:.0}", summary.physics_steps_per_trial)),
        or_dash(summary.settle_timeouts.to_string()),
        summary.stopped_by_contact,
        or_dash(summary.speed_faults.to_string()),
        summary.failures
    );
}

/// Microseconds per control tick of `arm` on `engine` (servos, one step, contact
/// detection), holding the start of its large servoed move.
fn micros_per_step(arm: &BenchArm, engine: Engine) -> f64 {
    let hold = DynamicSettings {
        engine,
        settle_position_tol: 1e-300,
        settle_speed_tol: 1e-300,
        settle_timeout: 5.0,
        ..dynamic_settings(&Config::default_config())
    };
    let (start, _) = mujoco::move_ends(arm.prefix, 2, arm.model.dof());
    let mut sim = DynamicSim::new(arm.model.clone(), hold);
    sim.place(&arm.model.controlled_of(&start))
        .expect("inside the limits");
    let counters = sim.counters();
    let steps = counters.steps();
    let started = Instant::now();
    sim.execute(&Default::default());
    started.elapsed().as_secs_f64() * 1e6 / (counters.steps() - steps) as f64
}

/// Microseconds per reading of `camera` at the target pose.
fn micros_per_read(camera: &dyn Camera) -> f64 {
    let object = Point3::new(0.6, 0.0, 0.0);
    let pose = nalgebra::Isometry3::new(
        Vector3::new(0.6, 0.0, 0.2),
        Vector3::y() * std::f64::consts::PI,
    );
    let reads = 20_000;
    let started = Instant::now();
    for k in 0..reads {
        let shifted = object + Vector3::x() * (k % 7) as f64 * 1e-3;
        std::hint::black_box(camera.read(&pose, &shifted).ok());
    }
    started.elapsed().as_secs_f64() * 1e6 / reads as f64
}

fn main() {
    let arms = arms();
    let oscar6 = &arms[0];
    print_header("`ik` on the OSCAR-6, 1,000 trials");
    let ik = run_of(
        oscar6,
        Method::Ik,
        SimKind::Kinematic,
        Engine::Rk4,
        IK_TRIALS,
    );
    print_row("ik kinematic", &ik);
    for engine in Engine::ALL {
        let summary = run_of(oscar6, Method::Ik, SimKind::Dynamic, engine, IK_TRIALS);
        print_row(&format!("ik dynamic {engine}"), &summary);
    }
    print_header("`lin5`, 2,000 trials");
    let lin5: Vec<RunSummary> = arms
        .iter()
        .flat_map(|arm| {
            let kinematic = run_of(
                arm,
                Method::Lin5,
                SimKind::Kinematic,
                Engine::Rk4,
                LIN5_TRIALS,
            );
            print_row(&format!("{} lin5 kinematic", arm.name), &kinematic);
            Engine::ALL.map(|engine| {
                let summary = run_of(arm, Method::Lin5, SimKind::Dynamic, engine, LIN5_TRIALS);
                print_row(&format!("{} lin5 dynamic {engine}", arm.name), &summary);
                summary
            })
        })
        .collect();
    println!(
        "\nmean distance (mm) after each feedback step over the last {} (ik) / {} (lin5) trials, seed {SEED}",
        ik.window, lin5[0].window
    );
    println!("\n| the engines side by side | OSCAR-6 rk4 | OSCAR-6 rapier | Panda rk4 | Panda rapier |\n|---|---|---|---|---|");
    let step: Vec<f64> = arms
        .iter()
        .flat_map(|arm| Engine::ALL.map(|engine| micros_per_step(arm, engine)))
        .collect();
    row(
        "control tick, holding a pose (µs)",
        step.iter().map(|s| format!("{s:.1}")).collect(),
    );
    row(
        "dynamic lin5 trials/s",
        lin5.iter()
            .map(|s| format!("{:.0}", s.trials_per_second))
            .collect(),
    );
    row(
        "dynamic lin5 wall time per trial / of it ticks × tick cost (ms)",
        lin5.iter()
            .zip(&step)
            .map(|(s, micros)| {
                let per_trial_ms = 1e3 / s.trials_per_second;
                let physics_ms = s.physics_steps_per_trial * micros * 1e-3;
                format!("{per_trial_ms:.2} / {physics_ms:.2}")
            })
            .collect(),
    );
    print_mujoco_comparison(&arms);
    let model = CameraModel::default();
    println!(
        "\ncamera read: projection / raycast 256² (bounded to the blob) / raycast 512²: {:.2} / {:.1} / {:.1} µs",
        micros_per_read(&ProjectionCamera::new(model)),
        micros_per_read(&RaycastCamera::new(model, 256)),
        micros_per_read(&RaycastCamera::new(model, 512)),
    );
}

/// A row of the engines' table: what, and its four figures (each arm on each engine).
fn row(what: &str, figures: Vec<String>) {
    println!("| {what} | {} |", figures.join(" | "));
}

/// The four cells of a row: the OSCAR-6's figure on each engine from `measure`, the
/// Panda's none (it has no such reference).
fn oscar6_only(measure: impl Fn(Engine) -> String) -> Vec<String> {
    let mut cells: Vec<String> = Engine::ALL.map(measure).to_vec();
    cells.extend([NONE.to_string(), NONE.to_string()]);
    cells
}

/// The four cells of a row: each arm's figure on each engine from `measure`.
fn every_arm(arms: &[BenchArm], measure: impl Fn(&BenchArm, Engine) -> String) -> Vec<String> {
    arms.iter()
        .flat_map(|arm| Engine::ALL.map(|engine| measure(arm, engine)))
        .collect()
}

/// Gaps (°) at 0.2, 0.5 and 1 s (– where the reference ends before).
fn at_three_times(gaps: &[(f64, f64)]) -> String {
    let at = |t: f64| {
        let gap = mujoco::gap_at(gaps, t);
        match gap.is_nan() {
            true => NONE.to_string(),
            false => format!("{gap:.1e}°"),
        }
    };
    format!("{} / {} / {}", at(0.2), at(0.5), at(1.0))
}

/// A servoed move's largest joint and camera differences and both arms' settle ticks.
fn move_figures(gaps: &mujoco::MoveGaps) -> String {
    format!(
        "{:.1e}° / {:.1e} mm, {} / {}",
        gaps.joints_deg(),
        gaps.camera_mm,
        gaps.settle_ticks.0,
        gaps.settle_ticks.1
    )
}

/// Each arm against MuJoCo 4.0 (RK4, 0.1 ms) on the same URDF, on both engines.
fn print_mujoco_comparison(arms: &[BenchArm]) {
    let worst = |gaps: Vec<(Joints, f64)>| gaps.iter().map(|g| g.1).fold(0.0, f64::max);
    let model = ArmModel::oscar6();
    for dt in [1e-4, 5e-3] {
        row(
            &format!(
                "OSCAR-6 accelerations from rest, 50 poses, one step of {} ms: largest relative difference",
                dt * 1e3
            ),
            oscar6_only(|engine| {
                let settings = mujoco::with_dt(dt, engine);
                let gaps = mujoco::acceleration_gaps(&model, "mujoco_accelerations.csv", 6, settings);
                format!("{:.1e}", worst(gaps))
            }),
        );
    }
    let mut long = model.clone();
    long.stretch_link(2, 0.1).expect("a valid stretch");
    row(
        "OSCAR-6 link 2 10 cm longer: accelerations (0.1 ms step), largest relative difference",
        oscar6_only(|engine| {
            let settings = mujoco::with_dt(1e-4, engine);
            let gaps = mujoco::acceleration_gaps(&long, "mujoco_stretched.csv", 12, settings);
            format!("{:.1e}", worst(gaps))
        }),
    );
    let swing = |file: &str, arm: &ArmModel, dt: f64| {
        oscar6_only(|engine| {
            at_three_times(&mujoco::swing_gaps_of(
                arm.clone(),
                file,
                mujoco::with_dt(dt, engine),
            ))
        })
    };
    for dt in [1e-3, 5e-3] {
        for n in 1..=3 {
            row(
                &format!(
                    "OSCAR-6 passive swing {n}, dt {} ms: apart at 0.2 / 0.5 / 1 s",
                    dt * 1e3
                ),
                swing(&format!("mujoco_swing_{n}.csv"), &model, dt),
            );
        }
    }
    for (name, arm) in mujoco::held_out_arms() {
        row(
            &format!("held-out OSCAR-6 `{name}`, passive swing, dt 5 ms: apart at 0.2 / 0.5 / 1 s"),
            swing(&format!("held_out/mujoco_swing_{name}.csv"), &arm, 5e-3),
        );
    }
    for (n, kind) in [(1, "small"), (2, "large"), (3, "onto a limit")] {
        let gaps = |arm: &BenchArm, engine| {
            mujoco::move_gaps(&arm.model, arm.prefix, n, mujoco::with_dt(5e-3, engine))
        };
        let limited = match n {
            3 => {
                let joints: Vec<String> = arms
                    .iter()
                    .map(|arm| format!("the {}'s {}", arm.name, arm.limited))
                    .collect();
                format!(": {}", joints.join(", "))
            }
            _ => String::new(),
        };
        row(
            &format!("servoed move {n} ({kind}{limited}), dt 5 ms: largest joint / camera difference, settle ticks ours / MuJoCo's"),
            every_arm(arms, |arm, engine| move_figures(&gaps(arm, engine))),
        );
        row(
            &format!("servoed move {n}, dt 5 ms: apart at 0.2 / 0.5 / 1 s"),
            every_arm(arms, |arm, engine| {
                at_three_times(&gaps(arm, engine).over_time)
            }),
        );
    }
    let (_, damped) = mujoco::held_out_arms()
        .into_iter()
        .find(|(name, _)| *name == "damped")
        .expect("the damped arm");
    let (start, goal) = mujoco::move_ends("mujoco_", 2, 6);
    row(
        "held-out OSCAR-6 `damped`, servoed move 2, dt 5 ms: largest joint / camera difference, settle ticks ours / MuJoCo's",
        oscar6_only(|engine| {
            let file = "held_out/mujoco_move_damped.csv";
            move_figures(&mujoco::trace_gaps(&damped, &start, &goal, file, mujoco::with_dt(5e-3, engine)))
        }),
    );
    row(
        "energy drift of a 20 s undamped swing, dt 5 ms (share of the peak kinetic energy)",
        every_arm(arms, |arm, engine| {
            let (change, peak) =
                mujoco::undamped_swing_energy(&arm.model, &arm.swing_start, engine);
            format!("{:+.3}%", 100.0 * change / peak)
        }),
    );
}
