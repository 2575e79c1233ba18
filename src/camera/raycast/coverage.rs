//! The blob's coverage: each sampled pixel's covered area and moments, from the strips
//! that the scanlines measure, with pixel noise and occlusion applied.

use super::pixel_noise::pixel_gaussian;
use super::scanline::Scanline;
use super::RaycastCamera;
use crate::camera::occlusion::Occlusion;
use nalgebra::Vector3;
use rapier3d_f64::math::Vector;
use rapier3d_f64::parry::shape::Ball;
use std::ops::RangeInclusive;

/// Rows of rays per pixel row: the blob is measured as strips this many to a pixel.
const SUB_ROWS: usize = 4;
/// … and this many where the silhouette's top or bottom is near.
const END_SUB_ROWS: usize = 32;

/// The blob's moments from pixel coverage: area (px²) and the area-weighted sums of the
/// image coordinates (px³).
#[derive(Debug, Default)]
pub(super) struct Coverage {
    pub(super) area: f64,
    pub(super) sum_u: f64,
    pub(super) sum_v: f64,
    /// Some covered pixel lies on the image's border: the blob may be cut.
    pub(super) on_border: bool,
}

impl Coverage {
    /// Measures the blob of the sphere centred at `p` (camera frame) over the pixels in
    /// `columns` × `rows`, in frame number `frame` (for the pixel noise), what `occlusion`
    /// hides left out.
    pub(super) fn measure(
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
    pub(super) fn each_pixel(
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
