//! Pre-learning: before trial 1 the learner is given a few moves whose outcome is known, so
//! that it starts with a rough idea of the mapping over the whole joint range.
//!
//! The object is put below the middle of the reach space and the arm at the pose that sees
//! it at the target ("base"). Each of the 8 moves starts from the base pose offset by
//! (±δ1, ±δ2, ±δ3) — every sign combination — and moves back to the base: the reading
//! after it is zero, so each move is an exact learning pattern, and together they span all
//! three joints.

use crate::camera::CameraModel;
use crate::robot::{ArmModel, Controlled};
use nalgebra::{Point3, Vector3};

/// Where the camera is at the end of every pre-learning move (m): mid-radius, mid-height.
const BASE_GOAL: [f64; 3] = [0.695, 0.0, 0.26];
/// The offsets (degrees) of the start poses from the base pose.
const OFFSETS_DEG: [f64; 3] = [10.0, 6.0, 8.0];

/// The object's centre and the 8 pre-learning moves (start pose, move; rad), or `None`
/// when the model cannot reach the base pose.
pub fn prelearning_moves(
    model: &ArmModel,
    camera: &CameraModel,
) -> Option<(Point3<f64>, Vec<(Controlled, Controlled)>)> {
    let goal = Point3::from(BASE_GOAL);
    let base = model.solve_camera_position(&goal).ok()?;
    let object = goal - Vector3::z() * camera.standoff;
    let moves = (0..8)
        .map(|corner: usize| {
            let sign = |bit: usize| if corner & (1 << bit) == 0 { -1.0 } else { 1.0 };
            let offset = Controlled::from_fn(|i, _| sign(i) * OFFSETS_DEG[i].to_radians());
            (base + offset, -offset)
        })
        .collect();
    Some((object, moves))
}
