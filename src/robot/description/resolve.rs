//! Where a URDF's mesh `filename` points on disk: relative to the URDF's folder, absolute,
//! `file://`, or `package://NAME/...` looked up in a list of search paths, then in the folder
//! tree the URDF lies in; never outside the folders a mesh may be read from.

use std::path::{Path, PathBuf};

/// Why a mesh's `filename` names no file that may be read.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum MeshPathError {
    /// A `package://` mesh that would be read from outside its search folder: a `..`,
    /// root or empty part in its name, or a file that a symbolic link puts elsewhere.
    OutsidePackage,
    /// A relative, absolute or `file://` mesh outside the URDF's folder and every search
    /// folder (after resolving `..` and symbolic links).
    OutsideFolders,
    /// Something is there, but not a regular file (a folder, a FIFO, a device).
    NotAFile,
}

/// Finds the file a mesh `filename` names, or `None` when nothing is at any candidate.
///
/// `package://NAME/REST` is tried as `SEARCH/NAME/REST` for every search path, then as
/// `SEARCH/REST` for a search path that is itself the package folder NAME, then in the
/// package folder found in the URDF's folder tree (`package_in_tree`); the file must
/// stay inside that search folder (after resolving `..` and symbolic links). Any other name
/// must lead inside the URDF's folder or one of the search paths. The first candidate at
/// which something is must be a regular file.
pub fn resolve_mesh(
    filename: &str,
    urdf_folder: &Path,
    package_paths: &[PathBuf],
) -> Result<Option<PathBuf>, MeshPathError> {
    let regular = |path: PathBuf| match path.metadata() {
        Ok(meta) if meta.is_file() => Some(Ok(path)),
        Ok(_) => Some(Err(MeshPathError::NotAFile)),
        Err(_) => None,
    };
    let Some(rest) = filename.strip_prefix("package://") else {
        let found = mesh_candidates(filename, urdf_folder, package_paths);
        let Some(path) = found.into_iter().find_map(regular).transpose()? else {
            return Ok(None);
        };
        let mut folders =
            std::iter::once(urdf_folder).chain(package_paths.iter().map(|p| p.as_path()));
        return if folders.any(|folder| lies_inside(&path, folder)) {
            Ok(Some(path))
        } else {
            Err(MeshPathError::OutsideFolders)
        };
    };
    let plain = |part: &str| {
        !part.is_empty()
            && Path::new(part)
                .components()
                .all(|c| matches!(c, std::path::Component::Normal(_)))
    };
    let (package, inside) = rest.split_once('/').unwrap_or((rest, ""));
    if !plain(package) || !plain(inside) {
        return Err(MeshPathError::OutsidePackage);
    }
    for (search, path) in package_candidates(package, inside, urdf_folder, package_paths) {
        if let Some(found) = regular(path) {
            let path = found?;
            return if lies_inside(&path, &search) {
                Ok(Some(path))
            } else {
                Err(MeshPathError::OutsidePackage)
            };
        }
    }
    Ok(None)
}

/// True when `path`, with `..` and symbolic links resolved, lies inside `folder` (the
/// working folder when empty: the folder of a URDF named without one).
fn lies_inside(path: &Path, folder: &Path) -> bool {
    let folder = if folder.as_os_str().is_empty() {
        Path::new(".")
    } else {
        folder
    };
    match (path.canonicalize(), folder.canonicalize()) {
        (Ok(file), Ok(folder)) => file.starts_with(folder),
        _ => false,
    }
}

/// The search folder and path of every place `package://PACKAGE/INSIDE` may be, in order.
fn package_candidates(
    package: &str,
    inside: &str,
    urdf_folder: &Path,
    package_paths: &[PathBuf],
) -> Vec<(PathBuf, PathBuf)> {
    let nested = package_paths
        .iter()
        .map(|search| (search.clone(), search.join(package).join(inside)));
    let itself = package_paths
        .iter()
        .filter(|search| search.file_name().is_some_and(|name| name == package))
        .map(|search| (search.clone(), search.join(inside)));
    let tree = package_in_tree(package, urdf_folder).map(|found| {
        let path = found.join(inside);
        (found, path)
    });
    nested.chain(itself).chain(tree).collect()
}

/// The package folder NAME as ROS finds it for a URDF inside a package's folder tree:
/// walking up from the URDF's folder, the first folder that is named NAME or whose
/// `package.xml` names it, or that holds a folder named NAME.
fn package_in_tree(package: &str, urdf_folder: &Path) -> Option<PathBuf> {
    let start = if urdf_folder.as_os_str().is_empty() {
        Path::new(".")
    } else {
        urdf_folder
    };
    let start = start.canonicalize().ok()?;
    start.ancestors().find_map(|folder| {
        if folder.file_name().is_some_and(|name| name == package)
            || package_xml_names(folder, package)
        {
            return Some(folder.to_path_buf());
        }
        let child = folder.join(package);
        child.is_dir().then_some(child)
    })
}

/// True when `folder/package.xml` exists and its `<name>` is `package`.
fn package_xml_names(folder: &Path, package: &str) -> bool {
    let Ok(text) = std::fs::read_to_string(folder.join("package.xml")) else {
        return false;
    };
    text.split("<name>")
        .nth(1)
        .and_then(|rest| rest.split("</name>").next())
        .is_some_and(|name| name.trim() == package)
}

/// Every path a mesh `filename` may be at, in the order they are tried (none for a
/// `package://` mesh without search paths outside a folder tree holding its package).
pub fn mesh_candidates(
    filename: &str,
    urdf_folder: &Path,
    package_paths: &[PathBuf],
) -> Vec<PathBuf> {
    if let Some(rest) = filename.strip_prefix("package://") {
        let (package, inside) = rest.split_once('/').unwrap_or((rest, ""));
        return package_candidates(package, inside, urdf_folder, package_paths)
            .into_iter()
            .map(|(_, path)| path)
            .collect();
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
        let search = [root.join("elsewhere"), root.join("robots")];
        assert_eq!(
            resolve_mesh("../robots/arm/meshes/a.stl", &urdf, &search),
            Ok(Some(urdf.join("../robots/arm/meshes/a.stl")))
        );
        let absolute = format!("file://{}", mesh.display());
        assert_eq!(
            resolve_mesh(&absolute, &urdf, &search),
            Ok(Some(mesh.clone()))
        );
        let beside = root.join("robots/arm");
        assert_eq!(
            resolve_mesh("meshes/a.stl", &beside, none),
            Ok(Some(beside.join("meshes/a.stl")))
        );
        assert_eq!(
            resolve_mesh("package://arm/meshes/a.stl", &urdf, none),
            Ok(None)
        );
        assert_eq!(
            resolve_mesh("package://arm/meshes/a.stl", &urdf, &search),
            Ok(Some(mesh.clone()))
        );
        let package_itself = [root.join("robots/arm")];
        assert_eq!(
            resolve_mesh("package://arm/meshes/a.stl", &urdf, &package_itself),
            Ok(Some(mesh))
        );
        assert_eq!(
            resolve_mesh("package://arm/meshes/b.stl", &urdf, &search),
            Ok(None)
        );
    }

    /// A ROS package's meshes without `package_paths`: the URDF inside a folder named like
    /// the package, inside one whose `package.xml` names it, or beside a folder of its name.
    #[test]
    fn a_package_is_found_in_the_urdf_folder_tree() {
        let dir = tempfile::tempdir().unwrap();
        let root = dir.path().canonicalize().unwrap();
        for folder in [
            "ws/arm_a/urdf",
            "ws/arm_a/meshes",
            "ws/renamed/urdf",
            "ws/tool_b/meshes",
        ] {
            fs::create_dir_all(root.join(folder)).unwrap();
        }
        fs::write(root.join("ws/arm_a/meshes/a.stl"), "solid").unwrap();
        fs::write(root.join("ws/tool_b/meshes/b.stl"), "solid").unwrap();
        fs::write(
            root.join("ws/renamed/package.xml"),
            "<package format=\"3\">\n  <name> arm_c </name>\n</package>\n",
        )
        .unwrap();
        fs::create_dir_all(root.join("ws/renamed/meshes")).unwrap();
        fs::write(root.join("ws/renamed/meshes/c.stl"), "solid").unwrap();
        let cases = [
            (
                "ws/arm_a/urdf",
                "package://arm_a/meshes/a.stl",
                "ws/arm_a/meshes/a.stl",
            ),
            (
                "ws/arm_a/urdf",
                "package://tool_b/meshes/b.stl",
                "ws/tool_b/meshes/b.stl",
            ),
            (
                "ws/renamed/urdf",
                "package://arm_c/meshes/c.stl",
                "ws/renamed/meshes/c.stl",
            ),
        ];
        for (urdf, uri, file) in cases {
            assert_eq!(
                resolve_mesh(uri, &root.join(urdf), &[]),
                Ok(Some(root.join(file))),
                "{uri}"
            );
        }
        assert_eq!(
            resolve_mesh(
                "package://arm_d/meshes/a.stl",
                &root.join("ws/arm_a/urdf"),
                &[]
            ),
            Ok(None)
        );
        assert_eq!(
            mesh_candidates(
                "package://arm_a/meshes/x.stl",
                &root.join("ws/arm_a/urdf"),
                &[]
            ),
            [root.join("ws/arm_a/meshes/x.stl")]
        );
    }

    /// The escapes a hostile URDF tried: `..` out of the package, an absolute path after
    /// the package's name, `..` as the package, and a symbolic link out of the folder.
    #[test]
    fn a_package_mesh_never_leads_outside_its_search_folder() {
        let dir = tempfile::tempdir().unwrap();
        let root = dir.path();
        fs::create_dir_all(root.join("robots/oscar/meshes")).unwrap();
        fs::create_dir_all(root.join("x")).unwrap();
        let secret = root.join("x/secret.stl");
        fs::write(&secret, "solid").unwrap();
        let urdf = root.join("robots/oscar");
        let search = [root.join("robots")];
        let depth = root.components().count() + 4;
        let climb = "../".repeat(depth);
        let up_and_out = format!("package://oscar/{climb}{}", secret.display());
        let absolute = format!("package://oscar/{}", secret.display());
        for escape in [
            up_and_out.as_str(),
            absolute.as_str(),
            "package://../x/secret.stl",
            "package://oscar/meshes/../../../x/secret.stl",
        ] {
            assert_eq!(
                resolve_mesh(escape, &urdf, &search),
                Err(MeshPathError::OutsidePackage),
                "{escape}"
            );
        }
        std::os::unix::fs::symlink(&secret, root.join("robots/oscar/meshes/link.stl")).unwrap();
        assert_eq!(
            resolve_mesh("package://oscar/meshes/link.stl", &urdf, &search),
            Err(MeshPathError::OutsidePackage)
        );
    }

    /// A relative or absolute mesh outside the URDF's folder and every search path is not
    /// read: `..` out of the folder, an absolute path elsewhere, a symbolic link out.
    #[test]
    fn a_plain_mesh_never_leads_outside_the_urdf_folder_or_the_search_paths() {
        let dir = tempfile::tempdir().unwrap();
        let root = dir.path();
        fs::create_dir_all(root.join("robot/meshes")).unwrap();
        fs::create_dir_all(root.join("x")).unwrap();
        let secret = root.join("x/secret.stl");
        fs::write(&secret, "solid").unwrap();
        let urdf = root.join("robot");
        std::os::unix::fs::symlink(&secret, urdf.join("meshes/link.stl")).unwrap();
        let absolute = secret.display().to_string();
        let file_url = format!("file://{absolute}");
        for escape in [
            "../x/secret.stl",
            "meshes/../../x/secret.stl",
            absolute.as_str(),
            file_url.as_str(),
            "meshes/link.stl",
        ] {
            assert_eq!(
                resolve_mesh(escape, &urdf, &[]),
                Err(MeshPathError::OutsideFolders),
                "{escape}"
            );
        }
        let x_searched = [root.join("x")];
        assert_eq!(
            resolve_mesh("../x/secret.stl", &urdf, &x_searched),
            Ok(Some(urdf.join("../x/secret.stl")))
        );
    }

    /// A URDF named without a folder (`robot.urdf`) has the working folder as its own.
    #[test]
    fn the_empty_folder_is_the_working_folder() {
        assert!(lies_inside(Path::new("Cargo.toml"), Path::new("")));
        assert!(!lies_inside(Path::new("/etc/hostname"), Path::new("")));
    }

    /// A folder, or a link to a device, named like a mesh is no mesh.
    #[test]
    fn only_a_regular_file_is_a_mesh() {
        let dir = tempfile::tempdir().unwrap();
        let root = dir.path();
        fs::create_dir_all(root.join("folder.stl")).unwrap();
        std::os::unix::fs::symlink("/dev/zero", root.join("zero.stl")).unwrap();
        for name in ["folder.stl", "zero.stl"] {
            assert_eq!(
                resolve_mesh(name, root, &[]),
                Err(MeshPathError::NotAFile),
                "{name}"
            );
        }
    }
}
