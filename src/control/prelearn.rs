//! Pre-learning: before trial 1 the learner is given a few moves whose outcome is known, so
//! that it starts with a rough idea of the mapping over the whole joint range.
//!
//! The object is put below the middle of the reach space and the arm at the pose that sees
//! it at the target ("base"). Each of the 8 moves starts from the base pose offset by
//! (±δ1, ±δ2, ±δ3) — every sign combination — and moves back to the base: the reading
//! after it is zero, so each move is an exact learning pattern, and together they span all
//! three joints.

use crate::camera::CameraModel;
use crate::robot::{ArmModel, Controlled, ReachSpace};
use nalgebra::Point3;

/// The offsets (degrees) of the start poses from the base pose.
const OFFSETS_DEG: [f64; 3] = [8.0, 5.0, 6.0];

/// One pre-learning move.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PrelearnMove {
    /// The pose the move starts from (rad).
    pub start: Controlled,
    /// The move (rad).
    pub delta: Controlled,
}

/// The object's centre and the 8 pre-learning moves, or `None` when the model cannot
/// reach the base pose, whose camera is at the middle of `reach`.
pub fn prelearning_moves(
    model: &ArmModel,
    camera: &CameraModel,
    reach: &ReachSpace,
) -> Option<(Point3<f64>, Vec<PrelearnMove>)> {
    let goal = reach.prelearning_goal();
    let base = model.solve_camera_position(&goal).ok()?;
    let object = camera.object_at_goal(&goal);
    let moves = (0..8)
        .map(|corner: usize| {
            let sign = |bit: usize| if corner & (1 << bit) == 0 { -1.0 } else { 1.0 };
            let offset = Controlled::from_fn(|i, _| sign(i) * OFFSETS_DEG[i].to_radians());
            PrelearnMove {
                start: base + offset,
                delta: -offset,
            }
        })
        .collect();
    Some((object, moves))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::camera::{Camera, ProjectionCamera};

    #[test]
    fn every_move_sees_the_object_and_ends_at_the_target() {
        let model = ArmModel::oscar6();
        let camera = ProjectionCamera::default();
        let (object, moves) =
            prelearning_moves(&model, camera.model(), &ReachSpace::OSCAR6).unwrap();
        assert_eq!(moves.len(), 8);
        for m in &moves {
            let start = model.check_limits(&m.start).unwrap();
            assert!(camera.read(&model.camera_pose(&start), &object).is_ok());
            let end = model.full_pose(&(m.start + m.delta));
            let c = camera.read(&model.camera_pose(&end), &object).unwrap();
            assert!(c.norm() < 1e-6, "the move ends at the target: {c}");
        }
        let spread = moves
            .iter()
            .map(|m| m.delta)
            .fold(Controlled::zeros(), |a, d| a + d.abs());
        assert!(
            spread.iter().all(|&s| s > 0.5),
            "all three joints move: {spread}"
        );
    }
}
