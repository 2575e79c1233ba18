//! The reach space of the camera centre: the study's open half cylinder.

use nalgebra::Point3;
use rand::Rng;

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
        let r = p.x.hypot(p.y);
        p.x >= 0.0 && r >= self.r_min && r <= self.r_max && p.z >= self.z_min && p.z <= self.z_max
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
