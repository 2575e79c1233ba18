//! The `raycast` camera: a ray through the centre of every sampled pixel, cast with parry
//! against the object's ball collider. The hit pixels form the blob; its centroid gives cx,
//! cy and its pixel count (in full-resolution px²) gives cz, with the quantisation a real
//! camera has.
//!
//! The 512×512 image is sampled by an N×N grid of rays (N = `raycast_resolution`). Only
//! the rays inside the blob's exact bounding box are cast: the planes through the camera
//! centre tangent to the sphere bound its image column- and row-wise, so no ray outside
//! them can hit (a one-ray margin absorbs rounding). At the target the blob is about 51 px
//! across, so a read costs about 700 rays at N = 256 instead of 65,536.

use super::model::{CameraModel, NotSeen};
use super::Camera;
use nalgebra::Vector3;
use rapier3d_f64::math::Vector;
use rapier3d_f64::parry::query::{Ray, RayCast};
use rapier3d_f64::parry::shape::Ball;
use std::ops::RangeInclusive;

/// The fewest rays per image side.
const MIN_RESOLUTION: usize = 2;

/// A camera that images the sphere by casting rays through its pixels.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RaycastCamera {
    model: CameraModel,
    resolution: usize,
}

impl RaycastCamera {
    /// A raycast camera with these intrinsics sampling the image with `resolution` rays per
    /// side (at least 2).
    pub fn new(model: CameraModel, resolution: usize) -> RaycastCamera {
        RaycastCamera {
            model,
            resolution: resolution.max(MIN_RESOLUTION),
        }
    }

    /// Rays per image side.
    pub fn resolution(&self) -> usize {
        self.resolution
    }

    /// The rays (column or row indices) that can hit the sphere whose centre lies at
    /// `lateral` across and `depth` along the optical axis, on an image side of `size` px;
    /// `None` when they all miss the image.
    /// The tangent planes u·z = f·x through the camera centre meet the sphere where
    /// (d² − r²)u² − 2f·x·d·u + f²(x² − r²) = 0; when the camera is inside the sphere's
    /// slab (d ≤ r) every ray is a candidate.
    fn span(&self, lateral: f64, depth: f64, size: f64) -> Option<RangeInclusive<usize>> {
        let m = &self.model;
        let n = self.resolution;
        let r = m.object_radius;
        let a = depth * depth - r * r;
        let root = lateral * lateral + a;
        if a <= 0.0 || root < 0.0 {
            return Some(0..=n - 1);
        }
        let spread = r * root.sqrt();
        let low = m.focal * (lateral * depth - spread) / a;
        let high = m.focal * (lateral * depth + spread) / a;
        let cell = size / n as f64;
        let index = |u: f64| (u + 0.5 * size) / cell - 0.5;
        let first = (index(low).floor() - 1.0).max(0.0);
        let last = (index(high).ceil() + 1.0).min((n - 1) as f64);
        (first <= last).then_some(first as usize..=last as usize)
    }
}

impl Camera for RaycastCamera {
    fn read_local(&self, p: &Vector3<f64>) -> Result<Vector3<f64>, NotSeen> {
        let m = &self.model;
        if !(p.iter().all(|v| v.is_finite()) && p.z >= m.min_depth) {
            return Err(NotSeen::TooClose);
        }
        let n = self.resolution;
        let (cell_u, cell_v) = (m.width / n as f64, m.height / n as f64);
        let (Some(columns), Some(rows)) =
            (self.span(p.x, p.z, m.width), self.span(p.y, p.z, m.height))
        else {
            return Err(NotSeen::OutsideFrame);
        };
        let ball = Ball::new(m.object_radius);
        let origin = Vector::new(-p.x, -p.y, -p.z);
        let (mut count, mut sum_u, mut sum_v) = (0usize, 0.0, 0.0);
        let mut on_border = false;
        for row in rows {
            let v = (row as f64 + 0.5) * cell_v - 0.5 * m.height;
            for column in columns.clone() {
                let u = (column as f64 + 0.5) * cell_u - 0.5 * m.width;
                let ray = Ray::new(origin, Vector::new(u / m.focal, v / m.focal, 1.0));
                if ball.intersects_local_ray(&ray, f64::MAX) {
                    count += 1;
                    sum_u += u;
                    sum_v += v;
                    on_border |= row == 0 || column == 0 || row == n - 1 || column == n - 1;
                }
            }
        }
        if count == 0 || on_border {
            return Err(NotSeen::OutsideFrame);
        }
        let area = count as f64 * cell_u * cell_v;
        Ok(Vector3::new(
            sum_u / count as f64,
            sum_v / count as f64,
            m.cz_from_area(area),
        ))
    }

    fn model(&self) -> &CameraModel {
        &self.model
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::camera::ProjectionCamera;

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
    fn readings_match_the_projection_where_the_blob_is_well_resolved() {
        let model = CameraModel::default();
        let exact = ProjectionCamera::new(model);
        let rays = RaycastCamera::new(model, 256);
        for p in centres() {
            let c = exact.read_local(&p).unwrap();
            let diameter = 2.0 * (model.area_from_cz(c.z) / std::f64::consts::PI).sqrt();
            assert!(diameter >= 20.0, "{p}: {diameter} px");
            let r = rays.read_local(&p).unwrap();
            assert!((r - c).xy().amax() < 0.5, "{p}: {r} vs {c}");
            // The blob's area is off by less than a quarter of the cells along its rim.
            let (blob, disc) = (model.area_from_cz(r.z), model.area_from_cz(c.z));
            let rim = std::f64::consts::PI * diameter * (512.0 / 256.0);
            assert!(
                (blob - disc).abs() < 0.25 * rim,
                "{p}: {blob} vs {disc} px²"
            );
        }
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
}
