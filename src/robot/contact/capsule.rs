//! The capsules that hold the arm's collision elements: a cheap lower bound on the distance
//! between two links, or between a link and an obstacle, before anything is measured exactly.

use super::world::Obstacle;
use nalgebra::{Isometry3, Point3, Vector3};

/// A capsule: the points within `radius` of the segment between `ends`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct Capsule {
    pub(super) ends: [Point3<f64>; 2],
    pub(super) radius: f64,
}

impl Capsule {
    /// This capsule moved by `at`.
    pub(super) fn placed(&self, at: &Isometry3<f64>) -> Capsule {
        Capsule {
            ends: self.ends.map(|e| at * e),
            radius: self.radius,
        }
    }

    /// The distance between the two capsules (negative when they overlap).
    pub(super) fn distance(&self, other: &Capsule) -> f64 {
        let ([p, q], [r, s]) = (&self.ends, &other.ends);
        segment_distance(p, q, r, s) - self.radius - other.radius
    }

    /// The distance between this capsule's bounding box and `obstacle`'s.
    pub(super) fn box_gap(&self, obstacle: &Obstacle) -> f64 {
        let [p, q] = &self.ends;
        let reach = Vector3::repeat(self.radius);
        let (low, high) = (p.inf(q) - reach, p.sup(q) + reach);
        let half = obstacle.size * 0.5;
        ((obstacle.centre - half) - high)
            .sup(&(low - (obstacle.centre + half)))
            .sup(&Vector3::zeros())
            .norm()
    }
}

/// The capsule holding a box of sides `size` centred at `centre` in the frame at `pose`:
/// its longest axis, as wide as the box's other two sides' diagonal.
pub(super) fn box_capsule(
    pose: &Isometry3<f64>,
    centre: &Vector3<f64>,
    size: &Vector3<f64>,
) -> ([Point3<f64>; 2], f64) {
    let long = size.imax();
    let across = (size.norm_squared() - size[long] * size[long]).sqrt();
    let half = Vector3::ith(long, 0.5 * size[long]);
    (
        [
            pose * Point3::from(centre - half),
            pose * Point3::from(centre + half),
        ],
        0.5 * across,
    )
}

/// The distance between segments `p`–`q` and `r`–`s`: the closest points' parameters are
/// found on the segments' lines, clamped to the segments, and the other re-found.
pub(super) fn segment_distance(
    p: &Point3<f64>,
    q: &Point3<f64>,
    r: &Point3<f64>,
    s: &Point3<f64>,
) -> f64 {
    let (d1, d2, w) = (q - p, s - r, p - r);
    let (a, e, f) = (d1.norm_squared(), d2.norm_squared(), d2.dot(&w));
    let tiny = 1e-18;
    let (t1, t2) = if a <= tiny && e <= tiny {
        (0.0, 0.0)
    } else if a <= tiny {
        (0.0, (f / e).clamp(0.0, 1.0))
    } else {
        let c = d1.dot(&w);
        if e <= tiny {
            ((-c / a).clamp(0.0, 1.0), 0.0)
        } else {
            let b = d1.dot(&d2);
            let denominator = a * e - b * b;
            let mut t1 = if denominator > tiny {
                ((b * f - c * e) / denominator).clamp(0.0, 1.0)
            } else {
                0.0
            };
            let mut t2 = (b * t1 + f) / e;
            if t2 < 0.0 {
                t2 = 0.0;
                t1 = (-c / a).clamp(0.0, 1.0);
            } else if t2 > 1.0 {
                t2 = 1.0;
                t1 = ((b - c) / a).clamp(0.0, 1.0);
            }
            (t1, t2)
        }
    };
    ((p + d1 * t1) - (r + d2 * t2)).norm()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn segment_distances() {
        let o = Point3::origin();
        let x = Point3::new(1.0, 0.0, 0.0);
        let across = |z: f64| (Point3::new(0.5, -1.0, z), Point3::new(0.5, 1.0, z));
        let (r, s) = across(0.3);
        assert!((segment_distance(&o, &x, &r, &s) - 0.3).abs() < 1e-15);
        // Parallel, overlapping along x, 0.2 apart.
        let (r, s) = (Point3::new(0.5, 0.2, 0.0), Point3::new(2.0, 0.2, 0.0));
        assert!((segment_distance(&o, &x, &r, &s) - 0.2).abs() < 1e-15);
        // End to end.
        let (r, s) = (Point3::new(2.0, 0.0, 0.0), Point3::new(3.0, 0.0, 0.0));
        assert!((segment_distance(&o, &x, &r, &s) - 1.0).abs() < 1e-15);
        // A point against a segment.
        assert!((segment_distance(&o, &o, &r, &s) - 2.0).abs() < 1e-15);
    }
}
