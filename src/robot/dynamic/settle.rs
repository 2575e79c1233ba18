//! Stepping the arm: following a move's set-point profile tick by tick, then stepping until
//! the joints are close to their set-points and nearly still.

use super::faults::SpeedFault;
use super::servo_law::SetPoint;
use super::sim::{DynamicSim, SimCounters};
use crate::robot::{Controlled, Joints, Simulator};

impl DynamicSim {
    /// One control tick: the servos sent to `set_point`, the arm stepped.
    pub(super) fn tick(&mut self, set_point: &SetPoint) {
        self.arm
            .step(self.plan.model(), Some(set_point), &self.settings);
        SimCounters::count(&self.counters.steps);
        if let Some(fault) = self.arm.speed_fault(self.plan.model()) {
            SimCounters::count(&self.counters.speed_faults);
            self.worst_speed_fault = SpeedFault::worse(self.worst_speed_fault, Some(fault));
        }
        if let Some(ticks) = &mut self.kept_ticks {
            ticks.push(self.arm.joints());
        }
        if let Some(ticks) = &mut self.move_ticks {
            ticks.push(self.arm.joints());
        }
    }

    /// The set-point of the line from `start` (the learned angles) along `delta` at
    /// `fraction`, the wrist solved from the joints `near` (the last set-point).
    fn set_point(
        &self,
        start: &Controlled,
        delta: &Controlled,
        fraction: f64,
        near: &Joints,
    ) -> Joints {
        self.full_set_point(&(start + delta * fraction), near)
    }

    /// The servos' set-point for the learned angles `theta`: the other joints where the
    /// model's wrist solver puts them, starting from their angles in `near` (the last
    /// set-point, as the kinematic simulator warm-starts from its last pose), or held at
    /// them where it finds no solution; each kept inside its limits.
    pub(super) fn full_set_point(&self, theta: &Controlled, near: &Joints) -> Joints {
        let model = self.model();
        let pose = model.pose_near(theta, near);
        let mut q = pose.joints;
        let learned = model.learned();
        for (i, joint) in model.joints().iter().enumerate() {
            if !learned.contains(&i) {
                let angle = if pose.wrist_found { q[i] } else { near[i] };
                q[i] = angle.clamp(joint.lower, joint.upper);
            }
        }
        q
    }

    /// Feeds the move from set-point `start` along `delta` (θ1..θ3) to the servos under the
    /// plan's trapezoidal profile (paced so that no joint is sent faster than its URDF
    /// velocity limit), one tick per step, until a contact stops it: the steps taken,
    /// and whether a contact stopped it. Each tick sends the set-point the step ends at,
    /// with its speed and acceleration there (fed forward), so the arm arrives with the
    /// profile instead of lagging behind it.
    pub(super) fn follow(&mut self, start: &Joints, delta: &Controlled) -> (usize, bool) {
        let profile = self.plan.last_profile();
        let dt = self.settings.dt;
        let ticks = (profile.duration() / dt).ceil() as usize;
        let from = self.model().controlled_of(start);
        let at = |k: usize| profile.fraction_at(k as f64 * dt);
        let now = self.set_point(&from, delta, 0.0, start);
        let (mut now, mut next) = (now, self.set_point(&from, delta, at(1), &now));
        for k in 0..ticks {
            let after = self.set_point(&from, delta, at(k + 2), &next);
            self.tick(&SetPoint::between(&now, &next, &after, dt));
            if self.arm.stopped_by_contact(&next) {
                return (k + 1, true);
            }
            (now, next) = (next, after);
        }
        (ticks, false)
    }

    /// Steps at the current set-point until the arm has settled or the time-out: whether
    /// it settled (a time-out is counted), and the steps taken (at least one).
    pub(super) fn settle(&mut self) -> (bool, usize) {
        let target = self.plan.joints();
        let limit = self.settings.settle_steps().max(1);
        for step in 1..=limit {
            self.tick(&SetPoint::at_rest(target));
            SimCounters::count(&self.counters.settle_steps);
            if self.is_settled(&target) {
                return (true, step);
            }
        }
        SimCounters::count(&self.counters.settle_timeouts);
        (false, limit)
    }

    /// True when every joint is within the position tolerance of `target` and slower than
    /// the speed tolerance.
    fn is_settled(&self, target: &Joints) -> bool {
        let s = &self.settings;
        (self.arm.joints() - target).amax() <= s.settle_position_tol
            && self.arm.speeds().amax() <= s.settle_speed_tol
    }
}
