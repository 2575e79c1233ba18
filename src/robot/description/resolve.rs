//! Where a URDF's mesh `filename` points on disk: relative to the URDF's folder, absolute,
//! `file://`, or `package://NAME/...` looked up in a list of search paths.

use std::path::{Path, PathBuf};

/// Finds the file a mesh `filename` names, or `None` when no candidate exists.
///
/// `package://NAME/REST` is tried as `SEARCH/NAME/REST` for every search path, then as
/// `SEARCH/REST` for a search path that is itself the package folder NAME.
pub fn resolve_mesh(
    filename: &str,
    urdf_folder: &Path,
    package_paths: &[PathBuf],
) -> Option<PathBuf> {
    mesh_candidates(filename, urdf_folder, package_paths)
        .into_iter()
        .find(|path| path.is_file())
}

/// Every path a mesh `filename` may be at, in the order they are tried (none for a
/// `package://` mesh without search paths).
pub fn mesh_candidates(
    filename: &str,
    urdf_folder: &Path,
    package_paths: &[PathBuf],
) -> Vec<PathBuf> {
    if let Some(rest) = filename.strip_prefix("package://") {
        let (package, inside) = rest.split_once('/').unwrap_or((rest, ""));
        let mut found: Vec<PathBuf> = package_paths
            .iter()
            .map(|search| search.join(package).join(inside))
            .collect();
        found.extend(
            package_paths
                .iter()
                .filter(|search| search.file_name().is_some_and(|name| name == package))
                .map(|search| search.join(inside)),
        );
        return found;
    }
    let plain = filename.strip_prefix("file://").unwrap_or(filename);
    vec![urdf_folder.join(plain)]
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::fs;

    #[test]
    fn paths_resolve_relative_absolute_and_by_package() {
        let dir = tempfile::tempdir().unwrap();
        let root = dir.path();
        fs::create_dir_all(root.join("robots/arm/meshes")).unwrap();
        fs::create_dir_all(root.join("urdf")).unwrap();
        let mesh = root.join("robots/arm/meshes/a.stl");
        fs::write(&mesh, "solid").unwrap();
        let urdf = root.join("urdf");
        let none: &[PathBuf] = &[];
        assert_eq!(
            resolve_mesh("../robots/arm/meshes/a.stl", &urdf, none),
            Some(urdf.join("../robots/arm/meshes/a.stl"))
        );
        let absolute = format!("file://{}", mesh.display());
        assert_eq!(resolve_mesh(&absolute, &urdf, none), Some(mesh.clone()));
        assert_eq!(
            resolve_mesh("package://arm/meshes/a.stl", &urdf, none),
            None
        );
        let search = [root.join("elsewhere"), root.join("robots")];
        assert_eq!(
            resolve_mesh("package://arm/meshes/a.stl", &urdf, &search),
            Some(mesh.clone())
        );
        let package_itself = [root.join("robots/arm")];
        assert_eq!(
            resolve_mesh("package://arm/meshes/a.stl", &urdf, &package_itself),
            Some(mesh)
        );
        assert_eq!(
            resolve_mesh("package://arm/meshes/b.stl", &urdf, &search),
            None
        );
    }
}
