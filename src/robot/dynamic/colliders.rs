//! Rapier colliders from the URDF's collision geometry: primitives, and the convex hulls of
//! collision meshes (the contacts' shapes; the camera's are in `seen.rs`).

use super::convert::{to_pose, to_vector};
use crate::robot::description::TriangleMesh;
use crate::robot::Shape;
use nalgebra::{Isometry3, Translation3, UnitQuaternion, Vector3};
use rapier3d_f64::prelude::{ColliderBuilder, SharedShape};
use std::f64::consts::FRAC_PI_2;

/// The one collider of a body: its collision elements (poses in the body's frame) as a
/// compound shape at the body's origin, without mass. One massless collider at the origin
/// adds nothing to the body's mass properties, so Rapier keeps the principal frame they
/// were given (adding a massless collider elsewhere makes it diagonalise the tensor again,
/// and lose the axes of a repeated moment).
pub(super) fn collider(elements: &[(Isometry3<f64>, Shape)]) -> ColliderBuilder {
    ColliderBuilder::new(contact_compound(elements)).density(0.0)
}

/// The collision elements as one shape for contacts: a mesh as its convex hull.
pub(super) fn contact_compound(elements: &[(Isometry3<f64>, Shape)]) -> SharedShape {
    SharedShape::compound(
        elements
            .iter()
            .map(|(pose, shape)| parts(pose, shape))
            .collect(),
    )
}

/// The Rapier pose and shape of a URDF collision element. URDF cylinders run along z,
/// parry's along y: they are turned by 90° about x.
pub(in crate::robot) fn parts(
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
        Shape::Mesh {
            ref mesh,
            centre,
            size,
        } => match convex(mesh.hull_or_mesh()) {
            Some(hull) => (to_pose(pose), hull),
            None => parts(&(pose * Translation3::from(centre)), &Shape::Cuboid(size)),
        },
    }
}

/// A closed convex mesh as a parry convex polyhedron (its vertices' hull should parry not
/// take the triangles as they are); `None` for a flat one, which the description refuses.
fn convex(mesh: &TriangleMesh) -> Option<SharedShape> {
    let points: Vec<_> = mesh.vertices.iter().map(|p| to_vector(&p.coords)).collect();
    SharedShape::convex_mesh(points.clone(), &mesh.triangles)
        .or_else(|| SharedShape::convex_hull(&points))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::robot::description::MeshGeometry;

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

    #[test]
    fn a_hull_collides_as_a_convex_polyhedron() {
        let corner = |x: f64, y: f64, z: f64| nalgebra::Point3::new(x, y, z);
        // A tetrahedron with a corner at the origin and its faces turned outwards.
        let tetrahedron = TriangleMesh {
            vertices: vec![
                corner(0.0, 0.0, 0.0),
                corner(0.1, 0.0, 0.0),
                corner(0.0, 0.1, 0.0),
                corner(0.0, 0.0, 0.1),
            ],
            triangles: vec![[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]],
        };
        let (_, shape) = parts(
            &Isometry3::identity(),
            &Shape::mesh(MeshGeometry {
                filename: "tetrahedron.obj".into(),
                path: "tetrahedron.obj".into(),
                scale: Vector3::repeat(1.0),
                mesh: tetrahedron.clone().into(),
                hull: Some(tetrahedron.into()),
            }),
        );
        let polyhedron = shape.as_convex_polyhedron().expect("a convex polyhedron");
        assert_eq!(polyhedron.points().len(), 4);
    }
}
