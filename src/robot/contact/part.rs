//! A collision element as the contact rules measure it: its parry shape (a mesh as its
//! convex hull, with the hull's bounding box to try first) and the capsule that holds it.

use super::capsule::{box_capsule, segment_distance, Capsule};
use crate::robot::dynamic::{parts, to_pose};
use crate::robot::Shape;
use nalgebra::{Isometry3, Point3, Translation3, Vector3};
use rapier3d_f64::math::Pose;
use rapier3d_f64::parry::query::distance;
use rapier3d_f64::parry::shape::SharedShape;

/// A pair whose distance bound is under this (m) is measured exactly.
pub(super) const NEAR: f64 = 0.01;

/// A collision element: its parry shape at its pose in the body frame, the box around it
/// when it is a mesh's hull (pose and shape), and the capsule that holds it (segment ends
/// in the body frame, radius).
#[derive(Debug, Clone)]
pub(super) struct Part {
    pub(super) pose: Pose,
    pub(super) shape: SharedShape,
    boxed: Option<(Pose, SharedShape)>,
    pub(super) capsule: Capsule,
}

impl Part {
    /// The distance (m) from this part placed at `at` to `other`'s `shape` at `pose`: exact
    /// for a primitive and for a hull under [`NEAR`], the hull's box's distance above it.
    pub(super) fn distance_to(
        &self,
        at: &Pose,
        pose: &Pose,
        shape: &dyn rapier3d_f64::parry::shape::Shape,
    ) -> f64 {
        if let Some((box_pose, cuboid)) = &self.boxed {
            let bound = exact(&(at * box_pose), cuboid.as_ref(), pose, shape);
            if bound >= NEAR {
                return bound;
            }
        }
        exact(&(at * self.pose), self.shape.as_ref(), pose, shape)
    }
}

/// An element as a part: its parry shape and the capsule that holds it.
pub(super) fn part((pose, shape): &(Isometry3<f64>, Shape)) -> Part {
    let along = |half: f64, axis: Vector3<f64>| {
        [
            pose * Point3::from(axis * -half),
            pose * Point3::from(axis * half),
        ]
    };
    let (ends, radius) = match *shape {
        Shape::Sphere { radius } => (along(0.0, Vector3::z()), radius),
        Shape::Cylinder { radius, length } | Shape::Capsule { radius, length } => {
            (along(0.5 * length, Vector3::z()), radius)
        }
        Shape::Cuboid(size) => box_capsule(pose, &Vector3::zeros(), &size),
        Shape::Mesh { centre, size, .. } => box_capsule(pose, &centre, &size),
    };
    let boxed = match shape {
        Shape::Mesh { centre, size, .. } => Some(parts(
            &(pose * Translation3::from(*centre)),
            &Shape::Cuboid(*size),
        )),
        _ => None,
    };
    let (pose, shape) = parts(pose, shape);
    Part {
        pose,
        shape,
        boxed,
        capsule: Capsule { ends, radius },
    }
}

/// The distance between parts `a` and `b` of bodies at `at_a` and `at_b`: exact under
/// [`NEAR`], a lower bound above it (a hull's box's distance).
pub(super) fn parts_distance(
    a: &Part,
    at_a: &Isometry3<f64>,
    b: &Part,
    at_b: &Isometry3<f64>,
) -> f64 {
    let (at_a, at_b) = (to_pose(at_a), to_pose(at_b));
    if let Some((box_pose, cuboid)) = &b.boxed {
        let bound = a.distance_to(&at_a, &(at_b * box_pose), cuboid.as_ref());
        if bound >= NEAR {
            return bound;
        }
    }
    a.distance_to(&at_a, &(at_b * b.pose), b.shape.as_ref())
}

/// The capsule that holds all of a body's parts: the longest part's segment, wide enough
/// to reach every part's farthest point (distance to a segment is convex, so a part's
/// farthest point lies at one of its own segment's ends, plus its radius).
pub(super) fn hull(parts: &[Part]) -> Option<Capsule> {
    let longest = parts.iter().max_by(|a, b| {
        let length = |p: &Part| (p.capsule.ends[1] - p.capsule.ends[0]).norm();
        length(a).total_cmp(&length(b))
    })?;
    let [p, q] = &longest.capsule.ends;
    let radius = parts
        .iter()
        .flat_map(|part| {
            part.capsule
                .ends
                .iter()
                .map(move |e| segment_distance(p, q, e, e) + part.capsule.radius)
        })
        .fold(0.0, f64::max);
    Some(Capsule {
        ends: [*p, *q],
        radius,
    })
}

/// The exact distance between two shapes (0 when they touch; the bound 0 when parry cannot
/// measure the pair).
pub(super) fn exact(
    a: &Pose,
    shape_a: &dyn rapier3d_f64::parry::shape::Shape,
    b: &Pose,
    shape_b: &dyn rapier3d_f64::parry::shape::Shape,
) -> f64 {
    distance(a, shape_a, b, shape_b).map_or(0.0, |d| d.distance)
}
