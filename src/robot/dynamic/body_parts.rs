//! What each rigid body of the arm is made of: its mass properties and collision elements
//! in its link frame, with the camera link merged into link 6 and a stretched link grown
//! as a uniform rod (see [`Inertial::stretched`] and [`stretched`]).

use super::colliders::stretched;
use super::inertia::Inertial;
use crate::robot::{ArmModel, Shape};
use nalgebra::{Isometry3, Unit};

/// Collision elements of a body: shapes and their poses in the body's frame.
pub(super) type Elements = Vec<(Isometry3<f64>, Shape)>;

/// Body `k` (0 the base, 1–6 the links) of `model` as it is now.
pub(super) fn body_parts(model: &ArmModel, k: usize) -> (Inertial, Elements) {
    let links = model.links();
    let mut parts = vec![(Isometry3::identity(), &links[k])];
    if k == 6 {
        parts.push((model.camera_mount(), &links[7]));
    }
    let inertial = Inertial::sum(
        &parts
            .iter()
            .map(|(at, link)| Inertial::of_link(link, at))
            .collect::<Vec<_>>(),
    );
    let elements: Elements = parts
        .iter()
        .flat_map(|(at, link)| link.collisions.iter().map(move |(p, s)| (*at * p, *s)))
        .collect();
    let stretch = if (1..=3).contains(&k) {
        model.link_stretch(k)
    } else {
        0.0
    };
    if stretch == 0.0 {
        return (inertial, elements);
    }
    let far = model.joints()[k].origin.translation.vector;
    let direction = Unit::new_normalize(far);
    let length = far.norm();
    (
        inertial.stretched(&direction, length - stretch, length),
        elements
            .iter()
            .map(|(pose, shape)| stretched(pose, shape, &direction, stretch))
            .collect(),
    )
}
