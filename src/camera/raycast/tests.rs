//! The ray-cast camera against the exact projection, its noise and occlusion.

use super::*;
use crate::camera::ProjectionCamera;
use rapier3d_f64::math::Vector;
use rapier3d_f64::parry::query::{Ray, RayCast};
use rapier3d_f64::parry::shape::Ball;

fn centres() -> Vec<Vector3<f64>> {
    let mut all = Vec::new();
    for depth in [0.08, 0.12, 0.2, 0.3, 0.45] {
        for (x, y) in [(0.0, 0.0), (0.013, -0.007), (-0.031, 0.022), (0.05, 0.04)] {
            all.push(Vector3::new(x * depth / 0.2, y * depth / 0.2, depth));
        }
    }
    all
}

#[test]
fn readings_match_the_projection_to_a_twentieth_of_a_pixel_where_the_blob_is_resolved() {
    let model = CameraModel::default();
    let exact = ProjectionCamera::new(model);
    let rays = RaycastCamera::new(model, 256);
    let (mut worst_px, mut worst_area) = (0.0_f64, 0.0_f64);
    for p in centres() {
        let c = exact.read_local(&p).unwrap();
        let diameter = 2.0 * (model.area_from_cz(c.z) / std::f64::consts::PI).sqrt();
        assert!(diameter >= 20.0, "{p}: {diameter} px");
        let r = rays.read_local(&p).unwrap();
        worst_px = worst_px.max((r - c).xy().amax());
        let (blob, disc) = (model.area_from_cz(r.z), model.area_from_cz(c.z));
        worst_area = worst_area.max((blob / disc - 1.0).abs());
    }
    assert!(worst_px < 0.05, "centroid off by {worst_px} px");
    assert!(worst_area < 5e-4, "area off by {worst_area} of itself");
}

#[test]
fn pixel_noise_jitters_the_reading_reproducibly_and_without_bias() {
    let model = CameraModel::default();
    let p = Vector3::new(0.011, -0.004, 0.2);
    let exact = RaycastCamera::new(model, 256).read_local(&p).unwrap();
    let (a, b) = (
        RaycastCamera::new(model, 256).with_pixel_noise(0.1, 3),
        RaycastCamera::new(model, 256).with_pixel_noise(0.1, 3),
    );
    let reads: Vec<Vector3<f64>> = (0..200).map(|_| a.read_local(&p).unwrap()).collect();
    let replay: Vec<Vector3<f64>> = (0..200).map(|_| b.read_local(&p).unwrap()).collect();
    assert_eq!(reads, replay, "the same seed gives the same frames");
    assert_ne!(reads[0], reads[1], "each frame has its own noise");
    let mean = reads.iter().sum::<Vector3<f64>>() / reads.len() as f64;
    let spread = (reads.iter().map(|r| (r - mean).x.powi(2)).sum::<f64>() / 199.0).sqrt();
    assert!(spread > 0.005 && spread < 0.2, "σ(cx) {spread} px");
    assert!((mean - exact).xy().amax() < 0.05, "{mean} vs {exact}");
}

#[test]
fn only_the_rays_that_can_hit_are_cast_and_none_is_missed() {
    let camera = RaycastCamera::new(CameraModel::default(), 128);
    for p in centres() {
        let columns = camera.span(p.x, p.z, 512.0).unwrap();
        let rows = camera.span(p.y, p.z, 512.0).unwrap();
        // Brute force over the whole image: every hit lies inside the spans.
        let ball = Ball::new(0.02);
        for row in 0..128 {
            for column in 0..128 {
                let (u, v) = (
                    (column as f64 + 0.5) * 4.0 - 256.0,
                    (row as f64 + 0.5) * 4.0 - 256.0,
                );
                let ray = Ray::new(
                    Vector::new(-p.x, -p.y, -p.z),
                    Vector::new(u / 256.0, v / 256.0, 1.0),
                );
                if ball.intersects_local_ray(&ray, f64::MAX) {
                    assert!(columns.contains(&column) && rows.contains(&row), "{p}");
                }
            }
        }
        let cast = columns.count() * rows.count();
        assert!(cast < 128 * 128 / 4, "{p}: {cast} rays");
    }
}

#[test]
fn blobs_cut_by_the_border_and_objects_behind_are_not_seen() {
    let camera = RaycastCamera::new(CameraModel::default(), 256);
    // The image's edge is at 45°: a sphere centred 0.2 m out at 0.2 m depth is cut.
    assert_eq!(
        camera.read_local(&Vector3::new(0.2, 0.0, 0.2)),
        Err(NotSeen::OutsideFrame)
    );
    assert_eq!(
        camera.read_local(&Vector3::new(0.0, -0.19, 0.2)),
        Err(NotSeen::OutsideFrame)
    );
    assert_eq!(
        camera.read_local(&Vector3::new(1.0, 1.0, 0.2)),
        Err(NotSeen::OutsideFrame)
    );
    assert_eq!(
        camera.read_local(&Vector3::new(0.0, 0.0, -0.2)),
        Err(NotSeen::TooClose)
    );
    assert_eq!(
        camera.read_local(&Vector3::new(0.0, 0.0, 0.03)),
        Err(NotSeen::TooClose)
    );
    assert_eq!(
        camera.read_local(&Vector3::new(f64::NAN, 0.0, 0.2)),
        Err(NotSeen::TooClose)
    );
    // Far away the blob falls between the rays of a coarse grid: empty, not seen.
    let coarse = RaycastCamera::new(CameraModel::default(), 2);
    assert_eq!(
        coarse.read_local(&Vector3::new(0.0, 0.0, 5.0)),
        Err(NotSeen::OutsideFrame)
    );
    assert_eq!(
        RaycastCamera::new(CameraModel::default(), 0).resolution(),
        2
    );
}
