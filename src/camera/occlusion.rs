//! The ray-cast camera in a scene: which parts of the sphere's silhouette the scene hides.
//! Along each strip of the silhouette, rays half a pixel apart test whether something
//! meets them before the sphere; where the answer changes, bisection places the edge of
//! the hidden part to 1/4096 of that step. An occluder thinner than half a pixel in the
//! image can slip between the rays.

use super::raycast::Scanline;
use super::scene::Scene;
use nalgebra::{Isometry3, Point3, Vector3};

/// Halvings that place the edge of a hidden part.
const BISECTIONS: usize = 12;

/// A scene seen from a camera pose.
pub(super) struct Occlusion<'a> {
    /// What besides the sphere is there.
    pub(super) scene: &'a dyn Scene,
    /// The camera frame in the world.
    pub(super) camera_pose: Isometry3<f64>,
}

impl Occlusion<'_> {
    /// True when the ray through image point (`u`, `v`) meets the scene before the
    /// sphere (a ray grazing past the sphere's edge: before its nearest approach).
    fn blocked(&self, scan: &Scanline, u: f64, v: f64) -> bool {
        let sphere = scan.distance(u, v);
        let origin = Point3::from(self.camera_pose.translation.vector);
        let dir = self.camera_pose.rotation * Vector3::new(u / scan.focal, v / scan.focal, 1.0);
        self.scene.first_hit(&origin, &dir, sphere).is_some()
    }

    /// Calls `part(lo, hi)` for every stretch of the silhouette from `from` to `to` on the
    /// row at `v` that nothing hides.
    pub(super) fn visible_parts(
        &self,
        scan: &Scanline,
        v: f64,
        (from, to): (f64, f64),
        mut part: impl FnMut(f64, f64),
    ) {
        let count = ((to - from) / scan.step).ceil().max(1.0) as usize;
        let at = |k: usize| from + (to - from) * k as f64 / count as f64;
        let mut hidden = self.blocked(scan, from, v);
        let mut start = (!hidden).then_some(from);
        let mut last = from;
        for k in 1..=count {
            let u = at(k);
            let now_hidden = self.blocked(scan, u, v);
            if now_hidden != hidden {
                let edge = self.edge(scan, v, last, u, hidden);
                match start.take() {
                    Some(begin) => part(begin, edge),
                    None => start = Some(edge),
                }
                hidden = now_hidden;
            }
            last = u;
        }
        if let Some(begin) = start {
            part(begin, to);
        }
    }

    /// Where between `a` (hidden or not as `hidden_at_a` says) and `b` (the other) the
    /// ray's fate changes.
    fn edge(&self, scan: &Scanline, v: f64, a: f64, b: f64, hidden_at_a: bool) -> f64 {
        let (mut same, mut other) = (a, b);
        for _ in 0..BISECTIONS {
            let middle = 0.5 * (same + other);
            if self.blocked(scan, middle, v) == hidden_at_a {
                same = middle;
            } else {
                other = middle;
            }
        }
        0.5 * (same + other)
    }
}
