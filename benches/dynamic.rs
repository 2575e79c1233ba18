//! The dynamic simulator on both engines (`rk4`, `rapier`) against the kinematic one,
//! seed 1, configs/lin5.conf: `ik` (what the servos and settling cost in precision) and
//! `lin5` over 5,000 trials — mean distance after feedback steps 1..5 over the last tenth
//! of the trials, trials per second, physics steps per trial (and how many of them
//! settle), settle time-outs, contact stops — then the engines side by side: tick cost,
//! where a dynamic trial's time goes, and each arm against MuJoCo (tests/data/mujoco_*):
//! accelerations, passive swings at 0.2 / 0.5 / 1 s, servoed moves of the OSCAR-6 and
//! the Panda with their settle ticks, and the energy drift of a 20 s undamped swing.
//! Prints markdown tables.
//!
//! `cargo bench --bench dynamic`

use eyehand::camera::{Camera, CameraModel, ProjectionCamera, RaycastCamera};
use eyehand::control::TrialLoop;
use eyehand::experiment::setup::{build_learner, dynamic_settings, trial_settings};
use eyehand::experiment::{Config, SimKind, StepFigures};
use eyehand::learn::Method;
use eyehand::robot::{
    ArmModel, Controlled, DynamicSettings, DynamicSim, Engine, KinematicSim, Simulator,
};
use nalgebra::{Point3, Vector3};
use std::time::Instant;

#[path = "../tests/mujoco/mod.rs"]
mod mujoco;
#[path = "../tests/common/test_arms.rs"]
mod test_arms;

const SEED: u64 = 1;
const IK_TRIALS: usize = 1_000;
const LIN5_TRIALS: usize = 5_000;

/// One run's figures.
struct Row {
    trials_per_second: f64,
    means: Vec<String>,
    steps_per_trial: Option<f64>,
    settle_steps_per_trial: Option<f64>,
    timeouts: Option<u64>,
    contact_stops: Option<u64>,
    failures: usize,
    window: usize,
}

fn trials(method: Method, sim: SimKind, engine: Engine, count: usize) -> Row {
    let mut config = Config::default_config();
    config.method = method;
    config.engine = engine;
    config.trials = count;
    config.seed = SEED;
    let model = ArmModel::oscar6();
    let (simulator, counters): (Box<dyn Simulator>, _) = match sim {
        SimKind::Kinematic => (
            Box::new(KinematicSim::new(
                model.clone(),
                dynamic_settings(&config).moves,
            )),
            None,
        ),
        SimKind::Dynamic => {
            let dynamic = DynamicSim::new(model.clone(), dynamic_settings(&config));
            let counters = dynamic.counters();
            (Box::new(dynamic), Some(counters))
        }
    };
    let settings = trial_settings(&config);
    let camera = Box::new(ProjectionCamera::new(CameraModel::default()));
    let mut learner = build_learner(&config, &model, None).expect("the learner builds");
    let mut loop_ = TrialLoop::new(simulator, camera, settings, SEED);
    let mut figures = StepFigures::new(count, 5);
    let mut failures = 0;
    let started = Instant::now();
    loop_.prelearn(learner.as_mut()).expect("pre-learning");
    let before = counters.as_ref().map_or(0, |c| c.steps());
    let settle_before = counters.as_ref().map_or(0, |c| c.settle_steps());
    for trial in 1..=count {
        let outcome = loop_.run_trial(learner.as_mut()).expect("a trial");
        failures += usize::from(outcome.failure.is_some());
        figures.record(trial, &outcome.distances_mm, None);
    }
    let seconds = started.elapsed().as_secs_f64();
    Row {
        trials_per_second: count as f64 / seconds,
        means: figures
            .means()
            .iter()
            .map(|d| d.map_or("-".into(), |d| format!("{d:.4}")))
            .collect(),
        steps_per_trial: counters
            .as_ref()
            .map(|c| (c.steps() - before) as f64 / count as f64),
        settle_steps_per_trial: counters
            .as_ref()
            .map(|c| (c.settle_steps() - settle_before) as f64 / count as f64),
        timeouts: counters.as_ref().map(|c| c.settle_timeouts()),
        contact_stops: counters.as_ref().map(|c| c.contact_stops()),
        failures,
        window: figures.window(),
    }
}

fn print_row(label: &str, row: &Row) {
    let or_dash = |v: Option<String>| v.unwrap_or_else(|| "-".into());
    println!(
        "| {label} | {:.0} | {} | {} | {} | {} | {} | {} |",
        row.trials_per_second,
        row.means.join(" | "),
        or_dash(row.steps_per_trial.map(|s| format!("{s:.0}"))),
        or_dash(row.settle_steps_per_trial.map(|s| format!("{s:.0}"))),
        or_dash(row.timeouts.map(|t| t.to_string())),
        or_dash(row.contact_stops.map(|t| t.to_string())),
        row.failures
    );
}

/// Microseconds per control tick on `engine` (servos, one step, contact detection) of the
/// arm holding an outstretched pose.
fn micros_per_step(engine: Engine) -> f64 {
    let hold = DynamicSettings {
        engine,
        settle_position_tol: 1e-300,
        settle_speed_tol: 1e-300,
        settle_timeout: 5.0,
        ..dynamic_settings(&Config::default_config())
    };
    let mut sim = DynamicSim::new(ArmModel::oscar6(), hold);
    sim.place(&Controlled::new(0.3, 0.2, 0.6))
        .expect("inside the limits");
    let counters = sim.counters();
    let steps = counters.steps();
    let started = Instant::now();
    sim.execute(&Controlled::zeros());
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
    let header = |what: &str| {
        println!("\n{what}\n");
        println!("| run | trials/s | 1 | 2 | 3 | 4 | 5 | physics steps/trial | of them settling | settle time-outs | contact stops | failures |");
        println!("|---|---|---|---|---|---|---|---|---|---|---|---|");
    };
    header("`ik`, 1,000 trials");
    let ik_kinematic = trials(Method::Ik, SimKind::Kinematic, Engine::Rk4, IK_TRIALS);
    print_row("ik kinematic", &ik_kinematic);
    for engine in Engine::ALL {
        let row = trials(Method::Ik, SimKind::Dynamic, engine, IK_TRIALS);
        print_row(&format!("ik dynamic {engine}"), &row);
    }
    header("`lin5`, 5,000 trials");
    print_row(
        "lin5 kinematic",
        &trials(Method::Lin5, SimKind::Kinematic, Engine::Rk4, LIN5_TRIALS),
    );
    let lin5 = Engine::ALL.map(|engine| {
        let row = trials(Method::Lin5, SimKind::Dynamic, engine, LIN5_TRIALS);
        print_row(&format!("lin5 dynamic {engine}"), &row);
        row
    });
    println!(
        "\nmean distance (mm) after each feedback step over the last {} (ik) / {} (lin5) trials, seed {SEED}",
        ik_kinematic.window, lin5[0].window
    );
    println!("\n| the engines side by side | rk4 | rapier |\n|---|---|---|");
    let step = Engine::ALL.map(micros_per_step);
    side_by_side(
        "control tick, holding a pose (µs)",
        step.map(|s| format!("{s:.1}")),
    );
    side_by_side(
        "dynamic lin5 trials/s",
        lin5.each_ref()
            .map(|row| format!("{:.0}", row.trials_per_second)),
    );
    side_by_side(
        "dynamic lin5 wall time per trial / of it ticks × tick cost (ms)",
        std::array::from_fn(|k| {
            let per_trial_ms = 1e3 / lin5[k].trials_per_second;
            let physics_ms = lin5[k].steps_per_trial.unwrap_or(0.0) * step[k] * 1e-3;
            format!("{per_trial_ms:.2} / {physics_ms:.2}")
        }),
    );
    print_mujoco_comparison();
    let model = CameraModel::default();
    println!(
        "\ncamera read: projection / raycast 256² (bounded to the blob) / raycast 512²: {:.2} / {:.1} / {:.1} µs",
        micros_per_read(&ProjectionCamera::new(model)),
        micros_per_read(&RaycastCamera::new(model, 256)),
        micros_per_read(&RaycastCamera::new(model, 512)),
    );
}

/// A row of the engines' table: what, and its figure on each engine.
fn side_by_side(what: &str, figures: [String; 2]) {
    println!("| {what} | {} | {} |", figures[0], figures[1]);
}

/// Each engine's figure from `measure`.
fn each(measure: impl Fn(Engine) -> String) -> [String; 2] {
    Engine::ALL.map(measure)
}

/// The relative energy drift of a 20 s undamped swing at 5 ms on `engine`, as a share of
/// its peak kinetic energy.
fn energy_drift(engine: Engine) -> f64 {
    let (change, peak) = mujoco::undamped_swing_energy(engine);
    change / peak
}

/// Each arm against MuJoCo 4.0 (RK4, 0.1 ms) on the same URDF, on both engines.
fn print_mujoco_comparison() {
    let worst =
        |gaps: Vec<(eyehand::robot::Joints, f64)>| gaps.iter().map(|g| g.1).fold(0.0, f64::max);
    let model = ArmModel::oscar6();
    for dt in [1e-4, 5e-3] {
        side_by_side(
            &format!(
                "accelerations from rest, 50 poses, one step of {} ms: largest relative difference",
                dt * 1e3
            ),
            each(|engine| {
                let settings = mujoco::with_dt(dt, engine);
                format!(
                    "{:.1e}",
                    worst(mujoco::acceleration_gaps(
                        &model,
                        "mujoco_accelerations.csv",
                        6,
                        settings
                    ))
                )
            }),
        );
    }
    let mut long = model.clone();
    long.stretch_link(2, 0.1).expect("a valid stretch");
    side_by_side(
        "link 2 10 cm longer: accelerations (0.1 ms step), largest relative difference",
        each(|engine| {
            let settings = mujoco::with_dt(1e-4, engine);
            format!(
                "{:.1e}",
                worst(mujoco::acceleration_gaps(
                    &long,
                    "mujoco_stretched.csv",
                    12,
                    settings
                ))
            )
        }),
    );
    let apart = |file: &str, arm: &ArmModel, dt: f64| {
        each(|engine| {
            let gaps = mujoco::swing_gaps_of(arm.clone(), file, mujoco::with_dt(dt, engine));
            format!(
                "{:.1e}° / {:.1e}° / {:.1e}°",
                mujoco::gap_at(&gaps, 0.2),
                mujoco::gap_at(&gaps, 0.5),
                mujoco::gap_at(&gaps, 1.0)
            )
        })
    };
    for dt in [1e-3, 5e-3] {
        for n in 1..=3 {
            side_by_side(
                &format!(
                    "OSCAR-6 passive swing {n}, dt {} ms: apart at 0.2 / 0.5 / 1 s",
                    dt * 1e3
                ),
                apart(&format!("mujoco_swing_{n}.csv"), &model, dt),
            );
        }
    }
    for (name, arm) in mujoco::held_out_arms() {
        side_by_side(
            &format!("held-out OSCAR-6 `{name}`, passive swing, dt 5 ms: apart at 0.2 / 0.5 / 1 s"),
            apart(&format!("held_out/mujoco_swing_{name}.csv"), &arm, 5e-3),
        );
    }
    let arms = [
        ("OSCAR-6", model.clone(), "mujoco_", "joint 3"),
        (
            "Panda",
            test_arms::PANDA.model(),
            "mujoco_panda_",
            "joint 4",
        ),
    ];
    for (arm, model, prefix, limited) in arms {
        for (n, kind) in [(1, "small"), (2, "large"), (3, "onto a limit")] {
            side_by_side(
                &format!(
                    "{arm} servoed move {n} ({kind}{}), dt 5 ms: largest joint / camera difference, settle ticks ours / MuJoCo's",
                    if n == 3 { format!(": {limited}") } else { String::new() }
                ),
                each(|engine| {
                    let gaps = mujoco::move_gaps(&model, prefix, n, mujoco::with_dt(5e-3, engine));
                    format!(
                        "{:.1e}° / {:.1e} mm, {} / {}",
                        gaps.joints_deg, gaps.camera_mm, gaps.settle_ticks.0, gaps.settle_ticks.1
                    )
                }),
            );
        }
    }
    let (_, damped) = mujoco::held_out_arms()
        .into_iter()
        .find(|(name, _)| *name == "damped")
        .expect("the damped arm");
    let (start, goal) = mujoco::move_ends("mujoco_", 2, 6);
    side_by_side(
        "held-out OSCAR-6 `damped`, servoed move 2, dt 5 ms: largest joint / camera difference, settle ticks ours / MuJoCo's",
        each(|engine| {
            let file = "held_out/mujoco_move_damped.csv";
            let gaps = mujoco::trace_gaps(&damped, &start, &goal, file, mujoco::with_dt(5e-3, engine));
            format!(
                "{:.1e}° / {:.1e} mm, {} / {}",
                gaps.joints_deg, gaps.camera_mm, gaps.settle_ticks.0, gaps.settle_ticks.1
            )
        }),
    );
    side_by_side(
        "energy drift of a 20 s undamped swing, dt 5 ms (share of the peak kinetic energy)",
        each(|engine| format!("{:+.3}%", 100.0 * energy_drift(engine))),
    );
}
