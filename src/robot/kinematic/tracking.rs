//! Continuous servoing's set-point: a point in (θ1, θ2, θ3) that heads for a goal which may
//! change at any tick, under the lead joint's speed and acceleration limits, keeping its
//! velocity when the goal changes (an online trajectory generator). For a goal set once
//! from rest it runs the same straight line and trapezoidal profile as a step move.

use crate::robot::Controlled;

/// Below this lead-joint distance (rad) the set-point counts as at its goal.
const ARRIVED: f64 = 1e-12;

/// A set-point chasing a goal.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SetPointTracker {
    point: Controlled,
    velocity: Controlled,
    goal: Controlled,
    speed: f64,
    accel: f64,
}

impl SetPointTracker {
    /// A set-point at rest at `point`, heading nowhere, whose lead joint may turn at
    /// `speed` (rad/s) and accelerate at `accel` (rad/s²).
    pub fn at_rest(point: Controlled, speed: f64, accel: f64) -> SetPointTracker {
        SetPointTracker {
            point,
            velocity: Controlled::zeros(),
            goal: point,
            speed,
            accel,
        }
    }

    /// Sends the set-point to `goal` from where it is now, with the velocity it has.
    pub fn set_goal(&mut self, goal: Controlled) {
        self.goal = goal;
    }

    /// The set-point now.
    pub fn point(&self) -> Controlled {
        self.point
    }

    /// The set-point's velocity (rad/s).
    pub fn velocity(&self) -> Controlled {
        self.velocity
    }

    /// True when the set-point sits still on its goal.
    pub fn is_at_rest(&self) -> bool {
        self.point == self.goal && self.velocity == Controlled::zeros()
    }

    /// Advances the set-point by `dt` (s): its velocity turns toward the goal along the
    /// straight line, no faster than the speed limit nor than it can still brake from
    /// (lead joint), changing by at most `accel·dt` on the lead component; then it moves.
    pub fn step(&mut self, dt: f64) {
        if self.is_at_rest() {
            return;
        }
        let to_go = self.goal - self.point;
        let distance = to_go.amax();
        let wanted = if distance > ARRIVED {
            let top = self
                .speed
                .min(self.braking_speed(distance, dt))
                .min(distance / dt);
            to_go * (top / distance)
        } else {
            Controlled::zeros()
        };
        let change = wanted - self.velocity;
        let most = self.accel * dt;
        let lead = change.amax();
        self.velocity += if lead > most {
            change * (most / lead)
        } else {
            change
        };
        self.point += self.velocity * dt;
        if (self.goal - self.point).amax() <= ARRIVED && self.velocity.amax() <= most {
            self.point = self.goal;
            self.velocity = Controlled::zeros();
        }
    }

    /// Keeps the set-point within `lower..=upper` (rad, each joint), stopping a joint
    /// that reaches a bound; the goal is kept within them too.
    pub fn keep_within(&mut self, lower: &Controlled, upper: &Controlled) {
        for i in 0..3 {
            let inside = self.point[i].clamp(lower[i], upper[i]);
            if inside != self.point[i] {
                self.point[i] = inside;
                self.velocity[i] = 0.0;
            }
            self.goal[i] = self.goal[i].clamp(lower[i], upper[i]);
        }
    }

    /// The highest lead speed from which braking by `accel·dt` a tick stops within
    /// `distance` (rad), counting the tick's own travel.
    fn braking_speed(&self, distance: f64, dt: f64) -> f64 {
        let a = self.accel;
        a * dt * ((0.25 + 2.0 * distance / (a * dt * dt)).sqrt() - 0.5)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::robot::TrapezoidProfile;

    const DT: f64 = 0.005;

    fn run_until_at_rest(tracker: &mut SetPointTracker, limit: usize) -> (usize, f64, f64) {
        let (mut top_speed, mut top_accel) = (0.0f64, 0.0f64);
        for tick in 1..=limit {
            let before = tracker.velocity();
            tracker.step(DT);
            top_speed = top_speed.max(tracker.velocity().amax());
            top_accel = top_accel.max((tracker.velocity() - before).amax() / DT);
            if tracker.is_at_rest() {
                return (tick, top_speed, top_accel);
            }
        }
        panic!("not at rest after {limit} ticks: {tracker:?}");
    }

    #[test]
    fn a_goal_from_rest_is_reached_on_the_straight_line_in_the_profile_time() {
        let (speed, accel) = (1.5, 3.0);
        let start = Controlled::new(0.1, 0.5, 1.2);
        let goal = Controlled::new(0.9, 0.2, 1.0);
        let mut tracker = SetPointTracker::at_rest(start, speed, accel);
        tracker.set_goal(goal);
        let mut off_line = 0.0f64;
        let line = (goal - start).normalize();
        let mut ticks = 0;
        while !tracker.is_at_rest() {
            tracker.step(DT);
            let along = tracker.point() - start;
            off_line = off_line.max((along - line * along.dot(&line)).norm());
            ticks += 1;
        }
        assert_eq!(tracker.point(), goal);
        assert!(off_line < 1e-12, "left the line by {off_line}");
        let profile = TrapezoidProfile::new((goal - start).amax(), speed, accel).duration();
        let took = ticks as f64 * DT;
        assert!(
            (took - profile).abs() < 0.03,
            "{took} s against {profile} s"
        );
    }

    #[test]
    fn a_changed_goal_is_reached_within_the_limits_without_stopping_first() {
        let (speed, accel) = (1.5, 3.0);
        let mut tracker = SetPointTracker::at_rest(Controlled::zeros(), speed, accel);
        tracker.set_goal(Controlled::new(1.0, 0.0, 0.0));
        for _ in 0..60 {
            tracker.step(DT);
        }
        let moving = tracker.velocity().amax();
        assert!(moving > 0.5, "under way: {moving} rad/s");
        let goal = Controlled::new(0.2, 0.6, -0.3);
        tracker.set_goal(goal);
        let (_, top_speed, top_accel) = run_until_at_rest(&mut tracker, 2000);
        assert_eq!(tracker.point(), goal);
        assert!(top_speed <= speed + 1e-9, "speed {top_speed}");
        assert!(top_accel <= accel + 1e-9, "acceleration {top_accel}");
    }

    #[test]
    fn kept_within_bounds_a_joint_stops_at_its_bound() {
        let mut tracker = SetPointTracker::at_rest(Controlled::zeros(), 1.0, 2.0);
        tracker.set_goal(Controlled::new(0.5, 0.5, 0.0));
        let (lower, upper) = (Controlled::repeat(-1.0), Controlled::new(1.0, 0.2, 1.0));
        for _ in 0..2000 {
            tracker.step(DT);
            tracker.keep_within(&lower, &upper);
            assert!(tracker.point().y <= 0.2);
        }
        assert!(tracker.is_at_rest());
        assert_eq!(tracker.point(), Controlled::new(0.5, 0.2, 0.0));
    }

    #[test]
    fn at_rest_on_its_goal_it_stays() {
        let point = Controlled::new(0.3, 0.4, 0.5);
        let mut tracker = SetPointTracker::at_rest(point, 1.0, 2.0);
        tracker.step(DT);
        assert_eq!(tracker.point(), point);
        assert!(tracker.is_at_rest());
    }
}
