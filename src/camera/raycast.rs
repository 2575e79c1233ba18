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

use super::model::{CameraModel, NotSeen};
use super::occlusion::Occlusion;
use super::scene::{view_may_be_blocked, Scene};
use super::Camera;
use nalgebra::{Isometry3, Point3, Vector3};
use rapier3d_f64::math::Vector;
use rapier3d_f64::parry::query::{Ray, RayCast};
use rapier3d_f64::parry::shape::Ball;
use std::cell::Cell;
use std::ops::RangeInclusive;

/// The fewest pixels per image side.
const MIN_RESOLUTION: usize = 2;

/// Rows of rays per pixel row: the blob is measured as strips this many to a pixel.
const SUB_ROWS: usize = 4;
/// … and this many where the silhouette's top or bottom is near.
const END_SUB_ROWS: usize = 32;
/// Halvings that place an edge on a row: to 1/4096 of the search step.
const BISECTIONS: usize = 12;

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

/// The blob's moments from pixel coverage: area (px²) and the area-weighted sums of the
/// image coordinates (px³).
#[derive(Debug, Default)]
struct Coverage {
    area: f64,
    sum_u: f64,
    sum_v: f64,
    /// Some covered pixel lies on the image's border: the blob may be cut.
    on_border: bool,
}

impl Coverage {
    /// Measures the blob of the sphere centred at `p` (camera frame) over the pixels in
    /// `columns` × `rows`, in frame number `frame` (for the pixel noise), what `occlusion`
    /// hides left out.
    fn measure(
        camera: &RaycastCamera,
        p: &Vector3<f64>,
        spans: (RangeInclusive<usize>, RangeInclusive<usize>),
        seen: (u64, Option<&Occlusion>),
    ) -> Coverage {
        let m = &camera.model;
        let n = camera.resolution;
        let pixel_area = (m.width / n as f64) * (m.height / n as f64);
        let mut blob = Coverage::default();
        Coverage::each_pixel(camera, p, spans, seen, |column, row, covered, u, v| {
            let area = covered * pixel_area;
            blob.area += area;
            blob.sum_u += area * u;
            blob.sum_v += area * v;
            blob.on_border |= row == 0 || column == 0 || row == n - 1 || column == n - 1;
        });
        blob
    }

    /// Calls `each(column, row, coverage, u, v)` for every pixel in `columns` × `rows` that
    /// the sphere centred at `p` covers where `occlusion` (if any) does not hide it (after
    /// the pixel noise of frame `frame`): its covered fraction and the centroid (px) of its
    /// covered part.
    fn each_pixel(
        camera: &RaycastCamera,
        p: &Vector3<f64>,
        (columns, rows): (RangeInclusive<usize>, RangeInclusive<usize>),
        (frame, occlusion): (u64, Option<&Occlusion>),
        mut each: impl FnMut(usize, usize, f64, f64, f64),
    ) {
        let m = &camera.model;
        let n = camera.resolution;
        let (cell_u, cell_v) = (m.width / n as f64, m.height / n as f64);
        let (c0, r0) = (*columns.start(), *rows.start());
        let (w, h) = (columns.end() - c0 + 1, rows.end() - r0 + 1);
        let left = c0 as f64 * cell_u - 0.5 * m.width;
        let scan = Scanline {
            ball: Ball::new(m.object_radius),
            origin: Vector::new(-p.x, -p.y, -p.z),
            focal: m.focal,
            left,
            right: left + w as f64 * cell_u,
            step: 0.5 * cell_u,
        };
        let mut pixels = vec![Moments::default(); w * h];
        // Near its top and bottom the silhouette's width changes fastest (as a square
        // root): rows there are cut into finer strips.
        let ends = camera.extent(p.y, p.z);
        let near_end = |top: f64| {
            ends.is_none_or(|(low, high)| {
                [low, high]
                    .iter()
                    .any(|&end| (top - cell_v..=top + 2.0 * cell_v).contains(&end))
            })
        };
        let mut last = None;
        for j in 0..h {
            let top = (r0 + j) as f64 * cell_v - 0.5 * m.height;
            let strips = if near_end(top) {
                END_SUB_ROWS
            } else {
                SUB_ROWS
            };
            let dv = cell_v / strips as f64;
            for s in 0..strips {
                let v = top + (s as f64 + 0.5) * dv;
                last = scan.segment(v, last);
                let Some(silhouette) = last else { continue };
                let row = &mut pixels[j * w..(j + 1) * w];
                let spread = |from: f64, to: f64| {
                    let first = (((from - left) / cell_u).floor().max(0.0) as usize).min(w - 1);
                    let end = (((to - left) / cell_u).floor().max(0.0) as usize).min(w - 1);
                    for (i, pixel) in row.iter_mut().enumerate().take(end + 1).skip(first) {
                        let lo = from.max(left + i as f64 * cell_u);
                        let hi = to.min(left + (i + 1) as f64 * cell_u);
                        if hi > lo {
                            pixel.add(lo, hi, v, dv);
                        }
                    }
                };
                match occlusion {
                    None => {
                        let mut spread = spread;
                        spread(silhouette.0, silhouette.1)
                    }
                    Some(hidden) => hidden.visible_parts(&scan, v, silhouette, spread),
                }
            }
        }
        let sigma = camera.pixel_noise;
        let pixel_area = cell_u * cell_v;
        for j in 0..h {
            for i in 0..w {
                let (column, row) = (c0 + i, r0 + j);
                let centre = (
                    left + (i as f64 + 0.5) * cell_u,
                    (row as f64 + 0.5) * cell_v - 0.5 * m.height,
                );
                let (mut covered, mean_u, mean_v) = pixels[j * w + i].coverage(pixel_area, centre);
                if sigma > 0.0 {
                    let grey = covered + sigma * pixel_gaussian(camera.seed, frame, column, row);
                    covered = if grey >= 3.0 * sigma {
                        grey.min(1.0)
                    } else {
                        0.0
                    };
                }
                if covered > 0.0 {
                    each(column, row, covered, mean_u, mean_v);
                }
            }
        }
    }
}

/// The covered part of one pixel: its area (px²) and first moments (px³).
#[derive(Debug, Clone, Copy, Default)]
struct Moments {
    area: f64,
    sum_u: f64,
    sum_v: f64,
}

impl Moments {
    /// Adds the strip from `lo` to `hi` along u, `dv` high, at height `v`.
    fn add(&mut self, lo: f64, hi: f64, v: f64, dv: f64) {
        let area = (hi - lo) * dv;
        self.area += area;
        self.sum_u += 0.5 * (hi * hi - lo * lo) * dv;
        self.sum_v += v * area;
    }

    /// The covered fraction of a pixel of `pixel_area` and the centroid of its covered
    /// part (`centre`, the pixel's, when nothing is covered).
    fn coverage(&self, pixel_area: f64, centre: (f64, f64)) -> (f64, f64, f64) {
        if self.area <= 0.0 {
            return (0.0, centre.0, centre.1);
        }
        (
            (self.area / pixel_area).min(1.0),
            self.sum_u / self.area,
            self.sum_v / self.area,
        )
    }
}

/// Rays along one image row: where the sphere's silhouette starts and ends on it.
#[derive(Debug)]
pub(super) struct Scanline {
    ball: Ball,
    origin: Vector,
    pub(super) focal: f64,
    /// The image coordinates (px) the rows are searched between.
    left: f64,
    right: f64,
    /// The spacing (px) of the rays that look for the silhouette.
    pub(super) step: f64,
}

impl Scanline {
    fn ray(&self, u: f64, v: f64) -> Ray {
        Ray::new(
            self.origin,
            Vector::new(u / self.focal, v / self.focal, 1.0),
        )
    }

    fn hits(&self, u: f64, v: f64) -> bool {
        self.ball.intersects_local_ray(&self.ray(u, v), f64::MAX)
    }

    /// Where the ray through image point (`u`, `v`) meets the sphere, in lengths of its
    /// direction (u/f, v/f, 1); where it misses, its nearest approach to the centre.
    pub(super) fn distance(&self, u: f64, v: f64) -> f64 {
        let ray = self.ray(u, v);
        self.ball
            .cast_local_ray(&ray, f64::MAX, true)
            .unwrap_or_else(|| -ray.origin.dot(ray.dir) / ray.dir.length_squared())
    }

    /// The silhouette's extent (u from, u to) on the row at `v`, `None` if the row misses
    /// it; `near` is the extent on a neighbouring row, where the search starts.
    fn segment(&self, v: f64, near: Option<(f64, f64)>) -> Option<(f64, f64)> {
        let middle = near.map(|(from, to)| 0.5 * (from + to));
        let (inside, (from, to)) = match (middle, near) {
            (Some(u), Some(guess)) if self.hits(u, v) => (u, guess),
            _ => {
                let u = self.first_hit(v)?;
                (u, (u, u))
            }
        };
        Some((
            self.edge(v, inside, from.min(inside), -1.0),
            self.edge(v, inside, to.max(inside), 1.0),
        ))
    }

    /// Some u on the row at `v` where a ray hits, from rays `step` apart.
    fn first_hit(&self, v: f64) -> Option<f64> {
        let count = ((self.right - self.left) / self.step).ceil() as usize;
        (0..count)
            .map(|k| self.left + (k as f64 + 0.5) * self.step)
            .find(|&u| self.hits(u, v))
    }

    /// The silhouette's edge on the row at `v` going from `inside` (a hit) `outward` (−1
    /// left, +1 right), `guess` on the way: from `guess`, rays `step` apart find a hit and
    /// a miss next to each other, then bisection closes in between them.
    fn edge(&self, v: f64, inside: f64, guess: f64, outward: f64) -> f64 {
        let (mut hit, mut miss) = if self.hits(guess, v) {
            let mut hit = guess;
            loop {
                let next = hit + outward * self.step;
                if !(self.left..=self.right).contains(&next) {
                    return next.clamp(self.left, self.right);
                }
                if !self.hits(next, v) {
                    break (hit, next);
                }
                hit = next;
            }
        } else {
            let mut miss = guess;
            loop {
                let next = miss - outward * self.step;
                if (next - inside) * outward <= 0.0 {
                    break (inside, miss);
                }
                if self.hits(next, v) {
                    break (next, miss);
                }
                miss = next;
            }
        };
        for _ in 0..BISECTIONS {
            let middle = 0.5 * (hit + miss);
            if self.hits(middle, v) {
                hit = middle;
            } else {
                miss = middle;
            }
        }
        0.5 * (hit + miss)
    }
}

/// A standard normal value that depends only on the seed, frame and pixel (two hashed
/// uniforms through Box–Muller).
fn pixel_gaussian(seed: u64, frame: u64, column: usize, row: usize) -> f64 {
    let key = seed ^ frame.rotate_left(40) ^ ((column as u64) << 20) ^ row as u64;
    let (a, b) = (splitmix(key), splitmix(key ^ 0x9e37_79b9_7f4a_7c15));
    let uniform = |x: u64| ((x >> 11) as f64 + 0.5) / (1u64 << 53) as f64;
    (-2.0 * uniform(a).ln()).sqrt() * (std::f64::consts::TAU * uniform(b)).cos()
}

/// The SplitMix64 finaliser: a well-mixed 64-bit hash of `x`.
fn splitmix(x: u64) -> u64 {
    let mut z = x.wrapping_add(0x9e37_79b9_7f4a_7c15);
    z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
    z ^ (z >> 31)
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
}
