//! Rays along one image row, finding where the sphere's silhouette starts and ends.

use rapier3d_f64::math::Vector;
use rapier3d_f64::parry::query::{Ray, RayCast};
use rapier3d_f64::parry::shape::Ball;

/// Halvings that place an edge on a row: to 1/4096 of the search step.
const BISECTIONS: usize = 12;

/// Rays along one image row: where the sphere's silhouette starts and ends on it.
#[derive(Debug)]
pub(in crate::camera) struct Scanline {
    pub(super) ball: Ball,
    pub(super) origin: Vector,
    pub(in crate::camera) focal: f64,
    /// The image coordinates (px) the rows are searched between.
    pub(super) left: f64,
    pub(super) right: f64,
    /// The spacing (px) of the rays that look for the silhouette.
    pub(in crate::camera) step: f64,
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
    pub(in crate::camera) fn distance(&self, u: f64, v: f64) -> f64 {
        let ray = self.ray(u, v);
        self.ball
            .cast_local_ray(&ray, f64::MAX, true)
            .unwrap_or_else(|| -ray.origin.dot(ray.dir) / ray.dir.length_squared())
    }

    /// The silhouette's extent (u from, u to) on the row at `v`, `None` if the row misses
    /// it; `near` is the extent on a neighbouring row, where the search starts.
    pub(super) fn segment(&self, v: f64, near: Option<(f64, f64)>) -> Option<(f64, f64)> {
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
