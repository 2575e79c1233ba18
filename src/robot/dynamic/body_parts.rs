//! What each rigid body of the arm is made of: its mass properties and collision elements
//! in its link frame, the camera link merged into the last body, a stretched link grown as
//! a uniform rod (see [`Inertial::stretched`]), a massless body given a small mass.

use super::inertia::Inertial;
use crate::robot::contact::collision::{body_elements, stretch_of, Elements};
use crate::robot::ArmModel;
use nalgebra::Isometry3;

/// Body `k` (0 the base, then one per joint) of `model` as it is now.
pub(super) fn body_parts(model: &ArmModel, k: usize) -> (Inertial, Elements) {
    let links = model.links();
    let mut parts = vec![Inertial::of_link(&links[k], &Isometry3::identity())];
    let last = model.dof();
    if k == last {
        parts.push(Inertial::of_link(&links[last + 1], &model.camera_mount()));
    }
    let inertial = Inertial::sum(&parts).at_least_minimal();
    let inertial = match stretch_of(model, k) {
        Some((direction, stretch)) => {
            let length = model.joints()[k].origin.translation.vector.norm();
            inertial.stretched(&direction, length - stretch, length)
        }
        None => inertial,
    };
    (inertial, body_elements(model, k))
}
