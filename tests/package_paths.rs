//! `package://` meshes found through the config's `package_paths`: a URDF in a folder tree
//! of its own loads its mesh with the entry (relative folders taken from the config file's
//! folder, made absolute) and warns, naming the URI and the paths tried, without it.

use eyehand::experiment::setup::load_arm;
use eyehand::experiment::Config;
use eyehand::robot::{Shape, DEFAULT_URDF};
use std::fs;
use std::path::Path;
use std::process::Command;

const ROOT: &str = env!("CARGO_MANIFEST_DIR");
const URI: &str = "package://myarm/meshes/wrist.obj";

/// A folder tree: `robots/myarm/meshes/wrist.obj` (the Panda's finger), `urdf/arm.urdf`
/// (the OSCAR-6 with that mesh as link 5's collision) and `conf/`.
fn tree(root: &Path) {
    let meshes = root.join("robots/myarm/meshes");
    fs::create_dir_all(&meshes).unwrap();
    fs::create_dir_all(root.join("urdf")).unwrap();
    fs::create_dir_all(root.join("conf")).unwrap();
    let finger = format!("{ROOT}/tests/data/panda/franka_panda/meshes/collision/finger.obj");
    fs::copy(finger, meshes.join("wrist.obj")).unwrap();
    let sphere = r#"<geometry><sphere radius="0.045"/></geometry>"#;
    assert!(DEFAULT_URDF.contains(sphere));
    let urdf = DEFAULT_URDF.replacen(
        sphere,
        &format!(r#"<geometry><mesh filename="{URI}"/></geometry>"#),
        1,
    );
    fs::write(root.join("urdf/arm.urdf"), urdf).unwrap();
}

/// The complete default config with `package_paths` set to `value`, written to `conf/arm.conf`.
fn config(root: &Path, value: &str) -> Config {
    let text = eyehand::experiment::defaults_text();
    let line = text
        .lines()
        .find(|l| l.starts_with("package_paths"))
        .unwrap();
    let path = root.join("conf/arm.conf");
    fs::write(&path, text.replace(line, &format!("package_paths {value}"))).unwrap();
    Config::from_file(&path).unwrap()
}

#[test]
fn package_meshes_load_with_the_search_paths_and_warn_without() {
    let dir = tempfile::tempdir().unwrap();
    let root = dir.path();
    tree(root);
    let urdf = root.join("urdf/arm.urdf");

    let found = load_arm(&config(root, "../urdf,../robots"), Some(&urdf)).unwrap();
    assert_eq!(found.warnings, Vec::<String>::new());
    assert!(matches!(
        found.model.links()[5].collisions.as_slice(),
        [(_, Shape::Mesh { .. })]
    ));

    for (value, tried) in [
        ("none", "no package_paths to look in".to_string()),
        (
            "../urdf",
            format!(
                "looked for {}",
                root.canonicalize()
                    .unwrap()
                    .join("urdf/myarm/meshes/wrist.obj")
                    .display()
            ),
        ),
    ] {
        let missing = load_arm(&config(root, value), Some(&urdf)).unwrap();
        assert!(matches!(
            missing.model.links()[5].collisions.as_slice(),
            [(_, Shape::Capsule { .. })]
        ));
        let [warning] = missing.warnings.as_slice() else {
            panic!("one warning: {:?}", missing.warnings);
        };
        assert!(warning.contains(URI), "{warning}");
        assert!(warning.ends_with(&tried), "{warning}");
    }

    // The command line prints the warning and goes on.
    let out = Command::new(env!("CARGO_BIN_EXE_eyehand"))
        .arg("check-config")
        .arg(root.join("conf/arm.conf"))
        .arg("--urdf")
        .arg(&urdf)
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "{stderr}");
    assert!(
        stderr.starts_with("eyehand: warning: ") && stderr.contains(URI),
        "{stderr}"
    );
}
