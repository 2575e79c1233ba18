//! The `raycast` camera: rays cast with parry against the object's ball collider measure
//! each sampled pixel's coverage — the grey level a real sensor's pixel records where the
//! sphere's edge crosses it. The blob's coverage-weighted centroid gives cx, cy and its
//! total coverage (in full-resolution px²) gives cz: sub-pixel measures, as a real blob
//! detector makes from grey levels.
//!
//! The 512×512 image is sampled by an N×N grid of pixels (N = `raycast_resolution`). Each
//! pixel row is measured as strips (4 to a row; 32 near the silhouette's top and bottom,
//! where its width changes as a square root): on each strip's centre line, rays find where
//! the silhouette starts and ends — stepping half a pixel from the neighbouring strip's
//! edges to a hit and a miss, then bisecting to 1/4096 px — and the strip's covered length
//! is shared out among the pixels it crosses. Only the rays inside the blob's exact
//! bounding box are cast: the planes through the camera centre tangent to the sphere bound
//! its image column- and row-wise, so no ray outside them can hit (a one-pixel margin
//! absorbs rounding).
//!
//! With pixel noise (`raycast_noise` σ > 0) every pixel's grey level gets Gaussian noise
//! before the blob is measured, as a real sensor's pixels do; the detector then keeps the
//! pixels brighter than a 3σ noise floor and weighs each by its grey level (clamped to
//! [0, 1]). The noise of a pixel is a hash of the seed, the frame number and the pixel, so
//! every read is reproducible and no generator is shared.

mod coverage;

mod pixel_noise;
mod scanline;
#[cfg(test)]
mod tests;

pub(in crate::camera) use scanline::Scanline;

use coverage::Coverage;

use super::model::{CameraModel, NotSeen};
use super::occlusion::Occlusion;
use super::scene::{view_may_be_blocked, Scene};
use super::Camera;
use nalgebra::{Isometry3, Point3, Vector3};
use std::cell::Cell;
use std::ops::RangeInclusive;

/// The fewest pixels per image side.
const MIN_RESOLUTION: usize = 2;

/// A camera that images the sphere by casting rays through its pixels.
#[derive(Debug, Clone, PartialEq)]
pub struct RaycastCamera {
    model: CameraModel,
    resolution: usize,
    /// σ of each pixel's grey level (0: noiseless).
    pixel_noise: f64,
    seed: u64,
    /// Frames read so far: the noise differs from frame to frame.
    frames: Cell<u64>,
}

impl RaycastCamera {
    /// A raycast camera with these intrinsics sampling the image with `resolution` rays per
    /// side (at least 2).
    pub fn new(model: CameraModel, resolution: usize) -> RaycastCamera {
        RaycastCamera {
            model,
            resolution: resolution.max(MIN_RESOLUTION),
            pixel_noise: 0.0,
            seed: 0,
            frames: Cell::new(0),
        }
    }

    /// This camera with Gaussian noise of σ `sigma` on each pixel's grey level (coverage
    /// 0–1), reproducible from `seed`.
    pub fn with_pixel_noise(mut self, sigma: f64, seed: u64) -> RaycastCamera {
        self.pixel_noise = sigma.max(0.0);
        self.seed = seed;
        self
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
        let n = self.resolution;
        let Some((low, high)) = self.extent(lateral, depth) else {
            return Some(0..=n - 1);
        };
        let cell = size / n as f64;
        let index = |u: f64| (u + 0.5 * size) / cell - 0.5;
        let first = (index(low).floor() - 1.0).max(0.0);
        let last = (index(high).ceil() + 1.0).min((n - 1) as f64);
        (first <= last).then_some(first as usize..=last as usize)
    }
}

impl RaycastCamera {
    /// The image coordinates (px) between which the silhouette of the sphere whose centre
    /// lies at `lateral` across and `depth` along the optical axis falls, along that axis
    /// (see [`span`](Self::span)); `None` when the camera is inside the sphere's slab.
    fn extent(&self, lateral: f64, depth: f64) -> Option<(f64, f64)> {
        let m = &self.model;
        let r = m.object_radius;
        let a = depth * depth - r * r;
        let root = lateral * lateral + a;
        if a <= 0.0 || root < 0.0 {
            return None;
        }
        let spread = r * root.sqrt();
        Some((
            m.focal * (lateral * depth - spread) / a,
            m.focal * (lateral * depth + spread) / a,
        ))
    }
}

impl RaycastCamera {
    /// The image this camera sees of the sphere centred at `p` (camera frame), without pixel
    /// noise: every pixel the sphere covers, row by row. Empty when the sphere is not in
    /// front of the camera or misses the image; a blob cut by the border is kept (the
    /// reading refuses it).
    pub fn render(&self, p: &Vector3<f64>) -> Vec<PixelCoverage> {
        self.render_visible(p, None)
    }

    /// The image of the sphere centred at `object` (world) seen from `camera_pose` with
    /// `scene` around it, as [`render`](Self::render) gives it: only what the scene does not
    /// hide.
    pub fn render_in(
        &self,
        camera_pose: &Isometry3<f64>,
        object: &Point3<f64>,
        scene: &dyn Scene,
    ) -> Vec<PixelCoverage> {
        let occlusion = Occlusion {
            scene,
            camera_pose: *camera_pose,
        };
        let p = camera_pose.inverse_transform_point(object).coords;
        self.render_visible(&p, Some(&occlusion))
    }

    /// The grey level of the scene behind every pixel, row by row (`None` where a pixel's
    /// centre ray meets nothing), seen from `camera_pose`; the sphere is not in it.
    pub fn render_scene(&self, camera_pose: &Isometry3<f64>, scene: &dyn Scene) -> Vec<Option<u8>> {
        let m = &self.model;
        let n = self.resolution;
        let origin = Point3::from(camera_pose.translation.vector);
        let centre = |index: usize, size: f64| ((index as f64 + 0.5) / n as f64 - 0.5) * size;
        (0..n * n)
            .map(|k| {
                let (u, v) = (centre(k % n, m.width), centre(k / n, m.height));
                let dir = camera_pose.rotation * Vector3::new(u / m.focal, v / m.focal, 1.0);
                scene.first_hit(&origin, &dir, f64::MAX).map(|hit| hit.grey)
            })
            .collect()
    }

    /// The pixels of the sphere centred at `p` (camera frame) that `occlusion` leaves.
    fn render_visible(
        &self,
        p: &Vector3<f64>,
        occlusion: Option<&Occlusion>,
    ) -> Vec<PixelCoverage> {
        let m = &self.model;
        let mut pixels = Vec::new();
        if !(p.iter().all(|v| v.is_finite()) && p.z > m.object_radius) {
            return pixels;
        }
        let (Some(columns), Some(rows)) =
            (self.span(p.x, p.z, m.width), self.span(p.y, p.z, m.height))
        else {
            return pixels;
        };
        let noiseless = RaycastCamera::new(*m, self.resolution);
        Coverage::each_pixel(
            &noiseless,
            p,
            (columns, rows),
            (0, occlusion),
            |column, row, coverage, _, _| {
                pixels.push(PixelCoverage {
                    column,
                    row,
                    coverage,
                });
            },
        );
        pixels
    }
}

/// A pixel of the ray-cast camera's image that the object covers.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PixelCoverage {
    /// The pixel's column (0 at the image's left, `resolution` pixels per side).
    pub column: usize,
    /// The pixel's row (0 at the image's top).
    pub row: usize,
    /// The covered fraction of the pixel (0–1]: its grey level.
    pub coverage: f64,
}

impl Camera for RaycastCamera {
    fn read_local(&self, p: &Vector3<f64>) -> Result<Vector3<f64>, NotSeen> {
        self.measure(p, None)
    }

    fn model(&self) -> &CameraModel {
        &self.model
    }

    fn read_in(
        &self,
        camera_pose: &Isometry3<f64>,
        object: &Point3<f64>,
        scene: &dyn Scene,
    ) -> Result<Vector3<f64>, NotSeen> {
        if !view_may_be_blocked(scene, camera_pose, object, self.model.object_radius) {
            return self.read(camera_pose, object);
        }
        let occlusion = Occlusion {
            scene,
            camera_pose: *camera_pose,
        };
        let p = camera_pose.inverse_transform_point(object).coords;
        self.measure(&p, Some(&occlusion))
    }
}

impl RaycastCamera {
    /// The reading of the sphere centred at `p` (camera frame) from the part of its blob
    /// that `occlusion` (if any) leaves visible.
    fn measure(
        &self,
        p: &Vector3<f64>,
        occlusion: Option<&Occlusion>,
    ) -> Result<Vector3<f64>, NotSeen> {
        let m = &self.model;
        if !(p.iter().all(|v| v.is_finite()) && p.z >= m.min_depth) {
            return Err(NotSeen::TooClose);
        }
        let (Some(columns), Some(rows)) =
            (self.span(p.x, p.z, m.width), self.span(p.y, p.z, m.height))
        else {
            return Err(NotSeen::OutsideFrame);
        };
        let frame = self.frames.get();
        self.frames.set(frame + 1);
        let blob = Coverage::measure(self, p, (columns, rows), (frame, occlusion));
        if blob.area <= 0.0 && occlusion.is_some() {
            return Err(NotSeen::Hidden);
        }
        if blob.area <= 0.0 || blob.on_border {
            return Err(NotSeen::OutsideFrame);
        }
        Ok(Vector3::new(
            blob.sum_u / blob.area,
            blob.sum_v / blob.area,
            m.cz_from_area(blob.area),
        ))
    }
}
