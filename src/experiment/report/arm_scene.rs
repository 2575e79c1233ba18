//! The arm as the report's 3-D view draws it: every link of the run's robot description in
//! the chain body it rides with, each drawn with its visual shapes (its collision shapes
//! where it has no visual one), meshes as triangle lists, and the body frames of a pose.

use super::json::{base64_f32, base64_u32, pose_json};
use crate::experiment::setup::{arm_settings, load_description};
use crate::experiment::show::RecordedRun;
use crate::robot::description::{GeometryElement, RobotDescription, Shape, TriangleMesh};
use crate::robot::{ArmModel, DescriptionError, Joints};
use nalgebra::Isometry3;
use serde_json::{json, Value};
use std::sync::Arc;

/// A shape of the arm placed in a chain body.
#[derive(Debug, Clone)]
struct Part {
    /// The body (0 the root, k the body joint k moves).
    body: usize,
    /// The shape's frame in the body frame.
    origin: Isometry3<f64>,
    /// The shape.
    shape: Shape,
    /// The link it belongs to.
    link: String,
}

/// The arm's shapes, body by body, and where its description came from.
#[derive(Debug, Clone)]
pub struct ArmScene {
    parts: Vec<Part>,
    bodies: usize,
    /// The robot's name in its URDF.
    pub robot: String,
    /// How many parts are meshes read from files.
    pub mesh_parts: usize,
}

impl ArmScene {
    /// The arm of `run`, read again from the URDF its `info` names.
    pub fn of(run: &RecordedRun) -> Result<ArmScene, DescriptionError> {
        let config = &run.setup.config;
        let description = load_description(config, run.urdf.as_deref())?;
        let chain = arm_settings(config).chain(&description)?;
        let mut parts = Vec::new();
        for (body, chain_body) in chain.bodies.iter().enumerate() {
            for (link, pose) in &chain_body.links {
                add_link(&mut parts, &description, body, *link, pose);
            }
        }
        for held in &chain.held {
            let Some(body) = held.body else { continue };
            let joint = &description.joints[held.joint];
            let parent = chain.bodies[body]
                .links
                .iter()
                .find(|(link, _)| *link == joint.parent);
            if let Some((_, pose)) = parent {
                let pose = pose * joint.transform(held.position);
                add_link(&mut parts, &description, body, joint.child, &pose);
            }
        }
        let mesh_parts = parts
            .iter()
            .filter(|p| matches!(p.shape, Shape::Mesh { .. }))
            .count();
        Ok(ArmScene {
            parts,
            bodies: chain.bodies.len(),
            robot: description.name.clone(),
            mesh_parts,
        })
    }

    /// The frame of every body (root first) at joint angles `joints` of `model` (the arm as
    /// it was in the trial: links stretched, camera turned).
    pub fn body_frames(&self, model: &ArmModel, joints: &Joints) -> Vec<Isometry3<f64>> {
        let mut frames = vec![Isometry3::identity()];
        frames.extend(model.link_frames(joints).iter().copied());
        frames.truncate(self.bodies);
        frames
    }

    /// The parts and their meshes as the page reads them: `meshes` (base64 little-endian
    /// f32 positions and u32 indices) and `parts` (body, origin, shape, link).
    pub fn to_json(&self) -> Value {
        let mut meshes: Vec<Arc<TriangleMesh>> = Vec::new();
        let parts: Vec<Value> = self
            .parts
            .iter()
            .map(|part| {
                let shape = match &part.shape {
                    Shape::Mesh { mesh, .. } => {
                        let index = meshes
                            .iter()
                            .position(|m| Arc::ptr_eq(m, &mesh.mesh))
                            .unwrap_or_else(|| {
                                meshes.push(mesh.mesh.clone());
                                meshes.len() - 1
                            });
                        json!({"kind": "mesh", "mesh": index})
                    }
                    Shape::Cuboid(size) => json!({"kind": "box", "size": [size.x, size.y, size.z]}),
                    Shape::Cylinder { radius, length } => {
                        json!({"kind": "cylinder", "radius": radius, "length": length})
                    }
                    Shape::Capsule { radius, length } => {
                        json!({"kind": "capsule", "radius": radius, "length": length})
                    }
                    Shape::Sphere { radius } => json!({"kind": "sphere", "radius": radius}),
                };
                json!({
                    "body": part.body,
                    "link": part.link,
                    "origin": pose_json(&part.origin),
                    "shape": shape,
                })
            })
            .collect();
        let meshes: Vec<Value> = meshes.iter().map(|m| mesh_json(m)).collect();
        json!({"robot": self.robot, "bodies": self.bodies, "parts": parts, "meshes": meshes})
    }
}

/// Adds the shapes of description link `link`, posed at `pose` in body `body`: its visual
/// elements, or its collision elements when it has none.
fn add_link(
    parts: &mut Vec<Part>,
    description: &RobotDescription,
    body: usize,
    link: usize,
    pose: &Isometry3<f64>,
) {
    let link = &description.links[link];
    let elements: &[GeometryElement] = if link.visuals.is_empty() {
        &link.collisions
    } else {
        &link.visuals
    };
    parts.extend(elements.iter().map(|element| Part {
        body,
        origin: pose * element.origin,
        shape: element.geometry.clone(),
        link: link.name.clone(),
    }));
}

fn mesh_json(mesh: &TriangleMesh) -> Value {
    let positions: Vec<f32> = mesh
        .vertices
        .iter()
        .flat_map(|p| [p.x as f32, p.y as f32, p.z as f32])
        .collect();
    let indices: Vec<u32> = mesh.triangles.iter().flatten().copied().collect();
    json!({"positions": base64_f32(&positions), "indices": base64_u32(&indices)})
}
