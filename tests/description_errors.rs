//! A malformed URDF, a chain that cannot be cut from it, or a mesh that cannot be read is a
//! clear error naming the element, or a warning with a stand-in where the description can
//! go on; tests match on the kinds.

use eyehand::robot::description::{
    Chain, DescriptionErrorKind as Kind, DescriptionOptions, DescriptionWarning, RobotDescription,
    Shape,
};
use nalgebra::{Isometry3, Vector3};
use std::path::{Path, PathBuf};

fn link(name: &str) -> String {
    format!(
        r#"<link name="{name}"><inertial><mass value="1"/>
        <inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/></inertial></link>"#
    )
}

fn joint(name: &str, kind: &str, parent: &str, child: &str) -> String {
    format!(
        r#"<joint name="{name}" type="{kind}"><parent link="{parent}"/><child link="{child}"/>
        <origin xyz="0 0 0.5"/><axis xyz="0 0 1"/>
        <limit lower="-1" upper="2" effort="10" velocity="1"/></joint>"#
    )
}

fn robot(parts: &[String]) -> String {
    format!("<robot name=\"t\">{}</robot>", parts.concat())
}

fn parse_in(
    text: &str,
    folder: &Path,
    options: &DescriptionOptions,
) -> Result<RobotDescription, Kind> {
    RobotDescription::parse(text, "t.urdf", folder, options).map_err(|e| {
        assert_eq!(e.file, "t.urdf");
        e.kind
    })
}

fn kind_of(text: &str) -> Kind {
    parse_in(text, Path::new("."), &DescriptionOptions::default()).unwrap_err()
}

#[test]
fn a_cycle_is_named_with_its_links() {
    let detached = robot(&[
        link("base"),
        link("a"),
        link("b"),
        joint("j1", "revolute", "base", "a"),
        link("c"),
        link("d"),
        joint("cd", "fixed", "c", "d"),
        joint("dc", "fixed", "d", "c"),
    ]);
    let Kind::Cycle { links } = kind_of(&detached) else {
        panic!("a cycle")
    };
    assert_eq!(links.len(), 3);
    assert!(links.contains(&"c".into()) && links.contains(&"d".into()) && links[0] == links[2]);
    let onto_itself = robot(&[link("base"), joint("loop", "revolute", "base", "base")]);
    assert_eq!(
        kind_of(&onto_itself),
        Kind::Cycle {
            links: vec!["base".into(), "base".into()]
        }
    );
}

#[test]
fn two_roots_two_parents_and_missing_links_are_named() {
    let two_roots = robot(&[
        link("r1"),
        link("a"),
        joint("j", "revolute", "r1", "a"),
        link("r2"),
    ]);
    assert_eq!(
        kind_of(&two_roots),
        Kind::TwoRoots {
            roots: vec!["r1".into(), "r2".into()]
        }
    );
    let two_parents = robot(&[
        link("r"),
        link("a"),
        link("b"),
        joint("ra", "revolute", "r", "a"),
        joint("rb", "revolute", "r", "b"),
        joint("ab", "fixed", "a", "b"),
    ]);
    assert_eq!(
        kind_of(&two_parents),
        Kind::TwoParents {
            link: "b".into(),
            joints: vec!["rb".into(), "ab".into()]
        }
    );
    let missing = robot(&[link("r"), joint("j", "revolute", "r", "ghost")]);
    assert_eq!(
        kind_of(&missing),
        Kind::MissingLink {
            joint: "j".into(),
            role: "child".into(),
            link: "ghost".into()
        }
    );
    let floating = robot(&[link("r"), link("a"), joint("free", "floating", "r", "a")]);
    assert_eq!(
        kind_of(&floating),
        Kind::UnsupportedJoint {
            joint: "free".into(),
            found: "floating".into()
        }
    );
    assert!(matches!(
        kind_of("<robot name=\"t\">"),
        Kind::NotUrdf { .. }
    ));
}

fn panda() -> RobotDescription {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/panda/panda.urdf");
    RobotDescription::load(&path, &DescriptionOptions::default()).unwrap()
}

#[test]
fn a_camera_link_off_the_tree_or_at_its_root_is_refused() {
    let panda = panda();
    let kind = |name: &str| Chain::new(&panda, name).unwrap_err().kind;
    assert_eq!(
        kind("panda_camera"),
        Kind::UnknownLink {
            link: "panda_camera".into()
        }
    );
    assert_eq!(
        kind("panda_link0"),
        Kind::NoMovingJoint {
            link: "panda_link0".into()
        }
    );
    let error = Chain::new(&panda, "panda_camera").unwrap_err();
    assert!(error
        .to_string()
        .ends_with("panda.urdf: camera link `panda_camera` is not a link of the robot"));
}

#[test]
fn learned_joints_must_be_three_moving_joints_of_the_chain() {
    let panda = panda();
    let chain = Chain::new(&panda, "panda_hand").unwrap();
    let learned = |names: [&str; 3]| chain.learned_joints(&panda, &names).map_err(|e| e.kind);
    assert_eq!(
        learned(["panda_joint1", "panda_joint2", "panda_joint4"]),
        Ok([0, 1, 3])
    );
    assert_eq!(
        learned(["panda_joint1", "panda_joint8", "panda_joint4"]),
        Err(Kind::LearnedJointFixed {
            joint: "panda_joint8".into()
        })
    );
    assert_eq!(
        learned(["panda_finger_joint1", "panda_joint2", "panda_joint4"]),
        Err(Kind::LearnedJointOffChain {
            joint: "panda_finger_joint1".into(),
            camera_link: "panda_hand".into()
        })
    );
    assert_eq!(
        learned(["panda_joint1", "panda_joint2", "panda_joint2"]),
        Err(Kind::LearnedJointRepeated {
            joint: "panda_joint2".into()
        })
    );
    assert_eq!(
        learned(["elbow", "panda_joint2", "panda_joint4"]),
        Err(Kind::UnknownJoint {
            joint: "elbow".into()
        })
    );
    // Cut at link 4, joints 5–7 are off the chain (and held).
    let short = Chain::new(&panda, "panda_link4").unwrap();
    assert_eq!(short.joints.len(), 4);
    assert_eq!(short.held.len(), 5);
    assert_eq!(
        short
            .learned_joints(&panda, &["panda_joint1", "panda_joint2", "panda_joint6"])
            .unwrap_err()
            .kind,
        Kind::LearnedJointOffChain {
            joint: "panda_joint6".into(),
            camera_link: "panda_link4".into()
        }
    );
    let mut frames = vec![Isometry3::identity(); 3];
    let wrong = chain.body_frames(&[0.0; 7], &mut frames).unwrap_err().kind;
    assert_eq!(
        wrong,
        Kind::JointCount {
            expected: 8,
            found: 3
        }
    );
    let wrong = chain
        .camera_pose(&[0.0; 6], &Isometry3::identity())
        .unwrap_err()
        .kind;
    assert_eq!(
        wrong,
        Kind::JointCount {
            expected: 7,
            found: 6
        }
    );
}

/// A two-link arm whose link `a` has one collision and one visual mesh, written to a folder.
fn mesh_arm(collision: &str, visual: &str) -> String {
    robot(&[
        link("base"),
        format!(
            r#"<link name="a"><visual><geometry><mesh filename="{visual}"/></geometry></visual>
            <collision><geometry><mesh filename="{collision}" scale="1 1 2"/></geometry></collision></link>"#
        ),
        link("b"),
        joint("ja", "revolute", "base", "a"),
        joint("jb", "revolute", "a", "b"),
    ])
}

fn folder_with(files: &[(&str, &str)]) -> tempfile::TempDir {
    let dir = tempfile::tempdir().unwrap();
    for (name, text) in files {
        let path = dir.path().join(name);
        std::fs::create_dir_all(path.parent().unwrap()).unwrap();
        std::fs::write(path, text).unwrap();
    }
    dir
}

const BOX_OBJ: &str = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";

#[test]
fn a_mesh_that_is_not_a_mesh_is_named() {
    let dir = folder_with(&[
        ("bad.obj", "hello, I am a shopping list\n"),
        ("bad.stl", "not an stl"),
        ("bad.dae", "<COLLADA/>"),
        ("arm.ply", "ply\nformat ascii 1.0\n"),
    ]);
    let options = DescriptionOptions::default();
    for bad in ["bad.obj", "bad.stl", "bad.dae"] {
        let kind = parse_in(&mesh_arm(bad, bad), dir.path(), &options).unwrap_err();
        let Kind::NotAMesh { link, filename, .. } = kind else {
            panic!("{bad}: {kind}")
        };
        assert_eq!((link.as_str(), filename.as_str()), ("a", bad));
    }
    let kind = parse_in(&mesh_arm("arm.ply", "arm.ply"), dir.path(), &options).unwrap_err();
    assert_eq!(
        kind,
        Kind::UnsupportedMesh {
            link: "a".into(),
            filename: "arm.ply".into()
        }
    );
}

#[test]
fn a_missing_collision_mesh_becomes_a_capsule_with_a_warning() {
    let dir = folder_with(&[("robots/pkg/meshes/a.obj", BOX_OBJ), ("arm.ply", "ply\n")]);
    let none = DescriptionOptions::default();
    let arm = parse_in(
        &mesh_arm("package://pkg/meshes/a.obj", "arm.ply"),
        dir.path(),
        &none,
    )
    .unwrap();
    assert_eq!(
        arm.warnings,
        [
            DescriptionWarning::UnreadVisualMesh {
                link: "a".into(),
                filename: "arm.ply".into()
            },
            DescriptionWarning::MissingCollisionMesh {
                link: "a".into(),
                filename: "package://pkg/meshes/a.obj".into(),
                radius: 0.05,
                length: 0.5
            },
        ]
    );
    let stand_in = &arm.links[1].collisions[0];
    assert_eq!(
        stand_in.geometry,
        Shape::Capsule {
            radius: 0.05,
            length: 0.5
        }
    );
    assert!((stand_in.origin.translation.vector - Vector3::new(0.0, 0.0, 0.25)).norm() < 1e-15);
    assert!(arm.links[1].visuals.is_empty());
    // With the package's folder on the search path the mesh is read, scaled by 2 along z.
    let found = DescriptionOptions {
        package_paths: vec![PathBuf::from("/nowhere"), dir.path().join("robots")],
    };
    let arm = parse_in(
        &mesh_arm("package://pkg/meshes/a.obj", "robots/pkg/meshes/a.obj"),
        dir.path(),
        &found,
    )
    .unwrap();
    assert!(arm.warnings.is_empty(), "{:?}", arm.warnings);
    let Shape::Mesh { mesh, .. } = &arm.links[1].collisions[0].geometry else {
        panic!("a mesh")
    };
    assert_eq!(mesh.scale, Vector3::new(1.0, 1.0, 2.0));
    assert!(mesh.mesh.vertices.iter().any(|p| p.z == 2.0));
    assert_eq!(mesh.hull.as_ref().unwrap().triangles.len(), 4);
    let Shape::Mesh { mesh: visual, .. } = &arm.links[1].visuals[0].geometry else {
        panic!("a mesh")
    };
    assert!(visual.hull.is_none() && visual.mesh.vertices.iter().all(|p| p.z <= 1.0));
}
