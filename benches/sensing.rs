//! Realistic sensing, measured: lin5 and ik under sensor noise, lin5 with the ray-cast
//! camera beside the projection, and what a camera read costs. Prints the markdown tables
//! of docs/SENSING.md.
//!
//! `cargo bench --bench sensing [-- reads]` (`reads`: the read costs alone; kinematic simulator, 20,000 trials per run, seed 1; the
//! distances are means over the last 1,000 trials).
//!
//! Noise levels: `camera_noise_px` σ, with `camera_area_noise` = σ / 12.8 (the relative area
//! error of a reference blob, radius 25.6 px, whose radius is off by σ px) and
//! `joint_noise_deg` = 0.045·σ (an encoder error that moves the image by about σ px: 1 px is
//! 0.78 mm at the 20 cm standoff, 0.045° at about 1 m of reach).

use eyehand::camera::{Camera, CameraModel, ProjectionCamera, RaycastCamera};
mod common;

use common::run_in_process;
use eyehand::experiment::{CameraKind, Config, RunSummary};
use eyehand::learn::Method;
use eyehand::robot::{
    ArmModel, ArmSettings, DescriptionOptions, KinematicSim, MoveSettings, Obstacle, ReachSpace,
    RobotDescription, Simulator,
};
use nalgebra::{Isometry3, Point3, Translation3, UnitQuaternion, Vector3};
use std::time::Instant;

const TRIALS: usize = 20_000;
const SEED: u64 = 1;

fn config(method: Method) -> Config {
    let mut config = Config::default_config();
    config.method = method;
    config.trials = TRIALS;
    config.seed = SEED;
    config
}

fn distances(summary: &RunSummary) -> String {
    summary
        .mean_distance_mm
        .iter()
        .map(|&d| common::mm(d))
        .collect::<Vec<_>>()
        .join(" | ")
}

fn noise_table() {
    println!("| camera_noise_px | method | 1 | 2 | 3 | 4 | 5 | lin5 4-step / ik 4-step |");
    println!("|---|---|---|---|---|---|---|---|");
    for sigma in [0.0, 0.1, 0.25, 0.5, 1.0] {
        let noisy = |method| {
            let mut config = config(method);
            config.camera_noise_px = sigma;
            config.camera_area_noise = sigma / 12.8;
            config.joint_noise_deg = 0.045 * sigma;
            run_in_process(config)
        };
        let (lin5, ik) = (noisy(Method::Lin5), noisy(Method::Ik));
        let ratio = match (lin5.mean_distance_mm[3], ik.mean_distance_mm[3]) {
            (Some(a), Some(b)) if b > 1e-6 => format!("{:.2}", a / b),
            _ => "-".into(),
        };
        println!("| {sigma} | ik | {} | |", distances(&ik));
        println!("| {sigma} | lin5 | {} | {ratio} |", distances(&lin5));
    }
}

fn raycast_table() {
    println!("| camera | trials/s | 1 | 2 | 3 | 4 | 5 | failures |");
    println!("|---|---|---|---|---|---|---|---|");
    for (label, kind, resolution) in [
        ("projection", CameraKind::Projection, 256),
        ("raycast 256", CameraKind::Raycast, 256),
        ("raycast 512", CameraKind::Raycast, 512),
    ] {
        let mut config = config(Method::Lin5);
        config.camera = kind;
        config.raycast_resolution = resolution;
        let summary = run_in_process(config);
        println!(
            "| {label} | {:.0} | {} | {} |",
            summary.trials_per_second,
            distances(&summary),
            summary.failures
        );
    }
}

/// Microseconds per read of `camera` at the target and around it.
fn micros_per_read(camera: &dyn Camera) -> f64 {
    let points = [
        Vector3::new(0.0, 0.0, 0.2),
        Vector3::new(0.02, -0.01, 0.25),
        Vector3::new(-0.05, 0.04, 0.4),
    ];
    let reads = 3_000;
    let started = Instant::now();
    let mut sink = 0.0;
    for k in 0..reads {
        sink += camera.read_local(&points[k % 3]).map_or(0.0, |c| c.x);
    }
    std::hint::black_box(sink);
    started.elapsed().as_secs_f64() * 1e6 / reads as f64
}

/// Microseconds per read of `camera` in the world of `sim` (the world lent anew for each
/// read, as the trial loop does), looking from the arm's camera at `objects` in turn.
fn micros_per_read_in(camera: &dyn Camera, sim: &KinematicSim, objects: &[Point3<f64>]) -> f64 {
    micros_per_read_from(camera, sim, &sim.camera_pose(), objects)
}

/// Microseconds per read of `camera` at `pose` in the world of `sim`, looking at `objects`
/// in turn.
fn micros_per_read_from(
    camera: &dyn Camera,
    sim: &KinematicSim,
    pose: &Isometry3<f64>,
    objects: &[Point3<f64>],
) -> f64 {
    let reads = 3_000;
    let started = Instant::now();
    let mut sink = 0.0;
    for k in 0..reads {
        let object = &objects[k % objects.len()];
        sink += camera
            .read_in(pose, object, &sim.world())
            .map_or(0.0, |c| c.x);
    }
    std::hint::black_box(sink);
    started.elapsed().as_secs_f64() * 1e6 / reads as f64
}

/// The read costs in the world: the arm, the floor and, for the last rows, a box that hides
/// the left part of the target.
fn world_read_rows(model: CameraModel) {
    let arm = ArmModel::oscar6();
    let centre = Point3::new(0.7, 0.1, 0.25);
    let theta = arm.solve_camera_position(&centre).expect("in reach");
    let mut sim = KinematicSim::new(arm, MoveSettings::from_degrees(90.0, 180.0));
    sim.place(&theta).expect("inside the limits");
    let at = sim.camera_pose().translation.vector;
    let below = |dx: f64, dy: f64, depth: f64| Point3::new(at.x + dx, at.y + dy, at.z - depth);
    let objects = [
        below(0.0, 0.0, 0.2),
        below(0.02, -0.01, 0.25),
        below(-0.05, 0.04, 0.4),
    ];
    let projection = ProjectionCamera::new(model);
    let rays = RaycastCamera::new(model, 256);
    println!(
        "| projection, in the world (arm, floor) | {:.2} |",
        micros_per_read_in(&projection, &sim, &objects)
    );
    println!(
        "| raycast 256, in the world (arm, floor) | {:.1} |",
        micros_per_read_in(&rays, &sim, &objects)
    );
    // A box 5 cm under the camera whose face passes just beside the optical axis.
    let half_hidden = [below(0.0, 0.0, 0.2)];
    let block = Obstacle {
        centre: Point3::new(at.x - 0.049, at.y, at.z - 0.1),
        size: Vector3::new(0.1, 0.1, 0.1),
    };
    let sim = sim.with_obstacles(vec![block]);
    println!(
        "| raycast 256, target partly hidden by a box | {:.1} |",
        micros_per_read_in(&rays, &sim, &half_hidden)
    );
}

/// The Panda of tests/data (camera on its hand; joints 1, 2 and 4 learned) at the
/// pre-learning pose of its fitted reach space.
fn panda_at_rest() -> KinematicSim {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/panda/panda.urdf");
    let description = RobotDescription::load(path.as_ref(), &DescriptionOptions::default())
        .expect("the Panda loads");
    let settings = ArmSettings {
        camera_link: "panda_hand".into(),
        camera_offset: Vector3::zeros(),
        learned_joints: ["panda_joint1", "panda_joint2", "panda_joint4"].into(),
        ..ArmSettings::default()
    };
    let mut arm = ArmModel::from_description(&description, &settings).expect("the Panda's arm");
    let fit = ReachSpace::fit(&arm, -0.22, 0.22).expect("a reach space");
    let space = fit.space;
    arm.keep_branch(fit.branch);
    let theta = arm
        .solve_camera_position(&space.prelearning_goal())
        .expect("in reach");
    let mut sim = KinematicSim::new(arm, MoveSettings::from_degrees(90.0, 180.0));
    sim.place(&theta).expect("inside the limits");
    sim
}

/// The read costs on the Panda, whose collision meshes the camera sees as triangles: its
/// own camera at the pre-learning pose (links behind the lens, as in a trial), and a camera
/// 30 cm beside its fourth link (the elbow) looking along +y at a target 30 cm behind it,
/// every ray near the target meeting the link's mesh.
fn panda_read_rows(model: CameraModel) {
    let sim = panda_at_rest();
    let rays = RaycastCamera::new(model, 256);
    let at = sim.camera_pose().translation.vector;
    let below = |depth: f64, dx: f64| Point3::new(at.x + dx, at.y, at.z - depth);
    let objects = [below(0.2, 0.0), below(0.25, 0.02), below(0.4, -0.05)];
    println!(
        "| raycast 256, Panda at its pre-learning pose (arm, floor) | {:.1} |",
        micros_per_read_in(&rays, &sim, &objects)
    );
    let world = sim.world();
    let (pose, shape) = world.bodies[4].expect("the Panda's link 4 has meshes");
    let aabb = shape.compute_aabb(&pose);
    let centre = (aabb.mins + aabb.maxs) * 0.5;
    let look_along_y =
        UnitQuaternion::rotation_between(&Vector3::z(), &Vector3::y()).expect("a quarter turn");
    let beside = Isometry3::from_parts(
        Translation3::new(centre.x, centre.y - 0.3, centre.z),
        look_along_y,
    );
    let behind = [Point3::new(centre.x, centre.y + 0.3, centre.z)];
    println!(
        "| raycast 256, Panda's link 4 mesh between camera and target | {:.1} |",
        micros_per_read_from(&rays, &sim, &beside, &behind)
    );
}

fn read_cost_table() {
    let model = CameraModel::default();
    println!("| camera | µs per read |");
    println!("|---|---|");
    println!(
        "| projection | {:.2} |",
        micros_per_read(&ProjectionCamera::new(model))
    );
    for resolution in [256, 512] {
        println!(
            "| raycast {resolution} | {:.1} |",
            micros_per_read(&RaycastCamera::new(model, resolution))
        );
        println!(
            "| raycast {resolution}, raycast_noise 0.05 | {:.1} |",
            micros_per_read(&RaycastCamera::new(model, resolution).with_pixel_noise(0.05, 1))
        );
    }
    world_read_rows(model);
    panda_read_rows(model);
}

fn main() {
    read_cost_table();
    if std::env::args().any(|a| a == "reads") {
        return;
    }
    println!();
    noise_table();
    println!();
    raycast_table();
}
