//! The failed trials of a run, counted by why they failed, so a run whose trials all fail
//! can say why.

use crate::camera::NotSeen;
use crate::control::Failure;
use std::fmt;

/// Failed trials by reason (`summary.json`'s `failures_by_reason`).
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub struct FailureTally {
    /// No reachable target was drawn.
    pub unreachable_target: usize,
    /// No start pose from which the object is seen was drawn.
    pub no_start_seen: usize,
    /// The object left the image (cut by the border).
    pub left_the_image: usize,
    /// The object came behind or too close to the camera.
    pub too_close: usize,
    /// Something in the scene (an obstacle, the arm) hid the object.
    pub hidden: usize,
    /// The learner proposed a non-finite move.
    pub non_finite_move: usize,
}

impl FailureTally {
    /// Counts one failed trial.
    pub fn count(&mut self, failure: Failure) {
        let counter = match failure {
            Failure::UnreachableTarget => &mut self.unreachable_target,
            Failure::NoStartSeen => &mut self.no_start_seen,
            Failure::LostObject(NotSeen::OutsideFrame) => &mut self.left_the_image,
            Failure::LostObject(NotSeen::TooClose) => &mut self.too_close,
            Failure::LostObject(NotSeen::Hidden) => &mut self.hidden,
            Failure::NonFiniteMove => &mut self.non_finite_move,
        };
        *counter += 1;
    }

    /// Failed trials in all.
    pub fn total(&self) -> usize {
        self.unreachable_target
            + self.no_start_seen
            + self.left_the_image
            + self.too_close
            + self.hidden
            + self.non_finite_move
    }
}

impl fmt::Display for FailureTally {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let reasons = [
            (self.unreachable_target, "found no reachable target"),
            (
                self.no_start_seen,
                "found no start from which the object is seen",
            ),
            (self.left_the_image, "lost the object out of the image"),
            (self.too_close, "came too close to the object"),
            (self.hidden, "lost the object behind something"),
            (
                self.non_finite_move,
                "got a non-finite move from the learner",
            ),
        ];
        let parts: Vec<String> = reasons
            .iter()
            .filter(|(n, _)| *n > 0)
            .map(|(n, why)| format!("{n} {why}"))
            .collect();
        if parts.is_empty() {
            f.write_str("none failed")
        } else {
            f.write_str(&parts.join(", "))
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn failures_are_counted_and_said_by_reason() {
        let mut tally = FailureTally::default();
        assert_eq!(tally.to_string(), "none failed");
        tally.count(Failure::LostObject(NotSeen::OutsideFrame));
        tally.count(Failure::LostObject(NotSeen::OutsideFrame));
        tally.count(Failure::UnreachableTarget);
        assert_eq!(tally.total(), 3);
        assert_eq!(
            tally.to_string(),
            "1 found no reachable target, 2 lost the object out of the image"
        );
    }
}
