//! Robot descriptions from real URDFs: how long the OSCAR-6, the Franka Panda (meshes and
//! hulls) and the UR-style arm take to load, and how long the chain's forward kinematics
//! of the camera pose takes per call, next to `ArmModel`'s for the OSCAR-6. Prints the
//! markdown table of docs/ARMS.md. Then each arm as an `ArmModel` (its wrist solved):
//! the reach space, a pose with the wrist solved, and lin5 run for 20,000 trials on the
//! kinematic simulator (seed 1): the second table of docs/ARMS.md. Last, lin5 for 2,000
//! trials on the dynamic simulator per arm (seed 1): the third table.
//!
//! `cargo bench --bench arms` (20 loads, 1,000,000 poses per row, seed 1).

use eyehand::experiment::setup::{load_arm, reach_space};
use eyehand::experiment::{reachable_points, run, Config, RunOptions, RunSummary, REACH_SAMPLES};
use eyehand::robot::description::{Chain, DescriptionOptions, RobotDescription};
use eyehand::robot::{ArmModel, Controlled, Joints};
use nalgebra::Isometry3;
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use std::f64::consts::PI;
use std::hint::black_box;
use std::path::PathBuf;
use std::time::Instant;

#[path = "../tests/common/test_arms.rs"]
mod test_arms;

use test_arms::{TestArm, PANDA, UR_STYLE};

const LOADS: u32 = 20;
const CALLS: usize = 1_000_000;
const SEED: u64 = 1;
/// Trials of each lin5 run.
const TRIALS: usize = 20_000;
/// Poses per wrist-solving row.
const POSES: usize = 200_000;
/// Trials of each lin5 run on the dynamic simulator.
const DYNAMIC_TRIALS: usize = 2_000;

/// The arms of the second and third tables: the shipped OSCAR-6 at the defaults (`None`),
/// and the test data's Panda and UR-style arm.
const LEARNING_ARMS: [(&str, Option<TestArm>); 3] = [
    ("oscar6 (defaults)", None),
    ("panda", Some(PANDA)),
    ("ur_style", Some(UR_STYLE)),
];

/// Nanoseconds per pose with the wrist solved, along a path of small steps (each pose
/// warm-started from the last), and from rest.
fn wrist_costs(model: &ArmModel) -> (f64, f64) {
    let start = model.controlled_of(&model.rest());
    let mut theta = start;
    let mut near = model.pose_of(&theta).joints;
    let path_start = Instant::now();
    for k in 0..POSES {
        let phase = k as f64 * 1e-3;
        theta = start + Controlled::new(0.3 * phase.sin(), 0.2 * phase.cos(), 0.2 * phase.sin());
        near = black_box(model.pose_near(&theta, &near)).joints;
    }
    let path = path_start.elapsed().as_nanos() as f64 / POSES as f64;
    let rest_start = Instant::now();
    for k in 0..POSES {
        let phase = k as f64 * 1e-3;
        theta = start + Controlled::new(0.3 * phase.sin(), 0.2 * phase.cos(), 0.2 * phase.sin());
        black_box(model.pose_of(&theta));
    }
    (path, rest_start.elapsed().as_nanos() as f64 / POSES as f64)
}

/// `arm`'s config for a run of `trials` lin5 trials (seed 1) on simulator `sim`, and its
/// URDF.
fn arm_config(arm: Option<&TestArm>, trials: usize, sim: &str) -> (Config, Option<PathBuf>) {
    let mut config = Config::default_config();
    for (name, value) in arm.map(TestArm::sets).unwrap_or_default() {
        config.assign(name, &value).expect("a valid entry");
    }
    config.assign("sim", sim).expect("a valid entry");
    config.trials = trials;
    config.seed = SEED;
    config.check().expect("a valid config");
    (config, arm.map(TestArm::urdf))
}

/// The run's mean distances after steps 1..5 (mm), as a table cell.
fn mean_distances(summary: &RunSummary) -> String {
    let means: Vec<String> = summary
        .mean_distance_mm
        .iter()
        .map(|m| m.map_or("-".into(), |m| format!("{m:.3}")))
        .collect();
    means.join(" / ")
}

/// The second table: each arm's reach space, wrist cost and lin5 run.
fn learning_table() {
    println!();
    println!("| arm | joints | wrist | reach space r, z (cm) | covered | pose, warm (ns) | pose, from rest (ns) | lin5 mean distance after steps 1..5 (mm) | failures | trials/s |");
    println!("|---|---|---|---|---|---|---|---|---|---|");
    let data = tempfile::tempdir().expect("a scratch folder");
    for (name, arm) in LEARNING_ARMS {
        let (config, urdf) = arm_config(arm.as_ref(), TRIALS, "kinematic");
        let mut model = load_arm(&config, urdf.as_deref())
            .expect("the arm loads")
            .model;
        let reach = reach_space(&config, &mut model).expect("a reach space");
        let covered = reachable_points(&model, &reach, REACH_SAMPLES) as f64 / REACH_SAMPLES as f64;
        let (warm, cold) = wrist_costs(&model);
        let wrist = match *model.wrist() {
            eyehand::robot::Wrist::OneJoint(_) => "1 joint, closed form".to_string(),
            eyehand::robot::Wrist::Numerical { count, .. } => format!("{count} joints, Newton"),
            eyehand::robot::Wrist::None => "none".to_string(),
        };
        let options = RunOptions {
            urdf,
            ..RunOptions::new(config, data.path())
        };
        let result = run(&options).expect("the run runs");
        let summary = &result.summary;
        println!(
            "| {} | {} | {wrist} | {:.1}–{:.1}, {:.1}–{:.1} | {:.1}% | {warm:.0} | {cold:.0} | {} | {} | {:.0} |",
            name,
            model.dof(),
            reach.r_min * 100.0,
            reach.r_max * 100.0,
            reach.z_min * 100.0,
            reach.z_max * 100.0,
            covered * 100.0,
            mean_distances(summary),
            summary.failures,
            summary.trials_per_second
        );
    }
}

/// The third table: each arm on the dynamic simulator, lin5 for `DYNAMIC_TRIALS` trials.
fn dynamic_table() {
    println!();
    println!("| arm | lin5 mean distance after steps 1..5 (mm) | failures | trials/s | physics steps/trial | settle time-outs | contact stops |");
    println!("|---|---|---|---|---|---|---|");
    let data = tempfile::tempdir().expect("a scratch folder");
    for (name, arm) in LEARNING_ARMS {
        let (config, urdf) = arm_config(arm.as_ref(), DYNAMIC_TRIALS, "dynamic");
        let options = RunOptions {
            urdf,
            ..RunOptions::new(config, data.path())
        };
        let summary = run(&options).expect("the run runs").summary;
        println!(
            "| {} | {} | {} | {:.0} | {:.1} | {} | {} |",
            name,
            mean_distances(&summary),
            summary.failures,
            summary.trials_per_second,
            summary.physics_steps_per_trial,
            summary.settle_timeouts,
            summary.stopped_by_contact
        );
    }
}

/// 1,024 random joint vectors inside the chain's limits (±π where unlimited), flattened.
fn poses(chain: &Chain) -> Vec<f64> {
    let mut rng = ChaCha8Rng::seed_from_u64(SEED);
    (0..1024)
        .flat_map(|_| {
            chain
                .joints
                .iter()
                .map(|j| rng.random_range(j.limits.lower.max(-PI)..=j.limits.upper.min(PI)))
                .collect::<Vec<_>>()
        })
        .collect()
}

/// Mean nanoseconds per call of `pose` over `CALLS` calls cycling through `poses`.
fn per_call(poses: &[f64], joints: usize, pose: impl Fn(&[f64]) -> Isometry3<f64>) -> f64 {
    let start = Instant::now();
    let mut sum = 0.0;
    for q in poses.chunks_exact(joints).cycle().take(CALLS) {
        sum += pose(black_box(q)).translation.x;
    }
    black_box(sum);
    start.elapsed().as_nanos() as f64 / CALLS as f64
}

fn main() {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    println!("| arm | camera link | moving joints | bodies | load (ms) | camera FK (ns/call) |");
    println!("|---|---|---|---|---|---|");
    for (file, camera_link) in [
        ("urdf/oscar6.urdf", "camera_link"),
        ("tests/data/panda/panda.urdf", "panda_hand"),
        ("tests/data/ur_style.urdf", "tool0"),
    ] {
        let path = root.join(file);
        let start = Instant::now();
        for _ in 0..LOADS {
            black_box(
                RobotDescription::load(&path, &DescriptionOptions::default()).expect("loads"),
            );
        }
        let load_ms = start.elapsed().as_secs_f64() * 1e3 / LOADS as f64;
        let description =
            RobotDescription::load(&path, &DescriptionOptions::default()).expect("loads");
        let chain = Chain::new(&description, camera_link).expect("a chain");
        let mount = Isometry3::identity();
        let n = chain.joints.len();
        let ns = per_call(&poses(&chain), n, |q| {
            chain.camera_pose(q, &mount).expect("n joints")
        });
        println!(
            "| {} | `{camera_link}` | {n} | {} | {load_ms:.2} | {ns:.0} |",
            description.name,
            chain.bodies.len()
        );
        if file.starts_with("urdf/") {
            let model = ArmModel::oscar6();
            let ns = per_call(&poses(&chain), n, |q| {
                model.camera_pose(&Joints::from_slice(q))
            });
            println!("| oscar6 (`ArmModel`) | `camera_link` | 6 | - | - | {ns:.0} |");
        }
    }
    learning_table();
    dynamic_table();
}
