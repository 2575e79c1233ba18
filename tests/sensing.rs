//! Realistic sensing: the ray-cast camera measures to a twentieth of a pixel from the arm's
//! real poses, and noisy sensors keep runs reproducible.

use eyehand::camera::{Camera, CameraModel, ProjectionCamera, RaycastCamera};
use eyehand::experiment::{run, Config, RunOptions};
use eyehand::learn::Method;
use eyehand::robot::{ArmModel, Controlled};
use nalgebra::Vector3;
use std::path::Path;

#[test]
fn the_coverage_camera_matches_the_projection_over_a_grid_of_arm_poses() {
    let model = ArmModel::oscar6();
    let cameras = (
        RaycastCamera::new(CameraModel::default(), 256),
        ProjectionCamera::new(CameraModel::default()),
    );
    let object_below = |theta: &Controlled, offset: Vector3<f64>| {
        let pose = model.full_pose(theta);
        (
            model.camera_pose(&pose),
            model.camera_position(&pose) + offset,
        )
    };
    let mut compared = 0;
    for theta2 in [0.0_f64, 20.0, 45.0, 65.0] {
        for theta3 in [60.0_f64, 90.0, 120.0] {
            let theta = Controlled::new(0.3, theta2.to_radians(), theta3.to_radians());
            for offset in [
                Vector3::new(0.0, 0.0, -0.2),
                Vector3::new(0.03, -0.02, -0.25),
                Vector3::new(-0.06, 0.05, -0.35),
                Vector3::new(0.01, 0.04, -0.12),
            ] {
                let (pose, object) = object_below(&theta, offset);
                let exact = cameras.1.read(&pose, &object).unwrap();
                let area = cameras.1.model().area_from_cz(exact.z);
                let diameter = 2.0 * (area / std::f64::consts::PI).sqrt();
                if diameter < 20.0 {
                    continue;
                }
                let measured = cameras.0.read(&pose, &object).unwrap();
                let off = (measured - exact).xy().amax();
                assert!(
                    off <= 0.05,
                    "θ2 {theta2}°, θ3 {theta3}°, {offset}: {off} px"
                );
                compared += 1;
            }
        }
    }
    assert!(compared >= 40, "{compared} poses compared");
}

fn noisy_run(data: &Path, seed: u64, noise_px: f64) -> eyehand::experiment::RunResult {
    let mut config = Config::default_config();
    config.method = Method::Ik;
    config.trials = 150;
    config.seed = seed;
    config.camera_noise_px = noise_px;
    config.camera_area_noise = noise_px / 100.0;
    config.joint_noise_deg = noise_px / 10.0;
    run(&RunOptions::new(config, data)).unwrap()
}

#[test]
fn noisy_sensors_give_the_same_bytes_for_the_same_seed() {
    let (a, b, c) = (
        tempfile::tempdir().unwrap(),
        tempfile::tempdir().unwrap(),
        tempfile::tempdir().unwrap(),
    );
    let first = noisy_run(a.path(), 4, 0.5);
    let second = noisy_run(b.path(), 4, 0.5);
    let exact = noisy_run(c.path(), 4, 0.0);
    let read = |folder: &Path, name: &str| -> Vec<String> {
        let text = std::fs::read_to_string(folder.join(name)).unwrap();
        // Without the minutes column.
        text.lines()
            .map(|l| l.rsplit_once(' ').unwrap().0.to_string())
            .collect()
    };
    for name in ["1step", "2step", "5step"] {
        assert_eq!(
            read(&first.folder, name),
            read(&second.folder, name),
            "{name}"
        );
    }
    assert_ne!(read(&first.folder, "1step"), read(&exact.folder, "1step"));
    // ik on exact sensors lands in one step; with noise it cannot, but stays close.
    let noisy = first.summary.mean_distance_mm;
    let clean = exact.summary.mean_distance_mm;
    assert!(clean[0].unwrap() < 1e-6, "{clean:?}");
    assert!(
        noisy[0].unwrap() > 0.01 && noisy[4].unwrap() < 5.0,
        "{noisy:?}"
    );
}
