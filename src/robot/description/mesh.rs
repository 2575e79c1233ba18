//! Triangle meshes read from OBJ (tobj) and STL (stl_io) files, scaled as the URDF says,
//! and their convex hulls (parry, through Rapier's re-export).

use super::ranges::{number, MAX_LENGTH_M, MIN_SIZE_M};
use nalgebra::{Point3, Vector3};
use rapier3d_f64::parry::math::Vector as ParryVector;
use rapier3d_f64::parry::transformation::try_convex_hull;
use std::collections::HashMap;
use std::fs::File;
use std::io::BufReader;
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
}

impl MeshFormat {
    /// The format a file name's extension says, if it is one read here.
    pub fn of(path: &Path) -> Option<MeshFormat> {
        let extension = path.extension()?.to_str()?.to_ascii_lowercase();
        match extension.as_str() {
            "obj" => Some(MeshFormat::Obj),
            "stl" => Some(MeshFormat::Stl),
            _ => None,
        }
    }
}

/// A convex hull enclosing less than this share of the cube of the mesh's extent is flat.
const FLAT: f64 = 1e-9;

impl TriangleMesh {
    /// Reads a mesh file and scales it per axis; the error is the reason in words.
    pub fn read(path: &Path, format: MeshFormat, scale: &Vector3<f64>) -> Result<Self, String> {
        let file = crate::files::open_regular(path, crate::files::MAX_MESH_BYTES)
            .map_err(|e| e.to_string())?;
        let mut reader = BufReader::new(file);
        let mut mesh = match format {
            MeshFormat::Obj => read_obj(&mut reader)?,
            MeshFormat::Stl => read_stl(&mut reader)?,
        };
        for vertex in &mut mesh.vertices {
            *vertex = Point3::from(vertex.coords.component_mul(scale));
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

fn read_obj(reader: &mut BufReader<File>) -> Result<TriangleMesh, String> {
    let options = tobj::LoadOptions {
        triangulate: true,
        ignore_points: true,
        ignore_lines: true,
        ..Default::default()
    };
    let no_materials = |_: &Path| -> tobj::MTLLoadResult { Ok((Vec::new(), HashMap::new())) };
    let (models, _) = tobj::load_obj_buf(reader, &options, no_materials)
        .map_err(|e| format!("not a readable OBJ file ({e})"))?;
    let mut mesh = TriangleMesh {
        vertices: Vec::new(),
        triangles: Vec::new(),
    };
    for model in models {
        let offset = mesh.vertices.len() as u32;
        let positions = &model.mesh.positions;
        mesh.vertices.extend(
            positions
                .chunks_exact(3)
                .map(|p| Point3::new(p[0], p[1], p[2])),
        );
        mesh.triangles.extend(
            model
                .mesh
                .indices
                .chunks_exact(3)
                .map(|t| [t[0] + offset, t[1] + offset, t[2] + offset]),
        );
    }
    Ok(mesh)
}

fn read_stl(reader: &mut BufReader<File>) -> Result<TriangleMesh, String> {
    let stl = stl_io::read_stl(reader).map_err(|e| format!("not a readable STL file ({e})"))?;
    Ok(TriangleMesh {
        vertices: stl
            .vertices
            .iter()
            .map(|v| Point3::new(v[0] as f64, v[1] as f64, v[2] as f64))
            .collect(),
        triangles: stl
            .faces
            .iter()
            .map(|f| f.vertices.map(|i| i as u32))
            .collect(),
    })
}

#[cfg(test)]
mod tests {
    use super::*;
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

    #[test]
    fn a_mirroring_scale_keeps_the_triangles_facing_out() {
        let (_dir, path) = written("t.obj", TETRAHEDRON.as_bytes());
        let mesh =
            TriangleMesh::read(&path, MeshFormat::Obj, &Vector3::new(-1.0, 1.0, 1.0)).unwrap();
        assert!(mesh.vertices.contains(&Point3::new(-1.0, 0.0, 0.0)));
        assert!((signed_volume(&mesh) - 1.0 / 6.0).abs() < 1e-12);
    }
}
