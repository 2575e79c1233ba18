//! Continuous servoing on the dynamic simulator: the servos' set-point chases a goal that
//! the trial loop may change at any tick ([`SetPointTracker`]), with the same velocity and
//! acceleration feed-forward a step move's profile gets, and no settling.
//!
//! The kinematic plan cuts each new goal where a straight move from the set-point would
//! meet a joint limit, the wrist's limit or the floor (as it cuts a step move); the
//! set-point then curves from its old heading onto the new one, so between goals it may
//! pass a little off that line: the physics' contacts stop the arm there (held where it
//! is, counted as a contact stop). A step move or a placing ends continuous servoing: the
//! plan takes over from the set-point.

use super::servo_law::SetPoint;
use super::sim::{DynamicSim, SimCounters};
use crate::robot::{Controlled, SetPointTracker, Simulator};

impl DynamicSim {
    /// The set-point tracker, started at rest at the plan's pose when none is running.
    fn tracker(&mut self) -> &mut SetPointTracker {
        let moves = self.settings.moves;
        let at = self.plan_theta();
        self.tracker
            .get_or_insert_with(|| SetPointTracker::at_rest(at, moves.speed, moves.accel))
    }

    /// θ1..θ3 of the plan's pose.
    fn plan_theta(&self) -> Controlled {
        self.model().controlled_of(&self.plan.joints())
    }

    /// The limits of the learned joints (rad): lower and upper.
    fn plan_limits(&self) -> (Controlled, Controlled) {
        let (joints, learned) = (self.model().joints(), self.model().learned());
        (
            Controlled::from_fn(|i, _| joints[learned[i]].lower),
            Controlled::from_fn(|i, _| joints[learned[i]].upper),
        )
    }

    /// Ends continuous servoing: the plan's pose becomes the set-point's, for a step move
    /// or settling to start from.
    pub(super) fn end_servoing(&mut self) {
        if let Some(tracker) = self.tracker.take() {
            // The set-point stays inside θ1..θ3's limits; should the wrist's refuse it,
            // the plan keeps the goal it was last given.
            let _ = self.plan.place(&tracker.point());
        }
    }

    /// Points the set-point at `goal` (θ1..θ3, rad), cut by the plan at a joint limit or
    /// the floor (counted as a contact stop); a non-finite goal is ignored.
    pub(super) fn aim(&mut self, goal: &Controlled) {
        if !goal.iter().all(|v| v.is_finite()) {
            return;
        }
        let from = self.tracker().point();
        if self.plan.place(&from).is_err() {
            // A set-point the wrist's limits refuse: the tick keeps θ1..θ3 within theirs.
            self.tracker().set_goal(*goal);
            return;
        }
        let cut = self.plan.execute(&(goal - from));
        if cut.stopped_by_contact {
            SimCounters::count(&self.counters.contact_stops);
        }
        let reachable = self.plan_theta();
        self.tracker().set_goal(reachable);
    }

    /// One tick toward the goal: the set-point advances, the servos get it with its speed
    /// and acceleration lead (looking one tick ahead, as a step move does), the world
    /// steps. True when a contact stopped the arm: the set-point is then put at rest where
    /// the arm is.
    pub(super) fn servo_step(&mut self) -> bool {
        let dt = self.settings.dt;
        let from = self.tracker().point();
        let last = self.full_set_point(&from, &self.arm.joints());
        let (lower, upper) = self.plan_limits();
        let tracker = self.tracker();
        tracker.step(dt);
        tracker.keep_within(&lower, &upper);
        let mut ahead = *tracker;
        let next_theta = tracker.point();
        ahead.step(dt);
        ahead.keep_within(&lower, &upper);
        let next = self.full_set_point(&next_theta, &last);
        let after = self.full_set_point(&ahead.point(), &next);
        self.tick(&SetPoint::between(&last, &next, &after, dt));
        if !self.arm.stopped_by_contact(&next) {
            return false;
        }
        let moving = !self.tracker().is_at_rest();
        let moves = self.settings.moves;
        let here = self.model().controlled_of(&self.joints());
        self.tracker = Some(SetPointTracker::at_rest(here, moves.speed, moves.accel));
        if moving {
            SimCounters::count(&self.counters.contact_stops);
        }
        true
    }
}
