//! A trial's draws: a target the arm can reach and a start from which the object is seen.

use super::outcome::Failure;
use super::TrialLoop;
use crate::learn::Observation;
use nalgebra::Point3;

/// Draws of a reachable target, or of a start from which it is seen, before giving up.
const MAX_DRAWS: usize = 10_000;

impl TrialLoop {
    /// The object's centre for a target drawn uniformly in the reach space, reachable by
    /// the robot as it is now and not inside an obstacle.
    pub(super) fn draw_target(&mut self) -> Result<Point3<f64>, Failure> {
        let model = *self.camera.model();
        for _ in 0..MAX_DRAWS {
            let goal = self.reach.sample(&mut self.rng);
            let object = model.object_at_goal(&goal);
            let inside = |o: &crate::robot::Obstacle| o.overlaps_ball(&object, model.object_radius);
            if self.sim.model().solve_camera_position(&goal).is_ok()
                && !self.sim.obstacles().iter().any(inside)
            {
                return Ok(object);
            }
        }
        Err(Failure::UnreachableTarget)
    }

    /// Places the arm at a start drawn uniformly in the reach space from which the object
    /// is seen, and observes it there.
    pub(super) fn draw_start(&mut self, object: &Point3<f64>) -> Result<Observation, Failure> {
        for _ in 0..MAX_DRAWS {
            let at = self.reach.sample(&mut self.rng);
            // Most draws do not see the object: skip their inverse kinematics.
            if !self.camera.model().may_see_from_above(&at, object) {
                continue;
            }
            let Ok(theta) = self.sim.model().solve_camera_position(&at) else {
                continue;
            };
            if self.sim.place(&theta).is_ok() {
                if let Ok(seen) = self.observe(object) {
                    return Ok(seen);
                }
            }
        }
        Err(Failure::NoStartSeen)
    }
}
