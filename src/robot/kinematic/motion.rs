//! Moves in joint space: a straight line under a trapezoidal speed profile, stopped at the
//! first joint limit on the way, and the bisection that finds where a move must stop.

use nalgebra::Vector3;

/// A trapezoidal speed profile for a move of the lead joint over `distance` (rad): constant
/// acceleration up to the top speed, cruise, constant deceleration (a triangle when the
/// move is too short to reach top speed).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TrapezoidProfile {
    distance: f64,
    speed: f64,
    accel: f64,
    ramp_time: f64,
    cruise_time: f64,
}

impl TrapezoidProfile {
    /// The profile for `distance` (rad, ≥ 0) at top `speed` (rad/s) and `accel` (rad/s²).
    pub fn new(distance: f64, speed: f64, accel: f64) -> TrapezoidProfile {
        let distance = distance.abs();
        let full_ramp = speed / accel;
        let (ramp_time, cruise_time) = if accel * full_ramp * full_ramp >= distance {
            ((distance / accel).sqrt(), 0.0)
        } else {
            (
                full_ramp,
                (distance - accel * full_ramp * full_ramp) / speed,
            )
        };
        TrapezoidProfile {
            distance,
            speed,
            accel,
            ramp_time,
            cruise_time,
        }
    }

    /// The move's duration (s).
    pub fn duration(&self) -> f64 {
        2.0 * self.ramp_time + self.cruise_time
    }

    /// The fraction of the move done at time `t` (0 before, 1 after the end).
    pub fn fraction_at(&self, t: f64) -> f64 {
        if self.distance == 0.0 || t >= self.duration() {
            return 1.0;
        }
        let t = t.max(0.0);
        let top = self.accel * self.ramp_time;
        let ramp_distance = 0.5 * top * self.ramp_time;
        let covered = if t < self.ramp_time {
            0.5 * self.accel * t * t
        } else if t < self.ramp_time + self.cruise_time {
            ramp_distance + top * (t - self.ramp_time)
        } else {
            let left = self.duration() - t;
            self.distance - 0.5 * self.accel * left * left
        };
        (covered / self.distance).clamp(0.0, 1.0)
    }

    /// The top speed actually reached (rad/s).
    pub fn peak_speed(&self) -> f64 {
        (self.accel * self.ramp_time).min(self.speed)
    }
}

/// How far along `start + s·delta` (s in [0, 1]) the move gets before a joint meets its
/// limit: 1 when none is met; 0 when a joint already sits on a limit it is pushed into.
pub fn limit_stop_fraction(
    start: &Vector3<f64>,
    delta: &Vector3<f64>,
    lower: &Vector3<f64>,
    upper: &Vector3<f64>,
) -> f64 {
    (0..3)
        .map(|i| {
            let end = start[i] + delta[i];
            let bound = if end > upper[i] {
                upper[i]
            } else if end < lower[i] {
                lower[i]
            } else {
                return 1.0;
            };
            ((bound - start[i]) / delta[i]).clamp(0.0, 1.0)
        })
        .fold(1.0, f64::min)
}

/// Bisection steps that find where a move must stop (1e-12 of a move).
pub(crate) const STOP_BISECTIONS: usize = 40;

/// The last fraction of a move found by [`STOP_BISECTIONS`] halvings of [`from`, `to`]
/// at which `holds` is still true, given that it holds at `from` and not at `to`.
pub(crate) fn last_holding(from: f64, to: f64, mut holds: impl FnMut(f64) -> bool) -> f64 {
    let (mut good, mut bad) = (from, to);
    for _ in 0..STOP_BISECTIONS {
        let middle = 0.5 * (good + bad);
        if holds(middle) {
            good = middle;
        } else {
            bad = middle;
        }
    }
    good
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_long_move_cruises_at_top_speed() {
        let p = TrapezoidProfile::new(2.0, 1.0, 2.0);
        // 0.5 s ramps of 0.25 rad each, 1.5 rad cruise at 1 rad/s.
        assert!((p.duration() - 2.5).abs() < 1e-12);
        assert!((p.fraction_at(0.5) - 0.125).abs() < 1e-12);
        assert!((p.fraction_at(1.25) - 0.5).abs() < 1e-12);
        assert_eq!(p.fraction_at(3.0), 1.0);
        assert_eq!(p.peak_speed(), 1.0);
    }

    #[test]
    fn a_short_move_is_a_triangle() {
        let p = TrapezoidProfile::new(0.1, 1.0, 2.0);
        let half = (0.1f64 / 2.0).sqrt();
        assert!((p.duration() - 2.0 * (0.1f64 / 2.0).sqrt()).abs() < 1e-12);
        assert!(p.peak_speed() < 1.0);
        assert!((p.fraction_at(half) - 0.5).abs() < 1e-9);
    }

    #[test]
    fn fractions_rise_monotonically() {
        let p = TrapezoidProfile::new(1.3, 1.5, 3.0);
        let mut last = 0.0;
        for k in 0..=200 {
            let f = p.fraction_at(p.duration() * k as f64 / 200.0);
            assert!(f >= last - 1e-15);
            last = f;
        }
        assert_eq!(last, 1.0);
    }

    #[test]
    fn a_move_stops_at_the_first_limit_on_the_way() {
        let lower = Vector3::new(-1.0, -1.0, -1.0);
        let upper = Vector3::new(1.0, 1.0, 1.0);
        let start = Vector3::new(0.0, 0.5, 0.0);
        // Joint 2 hits its limit halfway, joint 1 would at 2/3 of the way.
        let s = limit_stop_fraction(&start, &Vector3::new(1.5, 1.0, 0.2), &lower, &upper);
        assert!((s - 0.5).abs() < 1e-12);
        assert_eq!(
            limit_stop_fraction(&start, &Vector3::new(0.1, 0.1, 0.1), &lower, &upper),
            1.0
        );
        let on_limit = Vector3::new(1.0, 0.0, 0.0);
        assert_eq!(
            limit_stop_fraction(&on_limit, &Vector3::new(0.3, 0.0, 0.0), &lower, &upper),
            0.0
        );
        assert_eq!(
            limit_stop_fraction(&on_limit, &Vector3::new(-0.3, 0.0, 0.0), &lower, &upper),
            1.0
        );
    }
}
