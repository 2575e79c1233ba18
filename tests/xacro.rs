//! `--urdf FILE.xacro`: the file is expanded by the `xacro` program (PyPI's `xacro`) when
//! it is on the PATH, and is a clear error saying how to install it otherwise, before any
//! work. The arms are the public ones of PyPI's `example-robot-data` (`EYEHAND_ROBOT_DATA`,
//! as in tests/corpus.rs); the `xacro` program is found on the PATH or in the folder
//! `EYEHAND_XACRO_DIR` names (scripts/test-all.sh installs it into its virtual environment).

use std::ffi::OsString;
use std::path::{Path, PathBuf};
use std::process::Command;

#[path = "common/robot_data.rs"]
mod robot_data;
use robot_data::robot_data;
/// The variable naming a folder that holds the `xacro` program.
const XACRO_DIR: &str = "EYEHAND_XACRO_DIR";

/// A PATH on which the `xacro` program is found.
fn path_with_xacro() -> OsString {
    let path = std::env::var_os("PATH").unwrap_or_default();
    let mut folders: Vec<PathBuf> = std::env::split_paths(&path).collect();
    if let Some(dir) = std::env::var_os(XACRO_DIR) {
        folders.insert(0, PathBuf::from(dir));
    }
    assert!(
        folders.iter().any(|f| f.join("xacro").is_file()),
        "no `xacro` program on the PATH nor in {XACRO_DIR}: `pip install xacro` (as \
         scripts/test-all.sh does into its virtual environment, whose bin folder it names \
         in {XACRO_DIR})"
    );
    std::env::join_paths(folders).unwrap()
}

/// `eyehand ARGS` with `path` as its PATH: exit code, stdout, stderr.
fn eyehand(args: &[&str], path: &OsString) -> (Option<i32>, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_eyehand"))
        .args(args)
        .env("PATH", path)
        .output()
        .unwrap();
    let text = |b: &[u8]| String::from_utf8_lossy(b).into_owned();
    (out.status.code(), text(&out.stdout), text(&out.stderr))
}

/// A xacro file that includes the SO-100's public URDF (xacro takes the included robot's
/// elements), so that only an expansion gives it links.
fn so100_xacro(folder: &Path) -> PathBuf {
    let urdf = robot_data().join("robots/so_arm_description/urdf/so100.urdf");
    let file = folder.join("so100.urdf.xacro");
    std::fs::write(
        &file,
        format!(
            "<?xml version=\"1.0\"?>\n<robot name=\"so_arm100\" \
             xmlns:xacro=\"http://www.ros.org/wiki/xacro\">\n  \
             <xacro:include filename=\"{}\"/>\n</robot>\n",
            urdf.display()
        ),
    )
    .unwrap();
    file
}

#[test]
fn a_xacro_file_is_expanded_and_gives_the_arm_its_urdf_gives() {
    let folder = tempfile::tempdir().unwrap();
    let xacro = so100_xacro(folder.path());
    let share = robot_data();
    let urdf = share.join("robots/so_arm_description/urdf/so100.urdf");
    let path = path_with_xacro();
    let fk = |file: &Path| {
        let file = file.display().to_string();
        let packages = format!("package_paths={}", share.display());
        let args = [
            "fk",
            "--json",
            "--joints",
            "10,120,-80",
            "--urdf",
            &file,
            "--set",
            &packages,
        ];
        let (code, out, err) = eyehand(&args, &path);
        assert_eq!(code, Some(0), "{file}: {err}");
        assert!(!err.contains("missing"), "{file}: {err}");
        out
    };
    assert_eq!(fk(&xacro), fk(&urdf));
}

#[test]
fn a_xacro_file_without_the_xacro_program_says_how_to_install_it() {
    let folder = tempfile::tempdir().unwrap();
    // A public xacro file of the collection, and a PATH without the program.
    let xacro = robot_data().join("robots/hector_description/robots/quadrotor_base.urdf.xacro");
    let empty = OsString::from(folder.path());
    let file = xacro.display().to_string();
    let (code, _, err) = eyehand(&["reach", "--urdf", &file], &empty);
    assert_eq!(code, Some(2), "{err}");
    assert!(
        err.contains("`xacro` program") && err.contains("pip install xacro"),
        "{err}"
    );
}

#[test]
fn a_xacro_file_the_program_cannot_expand_is_its_error() {
    // The collection's hector quadrotor includes a file under a folder it does not ship.
    let xacro = robot_data().join("robots/hector_description/robots/quadrotor_base.xacro");
    let file = xacro.display().to_string();
    let (code, _, err) = eyehand(&["reach", "--urdf", &file], &path_with_xacro());
    assert_eq!(code, Some(2), "{err}");
    assert!(
        err.contains("`xacro` could not expand it (exit status"),
        "{err}"
    );
    assert!(err.contains("quadrotor_base.urdf.xacro"), "{err}");
}
