//! The projection camera: readings at and around the target, turned cameras, objects not
//! seen, agreement with a brute-force image of the sphere, and the inverse used by `ik`.

use eyehand::camera::{Camera, CameraModel, NotSeen, ProjectionCamera};
use eyehand::robot::{ArmModel, Controlled};
use nalgebra::{Point3, Vector3};
use proptest::prelude::*;

fn camera() -> ProjectionCamera {
    ProjectionCamera::new(CameraModel::default())
}

/// The arm at a mid-reach pose and an object right under the camera at the standoff.
fn arm_over_object() -> (ArmModel, Controlled, Point3<f64>) {
    let model = ArmModel::oscar6();
    let theta = Controlled::new(0.0, 20f64.to_radians(), 90f64.to_radians());
    let object = model.camera_position(&model.full_pose(&theta)) - Vector3::z() * 0.20;
    (model, theta, object)
}

#[test]
fn the_reading_is_zero_at_the_target() {
    let (model, theta, object) = arm_over_object();
    let c = camera()
        .read(&model.camera_pose(&model.full_pose(&theta)), &object)
        .unwrap();
    assert!(c.norm() < 1e-9, "{c}");
}

#[test]
fn offsets_have_the_right_sign_and_scale() {
    let cam = camera();
    // 1 cm along image x at 20 cm: about f·0.01/0.2 = 12.8 px.
    let c = cam.read_local(&Vector3::new(0.01, 0.0, 0.20)).unwrap();
    assert!((c.x - 12.8).abs() < 0.15 && c.y.abs() < 1e-12, "{c}");
    assert!(c.z.abs() < 1.0, "nearly the reference size: {c}");
    let c = cam.read_local(&Vector3::new(0.0, -0.02, 0.20)).unwrap();
    assert!((c.y + 25.6).abs() < 0.3 && c.x.abs() < 1e-12, "{c}");
    // 10 cm too high: cz ≈ 100·(30/20 − 1) = 50; 5 cm too low: ≈ −25.
    let high = cam.read_local(&Vector3::new(0.0, 0.0, 0.30)).unwrap();
    assert!((high.z - 50.0).abs() < 0.5, "{high}");
    let low = cam.read_local(&Vector3::new(0.0, 0.0, 0.15)).unwrap();
    assert!((low.z + 25.0).abs() < 0.5, "{low}");
}

#[test]
fn the_image_axes_follow_the_world_at_zero_yaw() {
    let (model, theta, object) = arm_over_object();
    let pose = model.camera_pose(&model.full_pose(&theta));
    let ahead = camera()
        .read(&pose, &(object + Vector3::new(0.02, 0.0, 0.0)))
        .unwrap();
    assert!(
        ahead.x > 20.0 && ahead.y.abs() < 1e-9,
        "object ahead is +cx: {ahead}"
    );
    let right = camera()
        .read(&pose, &(object + Vector3::new(0.0, -0.02, 0.0)))
        .unwrap();
    assert!(
        right.y > 20.0 && right.x.abs() < 1e-9,
        "object to the right is +cy: {right}"
    );
}

#[test]
fn turning_the_camera_90_degrees_swaps_the_axes() {
    let (mut model, theta, object) = arm_over_object();
    let target = object + Vector3::new(0.03, 0.0, 0.0);
    let before = camera()
        .read(&model.camera_pose(&model.full_pose(&theta)), &target)
        .unwrap();
    model.rotate_camera(90f64.to_radians());
    let after = camera()
        .read(&model.camera_pose(&model.full_pose(&theta)), &target)
        .unwrap();
    assert!(after.x.abs() < 1e-9, "{after}");
    assert!(
        (after.y.abs() - before.x).abs() < 1e-9,
        "{before} → {after}"
    );
    assert!((after.z - before.z).abs() < 1e-9);
}

#[test]
fn objects_behind_too_close_or_outside_are_not_seen() {
    let cam = camera();
    assert_eq!(
        cam.read_local(&Vector3::new(0.0, 0.0, -0.2)),
        Err(NotSeen::TooClose)
    );
    assert_eq!(
        cam.read_local(&Vector3::new(0.0, 0.0, 0.04)),
        Err(NotSeen::TooClose)
    );
    assert_eq!(
        cam.read_local(&Vector3::new(0.5, 0.0, 0.2)),
        Err(NotSeen::OutsideFrame)
    );
    // The centre inside the frame, the disc cut by the border.
    assert_eq!(
        cam.read_local(&Vector3::new(0.195, 0.0, 0.2)),
        Err(NotSeen::OutsideFrame)
    );
    assert!(cam.read_local(&Vector3::new(0.17, 0.0, 0.2)).is_ok());
    assert!(cam.read_local(&Vector3::new(f64::NAN, 0.0, 0.2)).is_err());
    assert!(cam.read_local(&Vector3::new(0.0, 0.0, f64::NAN)).is_err());
}

/// Centroid and area of the sphere's image by testing a fine grid of pixel rays.
fn brute_force_blob(p: &Vector3<f64>, model: &CameraModel) -> (f64, f64, f64) {
    let step = 0.125;
    let (mut n, mut sx, mut sy) = (0.0, 0.0, 0.0);
    let half = model.width / 2.0;
    let mut u = -half;
    while u < half {
        let mut v = -half;
        while v < half {
            let ray = Vector3::new(u + step / 2.0, v + step / 2.0, model.focal).normalize();
            let along = ray.dot(p);
            if along > 0.0 && (p - ray * along).norm() <= model.object_radius {
                n += 1.0;
                sx += u + step / 2.0;
                sy += v + step / 2.0;
            }
            v += step;
        }
        u += step;
    }
    (sx / n, sy / n, n * step * step)
}

#[test]
fn the_analytic_image_matches_a_brute_force_one() {
    let model = CameraModel::default();
    let cam = camera();
    for p in [
        Vector3::new(0.0, 0.0, 0.2),
        Vector3::new(0.08, -0.05, 0.25),
        Vector3::new(-0.12, 0.1, 0.3),
    ] {
        let c = cam.read_local(&p).unwrap();
        let (u, v, area) = brute_force_blob(&p, &model);
        assert!(
            (c.x - u).abs() < 0.05 && (c.y - v).abs() < 0.05,
            "{p}: {c} vs ({u}, {v})"
        );
        let area_c = model.area_from_cz(c.z);
        assert!(
            (area_c - area).abs() / area < 2e-3,
            "{p}: area {area_c} vs {area}"
        );
    }
}

proptest! {
    #[test]
    fn locate_inverts_the_reading(x in -1.0f64..1.0, y in -1.0f64..1.0, z in 0.06f64..0.8) {
        let p = Vector3::new(x * z, y * z, z);
        if let Ok(c) = camera().read_local(&p) {
            let found = camera().locate(&c).expect("a seen object can be located");
            prop_assert!((found - p).norm() < 1e-8, "{} vs {}", found, p);
        }
    }
}
