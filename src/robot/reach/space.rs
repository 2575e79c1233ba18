//! The reach space of the camera centre: the study's open half cylinder.

use nalgebra::Point3;
use rand::Rng;

/// Relative distance from a bound's square within which [`ReachSpace::contains`] asks
/// `hypot` rather than trusting the squared radius.
const RADIUS_BAND: f64 = 1e-9;

/// The region the camera centre must reach (m, base frame): `r_min ≤ √(x²+y²) ≤ r_max`,
/// `0 ≤ x`, `|y| ≤ r_max`, `z_min ≤ z ≤ z_max`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ReachSpace {
    /// Inner radius (m).
    pub r_min: f64,
    /// Outer radius (m).
    pub r_max: f64,
    /// Lowest height (m).
    pub z_min: f64,
    /// Highest height (m).
    pub z_max: f64,
}

impl ReachSpace {
    /// The study's reach space: 46 ≤ r ≤ 93 cm, x ≥ 0, 0 ≤ z ≤ 52 cm (533.6 dm³).
    pub const OSCAR6: ReachSpace = ReachSpace {
        r_min: 0.46,
        r_max: 0.93,
        z_min: 0.0,
        z_max: 0.52,
    };

    /// Where the camera is at the end of every pre-learning move: the middle of the space
    /// (mid-radius on the x axis, mid-height); for the study's space its 69.5, 0, 26 cm.
    pub fn prelearning_goal(&self) -> Point3<f64> {
        if *self == ReachSpace::OSCAR6 {
            return Point3::new(0.695, 0.0, 0.26);
        }
        Point3::new(
            0.5 * (self.r_min + self.r_max),
            0.0,
            0.5 * (self.z_min + self.z_max),
        )
    }

    /// True when `p` lies inside.
    pub fn contains(&self, p: &Point3<f64>) -> bool {
        p.x >= 0.0 && p.z >= self.z_min && p.z <= self.z_max && self.radius_within(p.x, p.y)
    }

    /// Whether `r_min ≤ hypot(x, y) ≤ r_max`, decided from `x² + y²` where that is farther
    /// than [`RADIUS_BAND`] (relative) from a bound's square, and by `hypot` itself
    /// otherwise. Both roundings (the sum's, `hypot`'s) are below 1e-15 relative for a
    /// normal sum, so outside the band the two tests cannot disagree.
    fn radius_within(&self, x: f64, y: f64) -> bool {
        let squared = x * x + y * y;
        if squared.is_normal() {
            let (inner, outer) = (self.r_min * self.r_min, self.r_max * self.r_max);
            let (low, high) = (1.0 - RADIUS_BAND, 1.0 + RADIUS_BAND);
            if squared < inner * low || squared > outer * high {
                return false;
            }
            if squared > inner * high && squared < outer * low {
                return true;
            }
        }
        let r = x.hypot(y);
        r >= self.r_min && r <= self.r_max
    }

    /// The volume (m³).
    pub fn volume(&self) -> f64 {
        0.5 * std::f64::consts::PI
            * (self.r_max.powi(2) - self.r_min.powi(2))
            * (self.z_max - self.z_min)
    }

    /// A point drawn uniformly inside (rejection from the bounding box).
    pub fn sample(&self, rng: &mut impl Rng) -> Point3<f64> {
        loop {
            let p = Point3::new(
                rng.random_range(0.0..=self.r_max),
                rng.random_range(-self.r_max..=self.r_max),
                rng.random_range(self.z_min..=self.z_max),
            );
            if self.contains(&p) {
                return p;
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::SeedableRng;

    /// The decision `hypot` alone gives.
    fn by_hypot(space: &ReachSpace, p: &Point3<f64>) -> bool {
        let r = p.x.hypot(p.y);
        p.x >= 0.0
            && r >= space.r_min
            && r <= space.r_max
            && p.z >= space.z_min
            && p.z <= space.z_max
    }

    #[test]
    fn squared_radius_decides_as_hypot_does_at_and_off_the_bounds() {
        let space = ReachSpace::OSCAR6;
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(5);
        let mut on_bound = 0;
        for _ in 0..20_000 {
            let angle: f64 = rng.random_range(-1.6..1.6);
            let bound = if rng.random_bool(0.5) {
                space.r_min
            } else {
                space.r_max
            };
            // A few ulps either side of a bound, or anywhere in the box.
            let r = if rng.random_bool(0.5) {
                on_bound += 1;
                let ulps: i64 = rng.random_range(-4..=4);
                f64::from_bits((bound.to_bits() as i64 + ulps) as u64)
            } else {
                rng.random_range(0.0..1.2)
            };
            let p = Point3::new(r * angle.cos(), r * angle.sin(), 0.1);
            assert_eq!(space.contains(&p), by_hypot(&space, &p), "{p:?}");
        }
        assert!(on_bound > 5_000);
        for odd in [f64::NAN, f64::INFINITY, 1e-200, 1e200] {
            let p = Point3::new(0.5, odd, 0.1);
            assert_eq!(space.contains(&p), by_hypot(&space, &p), "{p:?}");
        }
    }
}
