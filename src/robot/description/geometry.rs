//! A link's visual and collision geometry: primitives as the URDF gives them, meshes read
//! from disk (shared between elements that name the same file and scale), and the capsule
//! that stands in for a collision mesh that is not there.

use super::convert::pose;
use super::mesh::{MeshFormat, TriangleMesh};
use super::ranges::{within, MAX_LENGTH_M, MESH_SCALE, MIN_SIZE_M};
use super::resolve::{resolve_mesh, MeshPathError};
use super::{DescriptionErrorKind as Kind, DescriptionWarning};
use nalgebra::{Isometry3, Point3, Translation3, UnitQuaternion, Vector3};
use std::collections::HashMap;
use std::path::{Path, PathBuf};
use std::sync::Arc;

/// A shape in a geometry element's frame (m): the one shape type of eyehand, the
/// description's visual and collision elements and the arm model's collision shapes.
#[derive(Debug, Clone, PartialEq)]
pub enum Shape {
    /// A box with these full side lengths along x, y, z.
    Cuboid(Vector3<f64>),
    /// A cylinder along z, centred on the origin.
    Cylinder {
        /// Radius.
        radius: f64,
        /// Length.
        length: f64,
    },
    /// A capsule along z, centred on the origin.
    Capsule {
        /// Radius.
        radius: f64,
        /// Length of the segment between the two half-balls' centres.
        length: f64,
    },
    /// A ball centred on the origin.
    Sphere {
        /// Radius.
        radius: f64,
    },
    /// A triangle mesh read from a file. As a collision element the ray-cast camera sees
    /// its triangles, the physics' contacts its convex hull, the floor and contact rules
    /// the hull's bounding box.
    Mesh {
        /// The mesh as read, with its hull.
        mesh: Arc<MeshGeometry>,
        /// The centre of the bounding box of its hull (of the mesh itself when it has no
        /// hull).
        centre: Vector3<f64>,
        /// That box's side lengths.
        size: Vector3<f64>,
    },
}

impl Shape {
    /// The shape of `mesh`, with the bounding box of its hull (of the mesh without one).
    pub fn mesh(mesh: MeshGeometry) -> Shape {
        let (low, high) = mesh.hull_or_mesh().vertices.iter().fold(
            (
                Point3::from([f64::INFINITY; 3]),
                Point3::from([f64::NEG_INFINITY; 3]),
            ),
            |(low, high), p| (low.inf(p), high.sup(p)),
        );
        Shape::Mesh {
            centre: nalgebra::center(&low, &high).coords,
            size: high - low,
            mesh: Arc::new(mesh),
        }
    }
}

/// A mesh read from an OBJ or STL file, already scaled.
#[derive(Debug, Clone, PartialEq)]
pub struct MeshGeometry {
    /// The mesh as the URDF names it.
    pub filename: String,
    /// The file it was read from.
    pub path: PathBuf,
    /// The URDF's per-axis `scale` (1 when absent).
    pub scale: Vector3<f64>,
    /// The scaled triangles.
    pub mesh: Arc<TriangleMesh>,
    /// Their convex hull, for contacts: read for collision meshes, `None` for visual ones.
    pub hull: Option<Arc<TriangleMesh>>,
}

impl MeshGeometry {
    /// The hull, or the mesh itself when it has none (a visual mesh).
    pub fn hull_or_mesh(&self) -> &Arc<TriangleMesh> {
        self.hull.as_ref().unwrap_or(&self.mesh)
    }
}

/// A shape placed in a link.
#[derive(Debug, Clone, PartialEq)]
pub struct GeometryElement {
    /// The shape's frame in the link frame.
    pub origin: Isometry3<f64>,
    /// The shape.
    pub geometry: Shape,
}

/// Reads the geometry of a robot's links, sharing meshes and collecting warnings.
pub(super) struct GeometryReader<'a> {
    urdf_folder: &'a Path,
    package_paths: &'a [PathBuf],
    pub(super) warnings: Vec<DescriptionWarning>,
    meshes: HashMap<MeshKey, ReadMesh>,
}

/// A mesh file and the bits of its scale: meshes read under one key are read once.
type MeshKey = (PathBuf, [u64; 3]);

/// A mesh read once, and its hull once a collision element needs it.
struct ReadMesh {
    mesh: Arc<TriangleMesh>,
    hull: Option<Arc<TriangleMesh>>,
}

/// The smallest radius of a stand-in capsule (m).
const MIN_CAPSULE_RADIUS: f64 = 0.02;

impl<'a> GeometryReader<'a> {
    pub(super) fn new(urdf_folder: &'a Path, package_paths: &'a [PathBuf]) -> Self {
        GeometryReader {
            urdf_folder,
            package_paths,
            warnings: Vec::new(),
            meshes: HashMap::new(),
        }
    }

    /// A link's visual elements; missing or unread meshes are left out with a warning.
    pub(super) fn visuals(&mut self, link: &urdf_rs::Link) -> Result<Vec<GeometryElement>, Kind> {
        let mut elements = Vec::new();
        for visual in &link.visual {
            let origin = pose(
                &visual.origin,
                &format!("link `{}` visual origin", link.name),
            )?;
            let geometry = match &visual.geometry {
                urdf_rs::Geometry::Mesh { filename, scale } => {
                    match self.mesh(&link.name, filename, scale.as_ref(), false)? {
                        Some(mesh) => Shape::mesh(mesh),
                        None => continue,
                    }
                }
                primitive => primitive_shape(primitive, &link.name)?,
            };
            elements.push(GeometryElement { origin, geometry });
        }
        Ok(elements)
    }

    /// A link's collision elements; a missing mesh becomes a capsule from the link's origin
    /// to the farthest of `child_origins` (its child joints' origins), with a warning.
    pub(super) fn collisions(
        &mut self,
        link: &urdf_rs::Link,
        child_origins: &[Point3<f64>],
    ) -> Result<Vec<GeometryElement>, Kind> {
        let mut elements = Vec::new();
        for collision in &link.collision {
            let origin = pose(
                &collision.origin,
                &format!("link `{}` collision origin", link.name),
            )?;
            let element = match &collision.geometry {
                urdf_rs::Geometry::Mesh { filename, scale } => {
                    match self.mesh(&link.name, filename, scale.as_ref(), true)? {
                        Some(mesh) => GeometryElement {
                            origin,
                            geometry: Shape::mesh(mesh),
                        },
                        None => self.stand_in(&link.name, filename, child_origins),
                    }
                }
                primitive => GeometryElement {
                    origin,
                    geometry: primitive_shape(primitive, &link.name)?,
                },
            };
            elements.push(element);
        }
        Ok(elements)
    }

    fn mesh(
        &mut self,
        link: &str,
        filename: &str,
        scale: Option<&urdf_rs::Vec3>,
        collision: bool,
    ) -> Result<Option<MeshGeometry>, Kind> {
        let scale = Vector3::from(scale.map_or([1.0; 3], |s| s.0));
        if !scale.iter().all(|s| s.is_finite() && *s != 0.0) {
            return Err(Kind::BadScale {
                link: link.to_string(),
                filename: filename.to_string(),
            });
        }
        let element = format!("link `{link}` mesh `{filename}` scale");
        within(scale.as_slice(), MESH_SCALE, &element, "")?;
        let found =
            resolve_mesh(filename, self.urdf_folder, self.package_paths).map_err(|error| {
                match error {
                    MeshPathError::OutsidePackage => Kind::MeshOutsidePackage {
                        link: link.to_string(),
                        filename: filename.to_string(),
                    },
                    MeshPathError::OutsideFolders => Kind::MeshOutsideFolders {
                        link: link.to_string(),
                        filename: filename.to_string(),
                    },
                    MeshPathError::NotAFile => Kind::NotAMesh {
                        link: link.to_string(),
                        filename: filename.to_string(),
                        reason: "not a regular file (a folder, a FIFO or a device)".into(),
                    },
                }
            })?;
        let Some(path) = found else {
            if !collision {
                self.warnings.push(DescriptionWarning::MissingVisualMesh {
                    link: link.to_string(),
                    filename: filename.to_string(),
                });
            }
            return Ok(None);
        };
        let Some(format) = MeshFormat::of(&path) else {
            if collision {
                return Err(Kind::UnsupportedMesh {
                    link: link.to_string(),
                    filename: filename.to_string(),
                });
            }
            self.warnings.push(DescriptionWarning::UnreadVisualMesh {
                link: link.to_string(),
                filename: filename.to_string(),
            });
            return Ok(None);
        };
        let not_a_mesh = |reason| Kind::NotAMesh {
            link: link.to_string(),
            filename: filename.to_string(),
            reason,
        };
        let key = (path.clone(), scale.map(f64::to_bits).into());
        if !self.meshes.contains_key(&key) {
            let mesh = TriangleMesh::read(&path, format, &scale).map_err(not_a_mesh)?;
            let mesh = Arc::new(mesh);
            self.meshes
                .insert(key.clone(), ReadMesh { mesh, hull: None });
        }
        let ReadMesh { mesh, hull } = self.meshes.get_mut(&key).expect("inserted above");
        if collision && hull.is_none() {
            *hull = Some(Arc::new(mesh.convex_hull().map_err(not_a_mesh)?));
        }
        Ok(Some(MeshGeometry {
            filename: filename.to_string(),
            path,
            scale,
            mesh: mesh.clone(),
            hull: hull.clone().filter(|_| collision),
        }))
    }

    fn stand_in(
        &mut self,
        link: &str,
        filename: &str,
        child_origins: &[Point3<f64>],
    ) -> GeometryElement {
        let far = child_origins
            .iter()
            .map(|p| p.coords)
            .max_by(|a, b| a.norm().total_cmp(&b.norm()))
            .unwrap_or_else(Vector3::zeros);
        let length = far.norm();
        let radius = (0.1 * length).max(MIN_CAPSULE_RADIUS);
        self.warnings
            .push(DescriptionWarning::MissingCollisionMesh {
                link: link.to_string(),
                filename: filename.to_string(),
                radius,
                length,
            });
        let turn = if length > 0.0 {
            UnitQuaternion::rotation_between(&Vector3::z(), &far).unwrap_or_else(|| {
                UnitQuaternion::from_axis_angle(&Vector3::x_axis(), std::f64::consts::PI)
            })
        } else {
            UnitQuaternion::identity()
        };
        GeometryElement {
            origin: Isometry3::from_parts(Translation3::from(far / 2.0), turn),
            geometry: Shape::Capsule { radius, length },
        }
    }
}

fn primitive_shape(geometry: &urdf_rs::Geometry, link: &str) -> Result<Shape, Kind> {
    let (shape, name, sizes) = match *geometry {
        urdf_rs::Geometry::Box { size } => {
            (Shape::Cuboid(Vector3::from(size.0)), "box", size.0.to_vec())
        }
        urdf_rs::Geometry::Cylinder { radius, length } => (
            Shape::Cylinder { radius, length },
            "cylinder",
            vec![radius, length],
        ),
        urdf_rs::Geometry::Capsule { radius, length } => (
            Shape::Capsule { radius, length },
            "capsule",
            vec![radius, length],
        ),
        urdf_rs::Geometry::Sphere { radius } => (Shape::Sphere { radius }, "sphere", vec![radius]),
        urdf_rs::Geometry::Mesh { .. } => unreachable!("meshes are read by GeometryReader::mesh"),
    };
    if sizes.iter().all(|s| s.is_finite() && *s > 0.0) {
        let element = format!("link `{link}` {name}");
        within(&sizes, (MIN_SIZE_M, MAX_LENGTH_M), &element, "m")?;
        Ok(shape)
    } else {
        Err(Kind::BadShape {
            link: link.to_string(),
            shape: name.to_string(),
        })
    }
}
