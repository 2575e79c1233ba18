//! Triangle meshes read from OBJ, STL and COLLADA files (mesh-loader), scaled as the URDF
//! says, COLLADA's unit and up axis honoured, and their convex hulls (parry, through Rapier's
//! re-export).

use super::ranges::{number, MAX_LENGTH_M, MIN_SIZE_M};
use nalgebra::{Point3, Vector3};
use rapier3d_f64::parry::math::Vector as ParryVector;
use rapier3d_f64::parry::transformation::try_convex_hull;
use std::collections::HashMap;
use std::io::Read;
use std::path::Path;

/// A triangle mesh in a link's geometry frame (m).
#[derive(Debug, Clone, PartialEq)]
pub struct TriangleMesh {
    /// The vertices.
    pub vertices: Vec<Point3<f64>>,
    /// Triangles as indices into `vertices`, counter-clockwise seen from outside.
    pub triangles: Vec<[u32; 3]>,
}

/// The mesh file formats read.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum MeshFormat {
    /// Wavefront OBJ (`.obj`).
    Obj,
    /// STL, ASCII or binary (`.stl`).
    Stl,
    /// COLLADA (`.dae`): its `<unit>` and `<up_axis>` taken into account.
    Collada,
}

impl MeshFormat {
    /// The format a file name's extension says, if it is one read here.
    pub fn of(path: &Path) -> Option<MeshFormat> {
        let extension = path.extension()?.to_str()?.to_ascii_lowercase();
        match extension.as_str() {
            "obj" => Some(MeshFormat::Obj),
            "stl" => Some(MeshFormat::Stl),
            "dae" => Some(MeshFormat::Collada),
            _ => None,
        }
    }

    fn name(self) -> &'static str {
        match self {
            MeshFormat::Obj => "OBJ",
            MeshFormat::Stl => "STL",
            MeshFormat::Collada => "COLLADA",
        }
    }
}

/// A convex hull enclosing less than this share of the cube of the mesh's extent is flat.
const FLAT: f64 = 1e-9;

impl TriangleMesh {
    /// Reads a mesh file and scales it per axis; the error is the reason in words.
    pub fn read(path: &Path, format: MeshFormat, scale: &Vector3<f64>) -> Result<Self, String> {
        let mut file = crate::files::open_regular(path, crate::files::MAX_MESH_BYTES)
            .map_err(|e| e.to_string())?;
        let mut bytes = Vec::new();
        file.read_to_end(&mut bytes).map_err(|e| e.to_string())?;
        let unreadable = |e: std::io::Error| format!("not a readable {} file ({e})", format.name());
        let (scene, up) = match format {
            MeshFormat::Obj => (
                mesh_loader::obj::from_slice(&bytes, Some(path), no_materials)
                    .map_err(unreadable)?,
                UpAxis::Z,
            ),
            MeshFormat::Stl => (
                mesh_loader::stl::from_slice(&bytes).map_err(unreadable)?,
                UpAxis::Z,
            ),
            MeshFormat::Collada => (
                mesh_loader::collada::from_slice(&bytes).map_err(unreadable)?,
                UpAxis::of_collada(&bytes)?,
            ),
        };
        let mut mesh = TriangleMesh {
            vertices: Vec::new(),
            triangles: Vec::new(),
        };
        // The readers give each triangle corners of its own: equal corners become one vertex.
        let mut index: HashMap<[u64; 3], u32> = HashMap::new();
        for part in &scene.meshes {
            for face in &part.faces {
                let mut triangle = [0; 3];
                for (corner, &i) in triangle.iter_mut().zip(face) {
                    let v = part.vertices.get(i as usize).ok_or_else(|| {
                        format!("a triangle names vertex {i} of {}", part.vertices.len())
                    })?;
                    let z_up = up.to_z_up(Vector3::new(v[0], v[1], v[2]).cast::<f64>());
                    let point = Point3::from(z_up.component_mul(scale));
                    let next = u32::try_from(mesh.vertices.len())
                        .map_err(|_| "it has more than 2^32 vertices".to_string())?;
                    *corner = *index
                        .entry(point.coords.map(f64::to_bits).into())
                        .or_insert_with(|| {
                            mesh.vertices.push(point);
                            next
                        });
                }
                mesh.triangles.push(triangle);
            }
        }
        if scale.product() < 0.0 {
            for triangle in &mut mesh.triangles {
                triangle.swap(1, 2);
            }
        }
        mesh.check()?;
        Ok(mesh)
    }

    /// The convex hull of the vertices, as a closed mesh; an error for a flat mesh.
    pub fn convex_hull(&self) -> Result<TriangleMesh, String> {
        let points: Vec<ParryVector> = self
            .vertices
            .iter()
            .map(|p| ParryVector::new(p.x, p.y, p.z))
            .collect();
        let (vertices, triangles) = try_convex_hull(&points)
            .map_err(|e| format!("its convex hull cannot be built ({e:?})"))?;
        let volume: f64 = triangles
            .iter()
            .map(|&[a, b, c]| {
                let [a, b, c] = [a, b, c].map(|i| vertices[i as usize]);
                a.dot(b.cross(c)) / 6.0
            })
            .sum();
        let extent = points
            .iter()
            .map(|p| (*p - points[0]).length())
            .fold(0.0, f64::max);
        if triangles.len() < 4 || volume.abs() <= FLAT * extent.powi(3) {
            return Err("it is flat: its convex hull encloses no volume".into());
        }
        Ok(TriangleMesh {
            vertices: vertices
                .iter()
                .map(|v| Point3::new(v.x, v.y, v.z))
                .collect(),
            triangles,
        })
    }

    fn check(&self) -> Result<(), String> {
        if self.triangles.is_empty() {
            return Err("it has no triangles".into());
        }
        if let Some(p) = self
            .vertices
            .iter()
            .find(|p| !p.coords.iter().all(|c| c.is_finite()))
        {
            return Err(format!("vertex ({}, {}, {}) is not finite", p.x, p.y, p.z));
        }
        if let Some(p) = self
            .vertices
            .iter()
            .find(|p| p.coords.amax() > MAX_LENGTH_M)
        {
            return Err(format!(
                "a point of it lies {} m from its frame, beyond the {MAX_LENGTH_M} m a robot's part may reach",
                number(p.coords.amax())
            ));
        }
        let (low, high) = self.vertices.iter().fold(
            (
                Vector3::repeat(f64::INFINITY),
                Vector3::repeat(f64::NEG_INFINITY),
            ),
            |(l, h), p| (l.inf(&p.coords), h.sup(&p.coords)),
        );
        let extent = (high - low).amax();
        if extent < MIN_SIZE_M {
            return Err(format!(
                "it spans {} m, less than the {MIN_SIZE_M} m a part must span",
                number(extent)
            ));
        }
        let count = self.vertices.len();
        match self
            .triangles
            .iter()
            .flatten()
            .find(|&&i| i as usize >= count)
        {
            Some(i) => Err(format!("a triangle names vertex {i} of {count}")),
            None => Ok(()),
        }
    }
}

/// An OBJ file's materials are not read: the reader mesh-loader asks for them finds none.
fn no_materials(_: &Path) -> std::io::Result<Vec<u8>> {
    Err(std::io::Error::other("materials are not read"))
}

/// The axis a COLLADA file calls up (`<asset><up_axis>`, `Y_UP` when absent as the
/// format says); URDF meshes are Z-up.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum UpAxis {
    X,
    Y,
    Z,
}

impl UpAxis {
    fn of_collada(bytes: &[u8]) -> Result<UpAxis, String> {
        let text = String::from_utf8_lossy(&bytes[..bytes.len().min(1 << 16)]);
        let Some(start) = text.find("<up_axis>") else {
            return Ok(UpAxis::Y);
        };
        let rest = &text[start + "<up_axis>".len()..];
        let value = rest.split('<').next().unwrap_or("").trim();
        match value {
            "X_UP" => Ok(UpAxis::X),
            "Y_UP" => Ok(UpAxis::Y),
            "Z_UP" => Ok(UpAxis::Z),
            other => Err(format!("its up_axis `{other}` is none of X_UP, Y_UP, Z_UP")),
        }
    }

    /// A point of a file with this up axis in the Z-up frame (the COLLADA specification's
    /// right, up and in axes kept: X_UP's right is -y, Y_UP's and Z_UP's is x).
    fn to_z_up(self, v: Vector3<f64>) -> Vector3<f64> {
        match self {
            UpAxis::X => Vector3::new(-v.y, -v.z, v.x),
            UpAxis::Y => Vector3::new(v.x, -v.z, v.y),
            UpAxis::Z => v,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::fs::File;
    use std::io::Write;

    fn written(name: &str, text: &[u8]) -> (tempfile::TempDir, std::path::PathBuf) {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join(name);
        File::create(&path).unwrap().write_all(text).unwrap();
        (dir, path)
    }

    const TETRAHEDRON: &str =
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";

    /// The volume the triangles enclose, positive when they face outwards.
    fn signed_volume(mesh: &TriangleMesh) -> f64 {
        let v = |i: u32| mesh.vertices[i as usize].coords;
        let sum: f64 = mesh
            .triangles
            .iter()
            .map(|t| v(t[0]).dot(&v(t[1]).cross(&v(t[2]))))
            .sum();
        sum / 6.0
    }

    #[test]
    fn an_obj_is_read_scaled_and_its_hull_is_closed() {
        let (_dir, path) = written("t.obj", TETRAHEDRON.as_bytes());
        let mesh =
            TriangleMesh::read(&path, MeshFormat::Obj, &Vector3::new(2.0, 1.0, 1.0)).unwrap();
        assert_eq!((mesh.vertices.len(), mesh.triangles.len()), (4, 4));
        assert!(mesh.vertices.contains(&Point3::new(2.0, 0.0, 0.0)));
        assert!((signed_volume(&mesh) - 2.0 / 6.0).abs() < 1e-12);
        let hull = mesh.convex_hull().unwrap();
        assert_eq!((hull.vertices.len(), hull.triangles.len()), (4, 4));
        assert!((signed_volume(&hull) - 2.0 / 6.0).abs() < 1e-12);
    }

    #[test]
    fn an_ascii_stl_is_read() {
        let stl = "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\nendfacet\nendsolid t\n";
        let (_dir, path) = written("t.STL", stl.as_bytes());
        assert_eq!(MeshFormat::of(&path), Some(MeshFormat::Stl));
        let mesh = TriangleMesh::read(&path, MeshFormat::Stl, &Vector3::repeat(1.0)).unwrap();
        assert_eq!((mesh.vertices.len(), mesh.triangles.len()), (3, 1));
        let flat = mesh.convex_hull().unwrap_err();
        assert!(flat.contains("hull"), "{flat}");
    }

    #[test]
    fn text_that_is_no_mesh_is_refused_with_a_reason() {
        let (_dir, path) = written("t.obj", b"this is a note, not a mesh\n");
        let reason = TriangleMesh::read(&path, MeshFormat::Obj, &Vector3::repeat(1.0)).unwrap_err();
        assert!(reason.contains("no triangles"), "{reason}");
        let (_dir, path) = written("t.stl", b"garbage that is neither ascii nor binary stl");
        let reason = TriangleMesh::read(&path, MeshFormat::Stl, &Vector3::repeat(1.0)).unwrap_err();
        assert!(reason.contains("STL"), "{reason}");
    }

    /// A COLLADA tetrahedron in millimetres with the given up axis, instanced in its scene.
    fn collada(up: &str) -> String {
        format!(
            r##"<?xml version="1.0"?>
<COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">
  <asset><unit name="millimeter" meter="0.001"/>{up}</asset>
  <library_geometries><geometry id="t" name="t"><mesh>
    <source id="t-pos"><float_array id="t-arr" count="12">0 0 0 1000 0 0 0 1000 0 0 0 1000</float_array>
      <technique_common><accessor source="#t-arr" count="4" stride="3">
        <param name="X" type="float"/><param name="Y" type="float"/><param name="Z" type="float"/>
      </accessor></technique_common></source>
    <vertices id="t-vtx"><input semantic="POSITION" source="#t-pos"/></vertices>
    <triangles count="4"><input semantic="VERTEX" source="#t-vtx" offset="0"/>
      <p>0 2 1 0 1 3 0 3 2 1 2 3</p></triangles>
  </mesh></geometry></library_geometries>
  <library_visual_scenes><visual_scene id="s"><node id="n">
    <instance_geometry url="#t"/></node></visual_scene></library_visual_scenes>
  <scene><instance_visual_scene url="#s"/></scene>
</COLLADA>
"##
        )
    }

    /// The unit scales to metres; Y_UP's y becomes z (and z becomes -y), X_UP's x becomes
    /// z; the triangles keep facing out.
    #[test]
    fn a_collada_mesh_is_read_in_metres_with_z_up() {
        let one = Vector3::repeat(1.0);
        for (up, expected) in [
            (
                "<up_axis>Z_UP</up_axis>",
                [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]],
            ),
            (
                "<up_axis>Y_UP</up_axis>",
                [[1.0, 0.0, 0.0], [0.0, 0.0, 1.0], [0.0, -1.0, 0.0]],
            ),
            ("", [[1.0, 0.0, 0.0], [0.0, 0.0, 1.0], [0.0, -1.0, 0.0]]),
            (
                "<up_axis>X_UP</up_axis>",
                [[0.0, 0.0, 1.0], [-1.0, 0.0, 0.0], [0.0, -1.0, 0.0]],
            ),
        ] {
            let (_dir, path) = written("t.dae", collada(up).as_bytes());
            assert_eq!(MeshFormat::of(&path), Some(MeshFormat::Collada));
            let mesh = TriangleMesh::read(&path, MeshFormat::Collada, &one).unwrap();
            for corner in expected {
                let corner = Point3::from(Vector3::from(corner));
                assert!(
                    mesh.vertices.iter().any(|p| (p - corner).norm() < 1e-6),
                    "{up}: {corner} in {:?}",
                    mesh.vertices
                );
            }
            assert!((signed_volume(&mesh) - 1.0 / 6.0).abs() < 1e-6, "{up}");
        }
        let (_dir, path) = written("t.dae", collada("<up_axis>W_UP</up_axis>").as_bytes());
        let reason = TriangleMesh::read(&path, MeshFormat::Collada, &one).unwrap_err();
        assert!(reason.contains("W_UP"), "{reason}");
    }

    #[test]
    fn a_mirroring_scale_keeps_the_triangles_facing_out() {
        let (_dir, path) = written("t.obj", TETRAHEDRON.as_bytes());
        let mesh =
            TriangleMesh::read(&path, MeshFormat::Obj, &Vector3::new(-1.0, 1.0, 1.0)).unwrap();
        assert!(mesh.vertices.contains(&Point3::new(-1.0, 0.0, 0.0)));
        assert!((signed_volume(&mesh) - 1.0 / 6.0).abs() < 1e-12);
    }
}
