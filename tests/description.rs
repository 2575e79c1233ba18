//! Any arm from its real URDF: the Franka Panda fixture (meshes, a branching hand, massless
//! links, asymmetric limits), a hand-made UR-style arm and the OSCAR-6 load as robot
//! descriptions, and the chain's forward kinematics equals an independent computation
//! written here from the URDF spec.

use eyehand::robot::description::{
    Chain, DescriptionOptions, DescriptionWarning, JointKind, RobotDescription, Shape,
};
use eyehand::robot::{ArmModel, Joints, DEFAULT_URDF};
use nalgebra::{Isometry3, Matrix3, Matrix4, Translation3, UnitQuaternion, Vector3};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use std::collections::HashMap;
use std::path::{Path, PathBuf};

fn data(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/data")
        .join(name)
}

fn load(name: &str) -> RobotDescription {
    RobotDescription::load(&data(name), &DescriptionOptions::default()).unwrap()
}

/// A rotation by `a` about x, y or z, written out.
fn turn(axis: usize, a: f64) -> Matrix3<f64> {
    let (s, c) = a.sin_cos();
    match axis {
        0 => Matrix3::new(1.0, 0.0, 0.0, 0.0, c, -s, 0.0, s, c),
        1 => Matrix3::new(c, 0.0, s, 0.0, 1.0, 0.0, -s, 0.0, c),
        _ => Matrix3::new(c, -s, 0.0, s, c, 0.0, 0.0, 0.0, 1.0),
    }
}

fn homogeneous(rotation: Matrix3<f64>, translation: Vector3<f64>) -> Matrix4<f64> {
    let mut m = Matrix4::identity();
    m.fixed_view_mut::<3, 3>(0, 0).copy_from(&rotation);
    m.fixed_view_mut::<3, 1>(0, 3).copy_from(&translation);
    m
}

/// The URDF spec's `<origin>`: translation xyz, rotation Rz(yaw)·Ry(pitch)·Rx(roll).
fn origin(pose: &urdf_rs::Pose) -> Matrix4<f64> {
    let [roll, pitch, yaw] = pose.rpy.0;
    let rotation = turn(2, yaw) * turn(1, pitch) * turn(0, roll);
    homogeneous(rotation, Vector3::from(pose.xyz.0))
}

/// A joint's motion: Rodrigues' rotation about the unit axis, or a slide along it.
fn motion(joint: &urdf_rs::Joint, q: f64) -> Matrix4<f64> {
    let axis = Vector3::from(joint.axis.xyz.0).normalize();
    match joint.joint_type {
        urdf_rs::JointType::Fixed => Matrix4::identity(),
        urdf_rs::JointType::Prismatic => homogeneous(Matrix3::identity(), axis * q),
        _ => {
            let k = axis.cross_matrix();
            let rotation = Matrix3::identity() + k * q.sin() + k * k * (1.0 - q.cos());
            homogeneous(rotation, Vector3::zeros())
        }
    }
}

/// The pose of `link` in the root frame, walking the URDF's joints up from it.
fn reference_pose(robot: &urdf_rs::Robot, link: &str, q: &HashMap<String, f64>) -> Matrix4<f64> {
    match robot.joints.iter().find(|j| j.child.link == link) {
        None => Matrix4::identity(),
        Some(j) => {
            let position = q.get(&j.name).copied().unwrap_or(0.0);
            reference_pose(robot, &j.parent.link, q) * origin(&j.origin) * motion(j, position)
        }
    }
}

/// Random joint positions inside the limits (±π for unlimited joints), by joint name.
fn random_pose(chain: &Chain, rng: &mut ChaCha8Rng) -> (Vec<f64>, HashMap<String, f64>) {
    let q: Vec<f64> = chain
        .joints
        .iter()
        .map(|j| {
            let (lo, hi) = (j.limits.lower.max(-3.2), j.limits.upper.min(3.2));
            rng.random_range(lo..=hi)
        })
        .collect();
    let named = chain
        .joints
        .iter()
        .zip(&q)
        .map(|(j, &v)| (j.name.clone(), v))
        .collect();
    (q, named)
}

fn assert_same(ours: &Isometry3<f64>, reference: &Matrix4<f64>, what: &str) {
    let gap = (ours.to_homogeneous() - reference).abs().max();
    assert!(
        gap < 1e-9,
        "{what}: off by {gap:e}\nours {}\nreference {reference}",
        ours.to_homogeneous()
    );
}

/// 100 random poses: every link merged into a chain body, and a camera mounted off the
/// camera link, where the independent computation puts them.
fn fk_matches_the_spec(file: &str, camera_link: &str, seed: u64) {
    let description = load(file);
    let robot = urdf_rs::read_file(data(file)).unwrap();
    let chain = Chain::new(&description, camera_link).unwrap();
    let mount = Isometry3::from_parts(
        Translation3::new(0.01, -0.02, 0.05),
        UnitQuaternion::from_euler_angles(0.3, -0.2, 0.1),
    );
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let mut frames = vec![Isometry3::identity(); chain.bodies.len()];
    for _ in 0..100 {
        let (q, named) = random_pose(&chain, &mut rng);
        chain.body_frames(&q, &mut frames).unwrap();
        for body in &chain.bodies {
            for &(link, _) in &body.links {
                let name = &description.links[link].name;
                let ours = chain.link_pose(&frames, link).unwrap();
                assert_same(&ours, &reference_pose(&robot, name, &named), name);
            }
        }
        let camera = reference_pose(&robot, camera_link, &named) * mount.to_homogeneous();
        assert_same(&chain.camera_pose(&q, &mount).unwrap(), &camera, "camera");
    }
}

#[test]
fn the_panda_loads_with_its_collision_meshes_and_warns_of_its_missing_visual_ones() {
    let panda = load("panda/panda.urdf");
    assert_eq!(
        (panda.name.as_str(), panda.links.len(), panda.joints.len()),
        ("panda", 13, 12)
    );
    assert_eq!(panda.links[panda.root].name, "panda_link0");
    let missing: Vec<&str> = panda
        .warnings
        .iter()
        .map(|w| match w {
            DescriptionWarning::MissingVisualMesh { filename, .. } => filename.as_str(),
            other => panic!("only visual meshes are missing: {other}"),
        })
        .collect();
    assert_eq!(missing.len(), 9, "{missing:?}");
    assert!(missing.iter().all(|f| f.contains("/visual/")));
    for link in &panda.links {
        for element in &link.collisions {
            let Shape::Mesh { mesh, .. } = &element.geometry else {
                panic!("{}: a mesh", link.name)
            };
            let hull = mesh.hull.as_ref().expect("collision meshes have hulls");
            assert!(
                mesh.mesh.triangles.len() > 10 && hull.triangles.len() >= 4,
                "{}",
                link.name
            );
        }
    }
    let fingers = [
        panda.link_index("panda_leftfinger"),
        panda.link_index("panda_rightfinger"),
    ];
    let [Shape::Mesh { mesh: left, .. }, Shape::Mesh { mesh: right, .. }] =
        fingers.map(|l| &panda.links[l.unwrap()].collisions[0].geometry)
    else {
        panic!("finger meshes")
    };
    assert!(
        std::sync::Arc::ptr_eq(&left.mesh, &right.mesh),
        "one file read once"
    );
}

#[test]
fn the_panda_chain_to_its_hand_has_seven_revolute_joints_and_holds_its_fingers() {
    let panda = load("panda/panda.urdf");
    let chain = Chain::new(&panda, "panda_hand").unwrap();
    let names: Vec<&str> = chain.joints.iter().map(|j| j.name.as_str()).collect();
    assert_eq!(
        names,
        (1..=7)
            .map(|i| format!("panda_joint{i}"))
            .collect::<Vec<_>>()
    );
    assert!(chain.joints.iter().all(|j| j.kind == JointKind::Revolute));
    // Asymmetric limits as given: joint 4 from -3.1416 (the URDF's rounding of -π) to 0.
    let j4 = &chain.joints[3].limits;
    assert_eq!((j4.lower * 1e4).round(), -31416.0);
    assert_eq!(
        (j4.upper, j4.effort, j4.velocity),
        (0.0, Some(87.0), Some(2.175))
    );
    let held: Vec<(&str, f64, Option<usize>)> = chain
        .held
        .iter()
        .map(|h| (h.name.as_str(), h.position, h.body))
        .collect();
    assert_eq!(
        held,
        [
            ("panda_finger_joint1", 0.0, Some(7)),
            ("panda_finger_joint2", 0.0, Some(7))
        ]
    );
    // link7, the massless link8, the hand and the massless grasp target are one body.
    let hand_body = &chain.bodies[7];
    let merged: Vec<&str> = hand_body
        .links
        .iter()
        .map(|(l, _)| panda.links[*l].name.as_str())
        .collect();
    assert_eq!(
        merged,
        [
            "panda_link7",
            "panda_link8",
            "panda_hand",
            "panda_grasptarget"
        ]
    );
    assert!((hand_body.inertial.mass - 1.01).abs() < 1e-12);
    // COM: 0.2 kg at z 0.08 and 0.81 kg at z 0.107 + 0.04 in link7's frame.
    let com_z = (0.2 * 0.08 + 0.81 * 0.147) / 1.01;
    assert!((hand_body.inertial.com - nalgebra::Point3::new(0.0, 0.0, com_z)).norm() < 1e-12);
    // Parallel axis about x: 0.1 + 0.1 + Σ m dz².
    let ixx = 0.2 + 0.2 * (0.08 - com_z).powi(2) + 0.81 * (0.147 - com_z).powi(2);
    assert!((hand_body.inertial.inertia[(0, 0)] - ixx).abs() < 1e-12);
}

#[test]
fn panda_forward_kinematics_matches_the_urdf_spec() {
    fk_matches_the_spec("panda/panda.urdf", "panda_hand", 16);
}

#[test]
fn ur_style_arm_loads_merges_its_dummies_and_matches_the_urdf_spec() {
    let ur = load("ur_style.urdf");
    assert!(ur.warnings.is_empty());
    let chain = Chain::new(&ur, "tool0").unwrap();
    assert_eq!(chain.joints.len(), 6);
    assert_eq!(chain.joints[5].kind, JointKind::Continuous);
    assert_eq!(chain.joints[0].dynamics.damping, 0.5);
    let base: Vec<&str> = chain.bodies[0]
        .links
        .iter()
        .map(|(l, _)| ur.links[*l].name.as_str())
        .collect();
    assert_eq!(base, ["base_link", "base_link_inertia"]);
    assert_eq!(chain.bodies[0].inertial.mass, 4.0);
    // The π turn of the base is composed into the first joint's frame.
    let turned = chain.joints[0].origin.rotation.to_rotation_matrix();
    assert!(
        (turned.matrix() - turn(2, std::f64::consts::PI))
            .abs()
            .max()
            < 1e-12
    );
    // The tilted inertial frame of the upper arm gives off-diagonal terms, kept symmetric.
    let upper = chain.bodies[2].inertial.inertia;
    assert!(upper[(0, 1)].abs() > 1e-4 && (upper - upper.transpose()).norm() < 1e-15);
    assert_eq!(
        chain.bodies[6].links.len(),
        3,
        "wrist_3_link, flange and tool0"
    );
    fk_matches_the_spec("ur_style.urdf", "tool0", 17);
}

#[test]
fn the_oscar6_through_the_description_puts_the_camera_where_arm_model_does() {
    let folder = Path::new(env!("CARGO_MANIFEST_DIR")).join("urdf");
    let oscar =
        RobotDescription::parse(DEFAULT_URDF, "oscar6.urdf", &folder, &Default::default()).unwrap();
    let chain = Chain::new(&oscar, "camera_link").unwrap();
    assert_eq!(chain.joints.len(), 6);
    let model = ArmModel::oscar6();
    let mut rng = ChaCha8Rng::seed_from_u64(6);
    for _ in 0..100 {
        let (q, _) = random_pose(&chain, &mut rng);
        let ours = chain.camera_pose(&q, &Isometry3::identity()).unwrap();
        let theirs = model.camera_pose(&Joints::from_slice(&q));
        assert_same(&ours, &theirs.to_homogeneous(), "camera");
    }
}
