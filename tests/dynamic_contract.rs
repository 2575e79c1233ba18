//! The regression contract between the dynamic (Rapier) simulator and the kinematic model:
//! for the same commanded moves both end at the same joint angles, camera centre and camera
//! readings — on the nominal robot, after links are stretched or shortened, after the
//! camera is turned (also when such events come one on top of the other between moves, as
//! a run applies them), and when a joint limit stops a move. The arm holds a pose under
//! gravity, runs are deterministic, and every learner closes its loop over the dynamic sim.
//! Both engines (`rk4` and `rapier`) are held to the same contract.

use eyehand::camera::{Camera, CameraModel, ProjectionCamera, RaycastCamera};
use eyehand::experiment::{run, CameraKind, Config, Event, RunOptions, SimKind};
use eyehand::learn::Method;
use eyehand::robot::{
    ArmModel, Controlled, DynamicSettings, DynamicSim, Engine, KinematicSim, Simulator,
};
use nalgebra::{Point3, Vector3};

/// Camera centres (cm) the moves go between, spread over the reach space.
const WAYPOINTS_CM: [[f64; 3]; 7] = [
    [60.0, 0.0, 20.0],
    [90.0, 10.0, 50.0],
    [40.0, -30.0, 5.0],
    [20.0, 80.0, 40.0],
    [70.0, -60.0, 10.0],
    [47.0, 2.0, 51.0],
    [60.5, 0.3, 19.8],
];
/// Camera centres agree to this (m): the contract's 0.05 mm.
const CAMERA_TOL: f64 = 0.05e-3;
/// Readings agree to this (px).
const READING_TOL: f64 = 0.1;

/// The default settings on `engine`.
fn settings(engine: Engine) -> DynamicSettings {
    DynamicSettings {
        engine,
        ..DynamicSettings::default()
    }
}

/// A dynamic simulator on `engine` and a kinematic simulator of the same model.
fn pair(model: &ArmModel, engine: Engine) -> (DynamicSim, KinematicSim) {
    (
        DynamicSim::new(model.clone(), settings(engine)),
        KinematicSim::new(model.clone(), settings(engine).moves),
    )
}

fn pose_at(model: &ArmModel, cm: &[f64; 3]) -> Controlled {
    let at = Point3::from(Vector3::from(*cm) / 100.0);
    model
        .solve_camera_position(&at)
        .expect("a reachable waypoint")
}

/// Asserts that both simulators are at the same pose and see `object` alike.
fn assert_agree(dynamic: &DynamicSim, kinematic: &KinematicSim, object: &Point3<f64>, what: &str) {
    let joint_tol = 2.0 * dynamic.settings().settle_position_tol;
    let what = format!("{:?}, {what}", dynamic.settings().engine);
    let dq = (dynamic.joints() - kinematic.joints()).amax();
    assert!(dq <= joint_tol, "{what}: joints differ by {dq:.3e} rad");
    let camera = (dynamic.camera_pose().translation.vector
        - kinematic.camera_pose().translation.vector)
        .norm();
    assert!(
        camera <= CAMERA_TOL,
        "{what}: camera centres {:.2e} mm apart",
        camera * 1e3
    );
    let eye = ProjectionCamera::new(CameraModel::default());
    let (a, b) = (
        eye.read(&dynamic.camera_pose(), object),
        eye.read(&kinematic.camera_pose(), object),
    );
    match (a, b) {
        (Ok(a), Ok(b)) => assert!(
            (a - b).amax() <= READING_TOL,
            "{what}: readings {a} and {b} differ"
        ),
        (a, b) => assert_eq!(a.is_ok(), b.is_ok(), "{what}: seen by one only"),
    }
}

/// Every move between consecutive waypoints (and back to the first), each starting from a
/// placed pose, with the object under the move's goal.
fn check_moves(model: &ArmModel, what: &str, engine: Engine) {
    let (mut dynamic, mut kinematic) = pair(model, engine);
    let poses: Vec<Controlled> = WAYPOINTS_CM.iter().map(|w| pose_at(model, w)).collect();
    for (k, start) in poses.iter().enumerate() {
        let end = poses[(k + 1) % poses.len()];
        let goal = kinematic
            .model()
            .camera_position(&kinematic.model().full_pose(&end));
        let object = goal - Vector3::z() * 0.20;
        dynamic.place(start).unwrap();
        kinematic.place(start).unwrap();
        assert_agree(
            &dynamic,
            &kinematic,
            &object,
            &format!("{what}, placed at {k}"),
        );
        let report = dynamic.execute(&(end - start));
        let reference = kinematic.execute(&(end - start));
        assert!(report.settled, "{engine:?}, {what}, move {k} settles");
        assert_eq!(report.stopped_by_limit, reference.stopped_by_limit);
        assert!(report.duration >= reference.duration - 1e-9);
        assert_agree(&dynamic, &kinematic, &object, &format!("{what}, move {k}"));
        // A small correction after the gross move, as feedback steps make.
        let nudge = Controlled::new(0.3, -0.2, 0.25).map(f64::to_radians);
        dynamic.execute(&nudge);
        kinematic.execute(&nudge);
        assert_agree(&dynamic, &kinematic, &object, &format!("{what}, nudge {k}"));
    }
}

#[test]
fn moves_across_the_reach_space_end_where_the_kinematic_model_ends() {
    for engine in Engine::ALL {
        check_moves(&ArmModel::oscar6(), "nominal", engine);
    }
}

#[test]
fn stretched_and_shortened_links_agree() {
    for link in 1..=3 {
        for delta in [0.10, -0.10] {
            let mut model = ArmModel::oscar6();
            model.stretch_link(link, delta).unwrap();
            for engine in Engine::ALL {
                check_moves(
                    &model,
                    &format!("link {link} {delta:+} m (built so)"),
                    engine,
                );
            }
        }
    }
}

#[test]
fn a_link_stretched_at_run_time_moves_the_camera_by_the_stretch() {
    for engine in Engine::ALL {
        for link in 1..=3 {
            for delta in [0.10, -0.10] {
                let model = ArmModel::oscar6();
                let (mut dynamic, mut kinematic) = pair(&model, engine);
                let start = pose_at(&model, &WAYPOINTS_CM[0]);
                dynamic.place(&start).unwrap();
                kinematic.place(&start).unwrap();
                let before = dynamic.camera_pose().translation.vector;
                dynamic.stretch_link(link, delta).unwrap();
                let moved = (dynamic.camera_pose().translation.vector - before).norm();
                assert!(
                    (moved - delta.abs()).abs() < CAMERA_TOL,
                    "link {link}: {moved} m"
                );
                kinematic.stretch_link(link, delta).unwrap();
                let what = format!("link {link} {delta:+} m at run time");
                let object = Point3::new(0.6, 0.0, 0.0);
                assert_agree(&dynamic, &kinematic, &object, &what);
                let delta_move = pose_at(kinematic.model(), &WAYPOINTS_CM[1]) - start;
                dynamic.execute(&delta_move);
                kinematic.execute(&delta_move);
                assert_agree(&dynamic, &kinematic, &object, &what);
            }
        }
    }
}

#[test]
fn a_turned_camera_agrees() {
    for engine in Engine::ALL {
        let model = ArmModel::oscar6();
        let (mut dynamic, mut kinematic) = pair(&model, engine);
        dynamic.rotate_camera(30f64.to_radians());
        kinematic.rotate_camera(30f64.to_radians());
        let start = pose_at(&model, &WAYPOINTS_CM[0]);
        let end = pose_at(&model, &WAYPOINTS_CM[6]);
        let object = Point3::new(0.62, 0.02, 0.0);
        dynamic.place(&start).unwrap();
        kinematic.place(&start).unwrap();
        dynamic.execute(&(end - start));
        kinematic.execute(&(end - start));
        assert_agree(&dynamic, &kinematic, &object, "camera turned 30°");
        let c = ProjectionCamera::default()
            .read(&dynamic.camera_pose(), &object)
            .unwrap();
        assert!(c.x.hypot(c.y) > 1.0, "the object is off-centre: {c}");
    }
}

#[test]
fn events_applied_between_moves_keep_both_simulators_in_agreement() {
    for engine in Engine::ALL {
        // As a run applies them: each before a trial, after the arm has moved, one on top of
        // the other.
        let model = ArmModel::oscar6();
        let (mut dynamic, mut kinematic) = pair(&model, engine);
        let object = Point3::new(0.62, 0.02, 0.0);
        let start = pose_at(&model, &WAYPOINTS_CM[0]);
        dynamic.place(&start).unwrap();
        kinematic.place(&start).unwrap();
        let events: [Event; 4] = [
            "elongate:2:2:10".parse().unwrap(),
            "rotate:3:30".parse().unwrap(),
            "elongate:4:1:-5".parse().unwrap(),
            "rotate:5:-90".parse().unwrap(),
        ];
        for (k, event) in events.iter().enumerate() {
            let end = pose_at(
                kinematic.model(),
                &WAYPOINTS_CM[(k + 5) % WAYPOINTS_CM.len()],
            );
            let delta = end - kinematic.model().controlled_of(&kinematic.joints());
            dynamic.execute(&delta);
            kinematic.execute(&delta);
            assert_agree(&dynamic, &kinematic, &object, &format!("before {event}"));
            event.apply(&mut dynamic).unwrap();
            event.apply(&mut kinematic).unwrap();
            assert_agree(&dynamic, &kinematic, &object, &format!("after {event}"));
            let nudge = Controlled::new(0.3, -0.2, 0.25).map(f64::to_radians);
            dynamic.execute(&nudge);
            kinematic.execute(&nudge);
            assert_agree(
                &dynamic,
                &kinematic,
                &object,
                &format!("moved after {event}"),
            );
        }
    }
}

#[test]
fn moves_stopped_by_a_joint_limit_agree() {
    for engine in Engine::ALL {
        let model = ArmModel::oscar6();
        let deg = |a: f64, b: f64, c: f64| Controlled::new(a, b, c).map(f64::to_radians);
        // θ2 runs into its upper limit; θ3 into its lower one; θ5 (the wrist) into its upper.
        for (start, delta, joint) in [
            (deg(0.0, 80.0, 90.0), deg(10.0, 40.0, 0.0), 1),
            (deg(0.0, 0.0, 10.0), deg(0.0, 0.0, -30.0), 2),
            (deg(0.0, 60.0, 40.0), deg(0.0, 0.0, -50.0), 4),
        ] {
            let (mut dynamic, mut kinematic) = pair(&model, engine);
            dynamic.place(&start).unwrap();
            kinematic.place(&start).unwrap();
            let report = dynamic.execute(&delta);
            let reference = kinematic.execute(&delta);
            assert_eq!(reference.stopped_by_limit, Some(joint));
            assert_eq!(report.stopped_by_limit, Some(joint));
            assert!(report.settled, "joint {joint}");
            let limit = &model.joints()[joint];
            let q = dynamic.joints()[joint];
            assert!(
                q <= limit.upper + 1e-5 && q >= limit.lower - 1e-5,
                "joint {joint} holds at its limit: {q}"
            );
            let object =
                kinematic.model().camera_position(&kinematic.joints()) - Vector3::z() * 0.2;
            assert_agree(&dynamic, &kinematic, &object, &format!("limit {joint}"));
        }
    }
}

#[test]
fn the_arm_holds_a_pose_under_gravity_for_ten_seconds() {
    for engine in Engine::ALL {
        let model = ArmModel::oscar6();
        // Tolerances only an arm exactly still meets.
        let hold = DynamicSettings {
            settle_position_tol: 1e-300,
            settle_speed_tol: 1e-300,
            settle_timeout: 10.0,
            ..settings(engine)
        };
        let mut sim = DynamicSim::new(model.clone(), hold);
        // Outstretched, the heaviest load on the shoulder.
        sim.place(&Controlled::new(0.3, 0.0, 0.05)).unwrap();
        let (joints, camera) = (sim.joints(), sim.camera_pose().translation.vector);
        let timeouts = sim.counters().settle_timeouts();
        // Zero moves for 10 s: each steps until its 10 s time-out, or settles at once
        // where the arm stays exactly still (on rk4 the bias fed forward carries it
        // exactly), then the next follows.
        let (mut held, mut unsettled) = (0.0, 0);
        while held < 10.0 - 1e-9 {
            let report = sim.execute(&Controlled::zeros());
            held += report.duration;
            unsettled += u64::from(!report.settled);
        }
        assert!(held < 10.01, "{engine:?}: held {held} s");
        let drift = (sim.joints() - joints).amax();
        assert!(
            drift < settings(engine).settle_position_tol,
            "joints drift {drift:.2e} rad"
        );
        let moved = (sim.camera_pose().translation.vector - camera).norm();
        assert!(
            moved < CAMERA_TOL,
            "the camera sinks {:.2e} mm",
            moved * 1e3
        );
        assert_eq!(sim.counters().settle_timeouts(), timeouts + unsettled);
    }
}

#[test]
fn the_same_commands_give_the_same_results() {
    for engine in Engine::ALL {
        let model = ArmModel::oscar6();
        let commands = |sim: &mut DynamicSim| {
            sim.place(&pose_at(&model, &WAYPOINTS_CM[2])).unwrap();
            sim.execute(&Controlled::new(0.4, 0.2, -0.3));
            sim.stretch_link(2, 0.05).unwrap();
            sim.execute(&Controlled::new(-0.1, 0.05, 0.02));
            (sim.joints(), sim.camera_pose())
        };
        let first = commands(&mut DynamicSim::new(model.clone(), settings(engine)));
        let second = commands(&mut DynamicSim::new(model.clone(), settings(engine)));
        assert_eq!(first, second);
    }
}

#[test]
fn bad_commands_and_settings_neither_panic_nor_give_nan() {
    for engine in Engine::ALL {
        let nonsense = DynamicSettings {
            dt: f64::NAN,
            solver_iterations: 0,
            motor_stiffness: -1.0,
            settle_timeout: f64::INFINITY,
            ..settings(engine)
        };
        let mut sim = DynamicSim::new(ArmModel::oscar6(), nonsense);
        let fixed = DynamicSettings {
            solver_iterations: 1,
            ..settings(engine)
        };
        assert_eq!(*sim.settings(), fixed);
        let before = sim.joints();
        let report = sim.execute(&Controlled::new(f64::NAN, 0.1, f64::INFINITY));
        assert_eq!(report.executed, Controlled::zeros());
        assert_eq!(sim.joints(), before);
        assert!(sim.place(&Controlled::new(0.0, 3.0, 0.0)).is_err());
        assert!(sim.stretch_link(4, 0.1).is_err());
        assert!(sim.stretch_link(2, -0.7).is_err());
        sim.rotate_camera(f64::NAN);
        sim.execute(&Controlled::new(5.0, -5.0, 5.0));
        assert!(sim.joints().iter().all(|v| v.is_finite()));
        assert!(sim
            .camera_pose()
            .translation
            .vector
            .iter()
            .all(|v| v.is_finite()));
    }
}

#[test]
fn raycast_readings_from_the_dynamic_sim_match_the_projection() {
    for engine in Engine::ALL {
        let model = ArmModel::oscar6();
        let mut sim = DynamicSim::new(model.clone(), settings(engine));
        let rays = RaycastCamera::new(CameraModel::default(), 512);
        let exact = ProjectionCamera::default();
        let start = pose_at(&model, &WAYPOINTS_CM[0]);
        sim.place(&start).unwrap();
        for object in [Point3::new(0.6, 0.0, 0.0), Point3::new(0.62, 0.03, 0.05)] {
            let (a, b) = (
                rays.read(&sim.camera_pose(), &object).unwrap(),
                exact.read(&sim.camera_pose(), &object).unwrap(),
            );
            assert!((a - b).xy().amax() < 0.5, "{a} vs {b}");
        }
    }
}

#[test]
fn every_learner_closes_its_loop_over_the_dynamic_sim() {
    let data = tempfile::tempdir().unwrap();
    for (k, method) in Method::ALL.into_iter().enumerate() {
        let camera = [CameraKind::Projection, CameraKind::Raycast][k % 2];
        // The engines take turns, the other way round from the cameras.
        let engine = Engine::ALL[(k / 2) % 2];
        let mut config = Config::default_config();
        config.method = method;
        config.sim = SimKind::Dynamic;
        config.engine = engine;
        config.camera = camera;
        config.trials = 25;
        config.seed = 3;
        let options = RunOptions {
            events: vec![
                "elongate:10:2:5".parse().unwrap(),
                "rotate:15:20".parse().unwrap(),
            ],
            ..RunOptions::new(config, data.path())
        };
        let result = run(&options)
            .unwrap_or_else(|e| panic!("{method}/{camera}/{engine} runs on the dynamic sim: {e}"));
        let summary = &result.summary;
        let means: Vec<f64> = summary.mean_distance_mm.iter().flatten().copied().collect();
        assert!(!means.is_empty(), "{method}/{camera}: distances recorded");
        assert!(
            means.iter().all(|d| d.is_finite()),
            "{method}/{camera}: {means:?}"
        );
        let steps = std::fs::read_to_string(result.folder.join("1step")).unwrap();
        assert!(
            !steps.contains("NaN") && !steps.contains("inf"),
            "{method}/{camera}"
        );
    }
}
