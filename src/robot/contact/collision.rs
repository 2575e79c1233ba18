//! The arm's collision geometry outside any physics engine: each body's collision elements
//! as the arm is now (the camera on link 6, a stretched link's shapes grown with it), and
//! where a move starts as the floor and contact rules look at it.

use crate::robot::{ArmModel, ArmPose, Controlled, Shape};
use nalgebra::{Isometry3, Unit, Vector3};

/// Shapes never get shorter than this when a link is shortened (m).
const MIN_SIZE: f64 = 1e-3;
/// Cosine above which a shape's axis counts as lying along a link.
const PARALLEL: f64 = 1.0 - 1e-9;

/// Collision elements of a body: shapes and their poses in the body's frame.
pub(crate) type Elements = Vec<(Isometry3<f64>, Shape)>;

/// The collision elements of body `k` (0 the base, then one link per joint; the camera
/// link rides on the last) of `model` as it is now.
pub(crate) fn body_elements(model: &ArmModel, k: usize) -> Elements {
    let links = model.links();
    let mut parts = vec![(Isometry3::identity(), &links[k])];
    if k == model.dof() {
        parts.push((model.camera_mount(), &links[k + 1]));
    }
    let elements = parts.iter().flat_map(|(at, link)| {
        link.collisions
            .iter()
            .map(move |(p, s)| (*at * p, s.clone()))
    });
    match stretch_of(model, k) {
        Some((direction, stretch)) => elements
            .map(|(pose, shape)| stretched(&pose, &shape, &direction, stretch))
            .collect(),
        None => elements.collect(),
    }
}

/// The direction (link frame) and length change (m) of link `k` when it is stretched.
pub(crate) fn stretch_of(model: &ArmModel, k: usize) -> Option<(Unit<Vector3<f64>>, f64)> {
    if !(1..=3).contains(&k) {
        return None;
    }
    let stretch = model.link_stretch(k);
    let far = model.joints()[k].origin.translation.vector;
    (stretch != 0.0).then(|| (Unit::new_normalize(far), stretch))
}

/// The arm where a move starts, as the floor and contact rules first look at it: the
/// controlled angles and the pose solved from them (its link frames included) — worked out
/// once, when the arm got there (the kinematic simulator keeps them between moves).
#[derive(Debug, Clone)]
pub(crate) struct MoveStart {
    /// Its controlled (learned) angles.
    pub theta: Controlled,
    /// The pose (every joint, the camera, the link frames).
    pub pose: ArmPose,
}

impl MoveStart {
    /// The arm at `pose`, which `model` solved for its controlled angles.
    pub(crate) fn at(model: &ArmModel, pose: ArmPose) -> MoveStart {
        MoveStart {
            theta: model.controlled_of(&pose.joints),
            pose,
        }
    }
}

/// The collision element after its link grew by `delta` (m) along `direction` (the link's
/// far joint origin, in the link frame): a cylinder, capsule or box lying along the link
/// gets longer by `delta` and its centre moves by half of it, so it still spans the link
/// from joint to joint; other shapes stay as they are.
pub(crate) fn stretched(
    pose: &Isometry3<f64>,
    shape: &Shape,
    direction: &Unit<Vector3<f64>>,
    delta: f64,
) -> (Isometry3<f64>, Shape) {
    let along = |local: Vector3<f64>| (pose.rotation * local).dot(direction).abs() > PARALLEL;
    let shifted = || {
        let mut moved = *pose;
        moved.translation.vector += direction.into_inner() * (0.5 * delta);
        moved
    };
    let longer = |length: f64| (length + delta).max(MIN_SIZE);
    match *shape {
        Shape::Cylinder { radius, length } if along(Vector3::z()) => (
            shifted(),
            Shape::Cylinder {
                radius,
                length: longer(length),
            },
        ),
        Shape::Capsule { radius, length } if along(Vector3::z()) => (
            shifted(),
            Shape::Capsule {
                radius,
                length: longer(length),
            },
        ),
        Shape::Cuboid(size) => match (0..3).find(|&k| along(Vector3::ith(k, 1.0))) {
            Some(k) => {
                let mut size = size;
                size[k] = longer(size[k]);
                (shifted(), Shape::Cuboid(size))
            }
            None => (*pose, shape.clone()),
        },
        _ => (*pose, shape.clone()),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::FRAC_PI_2;

    #[test]
    fn a_cylinder_along_the_link_spans_it_after_a_stretch() {
        // The upper arm: a 0.6 m cylinder along x, centred halfway to the elbow.
        let pose = Isometry3::new(Vector3::new(0.3, 0.0, 0.0), Vector3::y() * FRAC_PI_2);
        let shape = Shape::Cylinder {
            radius: 0.08,
            length: 0.6,
        };
        let (moved, longer) = stretched(&pose, &shape, &Vector3::x_axis(), 0.1);
        assert!((moved.translation.vector - Vector3::new(0.35, 0.0, 0.0)).norm() < 1e-15);
        assert_eq!(
            longer,
            Shape::Cylinder {
                radius: 0.08,
                length: 0.7
            }
        );
        let ball = Shape::Sphere { radius: 0.05 };
        assert_eq!(
            stretched(&pose, &ball, &Vector3::x_axis(), 0.1),
            (pose, ball)
        );
    }

    #[test]
    fn a_box_grows_along_its_side_that_lies_along_the_link() {
        let pose = Isometry3::translation(0.0, 0.0, 0.1);
        let shape = Shape::Cuboid(Vector3::new(0.1, 0.1, 0.2));
        let (moved, grown) = stretched(&pose, &shape, &Vector3::z_axis(), -0.05);
        let Shape::Cuboid(size) = grown else {
            panic!("still a box: {grown:?}")
        };
        assert!((size - Vector3::new(0.1, 0.1, 0.15)).norm() < 1e-15);
        assert!((moved.translation.vector.z - 0.075).abs() < 1e-15);
    }
}
