//! Frames taken while the arm moves, learned as poses of the trial's path
//! (`learn_during_moves`): the camera takes them at its frame rate from the move's start
//! (on the kinematic simulator along the move's trapezoidal profile, on the dynamic one at
//! the physics tick then), and of each move's frames at most `per_move`, evenly spread and
//! the last the latest before the move ended, join the path between the poses at which
//! moves ended. A frame in which the object is not fully seen is no pose.

use super::trial::TrialLoop;
use crate::learn::Observation;
use nalgebra::Point3;

/// Which frames taken during moves are learned.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MoveFrames {
    /// Frames per second, counted from each move's start.
    pub fps: f64,
    /// At most this many frames of each move are learned.
    pub per_move: usize,
}

impl MoveFrames {
    /// The times (s from the move's start) of the frames learned of a move that took
    /// `duration` seconds: of the frames taken before it ended, at most `per_move`, evenly
    /// spread, the last the latest.
    pub fn times(&self, duration: f64) -> impl Iterator<Item = f64> {
        let period = 1.0 / self.fps;
        // Frames 1..=taken fall strictly inside the move.
        let taken = ((duration / period).ceil() as usize).saturating_sub(1);
        let learned = taken.min(self.per_move);
        (1..=learned).map(move |i| (i * taken).div_ceil(learned) as f64 * period)
    }
}

impl TrialLoop {
    /// Adds to the learning path the frames `frames` picks of the move just made (it took
    /// `duration` s) in which `object` is seen.
    pub(super) fn learn_frames_of_move(
        &mut self,
        frames: &MoveFrames,
        duration: f64,
        object: &Point3<f64>,
    ) {
        for t in frames.times(duration) {
            let Some(q) = self.sim.move_pose_at(t) else {
                return;
            };
            let pose = self.sim.model().camera_pose(&q);
            let Ok(c) = self.camera.read_in(&pose, object, &self.sim.world()) else {
                continue;
            };
            let exact = Observation {
                theta_deg: self.sim.model().controlled_of(&q).map(f64::to_degrees),
                c,
            };
            let seen = self.sensors.report(exact, self.camera.model());
            self.learning_path.push(seen);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_frames_learned_are_spread_over_the_move_the_last_the_latest() {
        let frames = MoveFrames {
            fps: 10.0,
            per_move: 3,
        };
        let times = |d: f64| frames.times(d).collect::<Vec<_>>();
        // Frames at 0.1 .. 0.9 s fall inside a move of 0.95 s; three of them are learned.
        let spread = times(0.95);
        assert_eq!(spread.len(), 3);
        for (t, want) in spread.iter().zip([0.3, 0.6, 0.9]) {
            assert!((t - want).abs() < 1e-12, "{spread:?}");
        }
        // A frame at the end itself is the move's end pose, not a frame during it.
        assert_eq!(times(0.2).len(), 1);
        assert!(times(0.1).is_empty());
        assert!(times(0.0).is_empty());
        let all = MoveFrames {
            fps: 10.0,
            per_move: 100,
        };
        assert_eq!(all.times(0.95).count(), 9);
    }
}
