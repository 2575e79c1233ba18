//! Colliders from the URDF's collision geometry, and how they follow a stretched link.

use super::convert::to_pose;
use crate::robot::Shape;
use nalgebra::{Isometry3, Unit, UnitQuaternion, Vector3};
use rapier3d_f64::prelude::{ColliderBuilder, SharedShape};
use std::f64::consts::FRAC_PI_2;

/// Shapes never get shorter than this when a link is shortened (m).
const MIN_SIZE: f64 = 1e-3;
/// Cosine above which a shape's axis counts as lying along a link.
const PARALLEL: f64 = 1.0 - 1e-9;

/// The one collider of a body: its collision elements (poses in the body's frame) as a
/// compound shape at the body's origin, without mass. One massless collider at the origin
/// adds nothing to the body's mass properties, so Rapier keeps the principal frame they
/// were given (adding a massless collider elsewhere makes it diagonalise the tensor again,
/// and lose the axes of a repeated moment).
pub(super) fn collider(elements: &[(Isometry3<f64>, Shape)]) -> ColliderBuilder {
    ColliderBuilder::new(compound(elements)).density(0.0)
}

/// The collision elements as one shape.
pub(super) fn compound(elements: &[(Isometry3<f64>, Shape)]) -> SharedShape {
    SharedShape::compound(
        elements
            .iter()
            .map(|(pose, shape)| parts(pose, shape))
            .collect(),
    )
}

/// The Rapier pose and shape of a URDF collision element. URDF cylinders run along z,
/// parry's along y: they are turned by 90° about x.
pub(super) fn parts(
    pose: &Isometry3<f64>,
    shape: &Shape,
) -> (rapier3d_f64::math::Pose, SharedShape) {
    match *shape {
        Shape::Cuboid(size) => (
            to_pose(pose),
            SharedShape::cuboid(0.5 * size.x, 0.5 * size.y, 0.5 * size.z),
        ),
        Shape::Cylinder { radius, length } => {
            let z_along_y = UnitQuaternion::from_axis_angle(&Vector3::x_axis(), FRAC_PI_2);
            (
                to_pose(&(pose * z_along_y)),
                SharedShape::cylinder(0.5 * length, radius),
            )
        }
        Shape::Capsule { radius, length } => {
            (to_pose(pose), SharedShape::capsule_z(0.5 * length, radius))
        }
        Shape::Sphere { radius } => (to_pose(pose), SharedShape::ball(radius)),
    }
}

/// The collision element after its link grew by `delta` (m) along `direction` (the link's
/// far joint origin, in the link frame): a cylinder, capsule or box lying along the link
/// gets longer by `delta` and its centre moves by half of it, so it still spans the link
/// from joint to joint; other shapes stay as they are.
pub(super) fn stretched(
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
            None => (*pose, *shape),
        },
        _ => (*pose, *shape),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

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

    #[test]
    fn urdf_cylinders_lie_along_their_z_axis() {
        let shape = Shape::Cylinder {
            radius: 0.1,
            length: 0.5,
        };
        let (pose, shared) = parts(&Isometry3::identity(), &shape);
        let top = pose.transform_point(rapier3d_f64::math::Vector::new(0.0, 0.25, 0.0));
        assert!((top.z - 0.25).abs() < 1e-12 && top.y.abs() < 1e-12);
        assert!(shared.as_cylinder().is_some());
    }
}
