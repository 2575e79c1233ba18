//! The world around the arm: a move that would take the camera or a link below the floor
//! stops there in both simulators alike (reported and counted as a contact stop), a
//! free-falling arm lands on the floor, an arm driven into its base stops there with every
//! joint within its URDF velocity limit (on both dynamic engines), and the dynamic entries
//! refuse absurd values.

use eyehand::experiment::Config;
use eyehand::robot::{
    ArmModel, Controlled, Drive, DynamicSettings, DynamicSim, Engine, FreeArm, Joints,
    KinematicSim, Simulator, DEFAULT_FLOOR_Z,
};

/// θ2 = −30°, θ3 = 20° (inside the limits) puts the camera 27 cm below the base plane.
fn into_the_floor() -> (Controlled, Controlled) {
    let start = Controlled::new(0.0, 20f64.to_radians(), 90f64.to_radians());
    let goal = Controlled::new(0.0, (-30f64).to_radians(), 20f64.to_radians());
    (start, goal - start)
}

#[test]
fn a_move_into_the_floor_stops_on_it_in_both_simulators() {
    let model = ArmModel::oscar6();
    let settings = DynamicSettings::default();
    let (start, delta) = into_the_floor();
    let mut kinematic = KinematicSim::new(model.clone(), settings.moves);
    kinematic.place(&start).expect("inside the limits");
    let report = kinematic.execute(&delta);
    assert!(report.stopped_by_contact, "{report:?}");
    assert!(report.executed.norm() < delta.norm() * 0.99, "{report:?}");
    assert_eq!(kinematic.work().contact_stops, 1);
    // Without the floor the same move goes all the way, the camera 27 cm down.
    let mut no_floor =
        KinematicSim::new(model.clone(), settings.moves.with_floor(f64::NEG_INFINITY));
    no_floor.place(&start).expect("inside the limits");
    assert!(!no_floor.execute(&delta).stopped_by_contact);
    assert!(no_floor.camera_pose().translation.z < -0.26);

    for engine in Engine::ALL {
        let settings = DynamicSettings { engine, ..settings };
        let mut dynamic = DynamicSim::new(model.clone(), settings);
        dynamic.place(&start).expect("inside the limits");
        let moved = dynamic.execute(&delta);
        assert!(
            moved.stopped_by_contact && moved.settled,
            "{engine:?}: {moved:?}"
        );
        let gap = (dynamic.camera_pose().translation.vector
            - kinematic.camera_pose().translation.vector)
            .norm();
        assert!(
            gap < 0.05e-3,
            "{engine:?}: the simulators stop {:.3} mm apart",
            gap * 1e3
        );
        assert_eq!(dynamic.work().contact_stops, 1);
        // The arm stopped with its lowest point on the floor, within a micrometre of it
        // (the servo holds the set-point the plan stopped on the floor; the contact's
        // solver lets a shallower touch be).
        let camera_z = dynamic.camera_pose().translation.z;
        assert!(
            (camera_z - DEFAULT_FLOOR_Z).abs() < 1e-6,
            "{engine:?}: camera at {camera_z} m"
        );
    }
}

#[test]
fn a_move_along_the_floor_away_from_it_is_not_stopped() {
    let model = ArmModel::oscar6();
    let mut kinematic = KinematicSim::new(model, DynamicSettings::default().moves);
    let (start, delta) = into_the_floor();
    kinematic.place(&start).expect("inside the limits");
    let down = kinematic.execute(&delta);
    let back = kinematic.execute(&-down.executed);
    assert!(!back.stopped_by_contact, "{back:?}");
    assert!((back.executed + down.executed).norm() < 1e-12);
}

/// The floor stops a falling arm within this (m) of it.
const LANDING_TOL: f64 = 1e-3;

#[test]
fn a_falling_arm_lands_on_the_floor() {
    let model = ArmModel::oscar6();
    let start = Joints::zeros(6);
    for (engine, contacts) in [
        (Engine::Rk4, true),
        (Engine::Rapier, true),
        (Engine::Rk4, false),
    ] {
        let settings = DynamicSettings {
            dt: 1e-3,
            engine,
            ..DynamicSettings::default()
        };
        let mut arm = FreeArm::new(
            model.clone(),
            &start,
            settings,
            Drive::Passive,
            false,
            contacts,
        )
        .expect("a finite start");
        let mut lowest = f64::INFINITY;
        for _ in 0..1000 {
            arm.step();
            lowest = lowest.min(model.camera_position(&arm.joints()).z);
        }
        if contacts {
            assert!(
                lowest > DEFAULT_FLOOR_Z - LANDING_TOL,
                "{engine:?}: camera sank to {lowest} m"
            );
        } else {
            assert!(
                lowest < DEFAULT_FLOOR_Z - 0.1,
                "camera fell only to {lowest} m"
            );
        }
    }
}

#[test]
fn an_arm_driven_into_its_base_stops_there_every_joint_within_its_velocity_limit() {
    // `simulate --from 0,30,90,0,30,0 --to 0,-29,160,0,30,0 --duration 3`: at about 0.69 s
    // the camera strikes the base at full speed. The contact holds the arm back from its
    // set-point, which stops the move there (within the tick of the strike), and the
    // servos hold the arm where it is: no joint turns faster than its URDF velocity limit
    // on either engine (servos pushing on toward a set-point inside the base used to whip
    // the wrist, joint 5, to 22.6 rad/s against its 2 rad/s), and the arm comes to rest.
    let deg = |v: [f64; 6]| Joints::from_slice(&v).map(f64::to_radians);
    let start = deg([0.0, 30.0, 90.0, 0.0, 30.0, 0.0]);
    let goal = deg([0.0, -29.0, 160.0, 0.0, 30.0, 0.0]);
    let model = ArmModel::oscar6();
    for engine in Engine::ALL {
        let settings = DynamicSettings {
            engine,
            ..DynamicSettings::default()
        };
        let mut arm = FreeArm::new(
            model.clone(),
            &start,
            settings,
            Drive::MoveTo(goal),
            true,
            true,
        )
        .expect("a move inside the limits");
        let mut fastest = 0.0f64;
        while arm.time() < 3.0 - 1e-9 {
            arm.step();
            let share = arm
                .speeds()
                .iter()
                .zip(model.joints())
                .map(|(v, joint)| v.abs() / joint.velocity)
                .fold(0.0, f64::max);
            fastest = fastest.max(share);
        }
        let stopped = arm.stopped_by_contact();
        assert!(
            stopped.is_some_and(|t| t > 0.6 && t < 0.75),
            "{engine:?}: {stopped:?}"
        );
        let (faults, worst) = arm.speed_faults();
        assert_eq!(faults, 0, "{engine:?}: {worst:?}");
        assert!(
            fastest < 1.0,
            "{engine:?}: a joint at {:.2} of its limit",
            fastest
        );
        assert!(
            arm.speeds().amax() < 1e-3,
            "{engine:?}: at rest, {}",
            arm.speeds()
        );
    }
}

#[test]
fn absurd_dynamic_entries_are_refused_before_any_work() {
    let base = Config::default_config().to_text();
    for (entry, value, words) in [
        ("dt", "1e-300", "dt: must be 0.00001 to 0.1 s"),
        (
            "solver_iterations",
            "0",
            "solver_iterations: must be 1 to 100",
        ),
        (
            "motor_stiffness",
            "1e300",
            "motor_stiffness: must be above 0",
        ),
        ("settle_timeout", "1e9", "settle_timeout: must be"),
        ("floor_z", "50", "floor_z: must be -1000 to 0"),
    ] {
        let text = base
            .lines()
            .map(|line| match line.split_whitespace().next() {
                Some(name) if name == entry => format!("{entry} {value}"),
                _ => line.to_string(),
            })
            .collect::<Vec<_>>()
            .join("\n");
        let error = Config::parse(&text, "test.conf")
            .expect_err(entry)
            .to_string();
        assert!(error.contains(words), "{entry} {value}: {error}");
    }
}
