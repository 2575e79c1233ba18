//! Robot descriptions from real URDFs: how long the OSCAR-6, the Franka Panda (meshes and
//! hulls) and the UR-style arm take to load, and how long the chain's forward kinematics
//! of the camera pose takes per call, next to `ArmModel`'s for the OSCAR-6. Prints the
//! markdown table of docs/ARMS.md.
//!
//! `cargo bench --bench arms` (20 loads, 1,000,000 poses per row, seed 1).

use eyehand::robot::description::{Chain, DescriptionOptions, RobotDescription};
use eyehand::robot::{ArmModel, Joints};
use nalgebra::Isometry3;
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use std::f64::consts::PI;
use std::hint::black_box;
use std::path::PathBuf;
use std::time::Instant;

const LOADS: u32 = 20;
const CALLS: usize = 1_000_000;
const SEED: u64 = 1;

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
}
