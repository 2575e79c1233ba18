//! The OSCAR-6 model against hand-computed geometry: forward kinematics, the vertical
//! camera, link stretching, inverse kinematics and the reach space.

use eyehand::experiment::Config;
use eyehand::robot::{ArmModel, Controlled, ReachSpace};
use nalgebra::{Point3, Vector3};
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;

const SHOULDER: f64 = 0.55;
const UPPER: f64 = 0.60;
const FORE: f64 = 0.55;
const CAMERA: f64 = 0.10;

fn deg(t1: f64, t2: f64, t3: f64) -> Controlled {
    Controlled::new(t1, t2, t3).map(f64::to_radians)
}

/// The camera centre by plane geometry: θ2 lifts the upper arm, θ3 bends the forearm down
/// from it, the camera hangs 10 cm below the wrist, θ1 yaws the plane.
fn by_hand(theta: &Controlled, upper: f64, fore: f64, shoulder: f64) -> Point3<f64> {
    let reach = upper * theta.y.cos() + fore * (theta.y - theta.z).cos();
    let height = shoulder + upper * theta.y.sin() + fore * (theta.y - theta.z).sin() - CAMERA;
    Point3::new(reach * theta.x.cos(), reach * theta.x.sin(), height)
}

fn poses() -> Vec<Controlled> {
    vec![
        deg(0.0, 0.0, 90.0),
        deg(0.0, 30.0, 100.0),
        deg(45.0, 10.0, 60.0),
        deg(-80.0, 60.0, 130.0),
        deg(20.0, -5.0, 55.0),
        deg(90.0, 45.0, 45.0),
    ]
}

#[test]
fn forward_kinematics_matches_hand_computed_geometry() {
    let model = ArmModel::oscar6();
    for theta in poses() {
        let camera = model.camera_position(&model.full_pose(&theta));
        let expected = by_hand(&theta, UPPER, FORE, SHOULDER);
        assert!(
            (camera - expected).norm() < 1e-12,
            "{theta:?}: {camera} vs {expected}"
        );
    }
}

#[test]
fn the_wrist_keeps_the_optical_axis_vertical() {
    let model = ArmModel::oscar6();
    let mut rng = ChaCha8Rng::seed_from_u64(7);
    use rand::Rng;
    for _ in 0..1000 {
        let theta = deg(
            rng.random_range(-90.0..90.0),
            rng.random_range(-5.0..75.0),
            rng.random_range(45.0..140.0),
        );
        let q = model.full_pose(&theta);
        let axis = model.camera_pose(&q).rotation * Vector3::z();
        assert!(
            (axis + Vector3::z()).norm() < 1e-9,
            "{theta:?}: optical axis {axis}"
        );
        assert!((q[4] - (90f64.to_radians() + theta.y - theta.z)).abs() < 1e-9);
        assert_eq!((q[3], q[5]), (0.0, 0.0));
    }
}

#[test]
fn image_axes_point_forward_and_right_at_zero_yaw() {
    let model = ArmModel::oscar6();
    let pose = model.camera_pose(&model.full_pose(&deg(0.0, 20.0, 90.0)));
    assert!((pose.rotation * Vector3::x() - Vector3::x()).norm() < 1e-12);
    assert!((pose.rotation * Vector3::y() + Vector3::y()).norm() < 1e-12);
}

#[test]
fn stretching_a_link_moves_the_camera_as_geometry_says() {
    for (link, stretch) in [(1, 0.10), (2, 0.10), (2, -0.10), (3, 0.10), (3, -0.05)] {
        let mut model = ArmModel::oscar6();
        model.stretch_link(link, stretch).unwrap();
        assert!((model.link_stretch(link) - stretch).abs() < 1e-15);
        let lengths = match link {
            1 => (UPPER, FORE, SHOULDER + stretch),
            2 => (UPPER + stretch, FORE, SHOULDER),
            _ => (UPPER, FORE + stretch, SHOULDER),
        };
        for theta in poses() {
            let camera = model.camera_position(&model.full_pose(&theta));
            let expected = by_hand(&theta, lengths.0, lengths.1, lengths.2);
            assert!(
                (camera - expected).norm() < 1e-12,
                "link {link}: {camera} vs {expected}"
            );
        }
    }
    // Link 1 lifts the whole arm by exactly the stretch.
    let mut lifted = ArmModel::oscar6();
    lifted.stretch_link(1, 0.1).unwrap();
    let theta = deg(10.0, 20.0, 80.0);
    let before = ArmModel::oscar6().camera_position(&ArmModel::oscar6().full_pose(&theta));
    let after = lifted.camera_position(&lifted.full_pose(&theta));
    assert!((after - before - Vector3::new(0.0, 0.0, 0.1)).norm() < 1e-12);
}

#[test]
fn bad_stretches_are_errors() {
    let mut model = ArmModel::oscar6();
    assert!(model.stretch_link(4, 0.1).is_err());
    assert!(model.stretch_link(0, 0.1).is_err());
    assert!(model
        .stretch_link(2, -0.7)
        .unwrap_err()
        .to_string()
        .contains("leaves it"));
    assert!(model.stretch_link(2, f64::NAN).is_err());
    assert_eq!(
        model,
        ArmModel::oscar6(),
        "a refused stretch changes nothing"
    );
}

#[test]
fn every_reach_space_point_has_an_elbow_up_pose_inside_limits_and_boundaries() {
    let model = ArmModel::oscar6();
    let config = Config::default_config();
    let reach = ReachSpace::OSCAR6;
    assert!((reach.volume() * 1000.0 - 533.6).abs() < 0.1, "533.6 dm³");
    let mut rng = ChaCha8Rng::seed_from_u64(11);
    let (mut t2_range, mut t3_range) = ((f64::MAX, f64::MIN), (f64::MAX, f64::MIN));
    for _ in 0..5000 {
        let p = reach.sample(&mut rng);
        assert!(reach.contains(&p));
        let theta = model
            .solve_camera_position(&p)
            .unwrap_or_else(|e| panic!("{e}"));
        let q = model.full_pose(&theta);
        assert!((model.camera_position(&q) - p).norm() < 1e-9);
        assert!(model.is_elbow_up(&theta));
        for (i, joint) in model.joints().iter().enumerate() {
            let margin = (q[i] - joint.lower).min(joint.upper - q[i]);
            assert!(
                margin > 1e-3,
                "joint {} at {:.2}° is at its limit",
                i + 1,
                q[i].to_degrees()
            );
        }
        let (t2, t3) = (theta.y.to_degrees(), theta.z.to_degrees());
        t2_range = (t2_range.0.min(t2), t2_range.1.max(t2));
        t3_range = (t3_range.0.min(t3), t3_range.1.max(t3));
        assert!(
            config.boundary_0_low < t2 && t2 < config.boundary_0_high,
            "θ2 {t2}"
        );
        assert!(
            config.boundary_1_low < t3 && t3 < config.boundary_1_high,
            "θ3 {t3}"
        );
    }
    // The ranges a first check of the design measured: shoulder −1°…69°, elbow interior
    // 47°…128° (docs/SIMULATION.md).
    assert!(t2_range.0 > -2.0 && t2_range.1 < 70.0, "{t2_range:?}");
    assert!(
        180.0 - t3_range.1 > 46.0 && 180.0 - t3_range.0 < 129.0,
        "{t3_range:?}"
    );
}

#[test]
fn points_out_of_reach_are_clear_errors() {
    let model = ArmModel::oscar6();
    for p in [
        Point3::new(2.0, 0.0, 0.3),
        Point3::new(0.0, 0.0, 0.5),
        Point3::new(f64::NAN, 0.0, 0.0),
    ] {
        let err = model.solve_camera_position(&p).unwrap_err();
        assert!(err.to_string().contains("unreachable"), "{err}");
    }
}

#[test]
fn a_solved_pose_carries_the_link_frames_of_its_joints() {
    let model = ArmModel::oscar6();
    for theta in poses() {
        let pose = model.pose_of(&theta);
        assert_eq!(pose.frames, model.link_frames(&pose.joints), "{theta:?}");
    }
}
