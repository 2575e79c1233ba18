//! What each rigid body of the arm is made of: its mass properties and collision elements
//! in its link frame, the camera link merged into link 6, a stretched link grown as a
//! uniform rod (see [`Inertial::stretched`]).

use super::inertia::Inertial;
use crate::robot::collision::{body_elements, stretch_of, Elements};
use crate::robot::ArmModel;
use nalgebra::Isometry3;

/// Body `k` (0 the base, 1–6 the links) of `model` as it is now.
pub(super) fn body_parts(model: &ArmModel, k: usize) -> (Inertial, Elements) {
    let links = model.links();
    let mut parts = vec![Inertial::of_link(&links[k], &Isometry3::identity())];
    if k == 6 {
        parts.push(Inertial::of_link(&links[7], &model.camera_mount()));
    }
    let inertial = Inertial::sum(&parts);
    let inertial = match stretch_of(model, k) {
        Some((direction, stretch)) => {
            let length = model.joints()[k].origin.translation.vector.norm();
            inertial.stretched(&direction, length - stretch, length)
        }
        None => inertial,
    };
    (inertial, body_elements(model, k))
}
