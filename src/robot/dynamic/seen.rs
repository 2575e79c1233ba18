//! What the ray-cast camera's rays meet of a body: its collision elements with each
//! collision mesh as its own triangles, where the physics' contacts take the mesh's convex
//! hull. A ray through a concavity of a link (a notch: inside the hull, outside the
//! mesh) passes.

use super::colliders::{contact_compound, parts};
use super::convert::{to_pose, to_vector};
use crate::robot::Shape;
use nalgebra::Isometry3;
use rapier3d_f64::math::Vector;
use rapier3d_f64::parry::shape::{SharedShape, TriMesh};

/// Segments a turn in the triangles of a round primitive on a body with a mesh.
const ROUND_SEGMENTS: u32 = 64;

/// Vertices and triangles (indices into the vertices) of a triangulated surface.
type Triangles = (Vec<Vector>, Vec<[u32; 3]>);

/// The collision elements (poses in the body's frame) as the one shape the camera sees,
/// built once per body: without a mesh among them the contacts' compound, as it is; with
/// one, a parry triangle mesh of every element (its bounding-volume tree built here):
/// meshes as their triangles, primitives beside them as triangles too (a box exactly, a
/// round shape with [`ROUND_SEGMENTS`] a turn). Should parry refuse the triangles, the
/// contacts' compound (the hulls) stands in.
pub(in crate::robot) fn compound(elements: &[(Isometry3<f64>, Shape)]) -> SharedShape {
    if !elements
        .iter()
        .any(|(_, shape)| matches!(shape, Shape::Mesh { .. }))
    {
        return contact_compound(elements);
    }
    let (mut vertices, mut indices): Triangles = (Vec::new(), Vec::new());
    for (pose, shape) in elements {
        let (at, (points, triangles)) = match shape {
            Shape::Mesh { mesh, .. } => (
                to_pose(pose),
                (
                    mesh.mesh
                        .vertices
                        .iter()
                        .map(|p| to_vector(&p.coords))
                        .collect(),
                    mesh.mesh.triangles.clone(),
                ),
            ),
            primitive => {
                let (at, shared) = parts(pose, primitive);
                (at, triangulate(&shared))
            }
        };
        let offset = vertices.len() as u32;
        vertices.extend(points.into_iter().map(|p| at.transform_point(p)));
        indices.extend(triangles.into_iter().map(|t| t.map(|i| i + offset)));
    }
    TriMesh::new(vertices, indices)
        .map(SharedShape::new)
        .unwrap_or_else(|_| contact_compound(elements))
}

/// The surface of a primitive's parry shape as triangles in the shape's frame.
fn triangulate(shape: &SharedShape) -> Triangles {
    if let Some(cuboid) = shape.as_cuboid() {
        cuboid.to_trimesh()
    } else if let Some(ball) = shape.as_ball() {
        ball.to_trimesh(ROUND_SEGMENTS, ROUND_SEGMENTS / 2)
    } else if let Some(cylinder) = shape.as_cylinder() {
        cylinder.to_trimesh(ROUND_SEGMENTS)
    } else if let Some(capsule) = shape.as_capsule() {
        capsule.to_trimesh(ROUND_SEGMENTS, ROUND_SEGMENTS / 2)
    } else {
        unreachable!("a primitive's parts are a box, ball, cylinder or capsule")
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::robot::description::{MeshFormat, MeshGeometry, TriangleMesh};
    use crate::robot::{WorldView, SEEN_BODIES};
    use nalgebra::{Point3, Vector3};
    use rapier3d_f64::math::Pose;
    use std::path::Path;
    use std::sync::Arc;

    /// The U-shaped block of tests/data (its notch at x 0.1–0.2 m, z 0.05–0.2 m) at the
    /// world's origin, with a 5 cm ball beside it, as the camera sees them and as the
    /// contacts do.
    fn u_block() -> (SharedShape, SharedShape) {
        let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/concave/u_block.obj");
        let scale = Vector3::repeat(1.0);
        let mesh = TriangleMesh::read(&path, MeshFormat::Obj, &scale).unwrap();
        let hull = mesh.convex_hull().unwrap();
        let u_block = MeshGeometry {
            filename: "u_block.obj".into(),
            path,
            scale,
            mesh: Arc::new(mesh),
            hull: Some(Arc::new(hull)),
        };
        let ball = Isometry3::translation(-0.2, 0.05, 0.1);
        let elements = [
            (Isometry3::identity(), Shape::mesh(u_block)),
            (ball, Shape::Sphere { radius: 0.05 }),
        ];
        (compound(&elements), contact_compound(&elements))
    }

    /// How far along +y the ray from (x, −1, z) meets `shape` within 2 m, if it does.
    fn met_along_y(shape: &SharedShape, x: f64, z: f64) -> Option<f64> {
        let mut bodies = [None; SEEN_BODIES];
        bodies[0] = Some((Pose::IDENTITY, shape));
        let world = WorldView {
            floor_z: f64::NEG_INFINITY,
            obstacles: &[],
            bodies,
        };
        let origin = Point3::new(x, -1.0, z);
        world
            .cast(&origin, &Vector3::y(), 2.0)
            .map(|hit| hit.distance)
    }

    #[test]
    fn the_camera_sees_through_a_mesh_concavity_that_the_hull_fills() {
        let (seen, contacts) = u_block();
        assert!(seen.as_trimesh().is_some());
        // Through the notch: inside the hull, outside the mesh.
        assert_eq!(met_along_y(&seen, 0.15, 0.15), None);
        let filled = met_along_y(&contacts, 0.15, 0.15).expect("the hull fills the notch");
        assert!((filled - 1.0).abs() < 1e-9, "{filled}");
        // Through the block's post and below the notch: blocked at its front face.
        for (x, z) in [(0.05, 0.15), (0.15, 0.02)] {
            let met = met_along_y(&seen, x, z).expect("the mesh blocks");
            assert!((met - 1.0).abs() < 1e-9, "{met}");
        }
        // The ball beside it, triangulated: met within 0.1 mm of its surface.
        let met = met_along_y(&seen, -0.2, 0.1).expect("the ball blocks");
        assert!((met - 1.0).abs() < 1e-4, "{met}");
    }
}
