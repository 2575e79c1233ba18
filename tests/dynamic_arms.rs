//! The dynamic simulator on arms other than the OSCAR-6: the Franka Panda from its real
//! URDF (meshes as convex hulls, seven joints, the fingers held) and the hand-made UR-style
//! arm hold a pose under gravity, end a move where the kinematic model ends it (as do the
//! UR5 and the xArm7 of the public collection, EYEHAND_ROBOT_DATA), and run lin5 trials;
//! the SO-100, whose velocity limits lie below robot_speed, and the OSCAR-6, whose wrist
//! follows two learned joints at once, keep every joint within its URDF velocity limit, as
//! does the xArm7's two-joint wrist passing its singularity;
//! lowering the Panda's hand (its seventh body) onto a box stops on it in both simulators.
//! (The hand touching the Panda's own links is a unit test of the contact rule,
//! robot/clearance.rs: no move that keeps the camera looking down brings it there within
//! the Panda's limits.)

use eyehand::experiment::setup::{fit_reach, load_arm};
use eyehand::experiment::{run, Config, RunOptions, Source, Sources};
use eyehand::robot::{
    ArmModel, Drive, DynamicSettings, DynamicSim, FreeArm, Joints, KinematicSim, Obstacle,
    ReachSpace, Simulator, TrapezoidProfile,
};
use nalgebra::{Point3, Vector3};
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;

#[path = "common/test_arms.rs"]
mod test_arms;

use test_arms::{PANDA, UR_STYLE};

#[path = "common/robot_data.rs"]
mod robot_data;

use robot_data::robot_data;

fn panda() -> ArmModel {
    PANDA.model()
}

fn ur_style() -> ArmModel {
    UR_STYLE.model()
}

/// The Panda without the shapes of its hand and fingers (riding with the camera on the
/// seventh body): what the contact rule saw before it checked every body.
fn panda_without_hand_shapes() -> ArmModel {
    let model = panda();
    let mut links = model.links().to_vec();
    links[model.dof() + 1].collisions.clear();
    ArmModel::from_parts(
        model.name().to_string(),
        model.joints().to_vec(),
        model.learned(),
        model.camera_mount(),
        links,
    )
    .unwrap()
}

/// The arm's fitted reach space (the default floor, 22 cm below the base plane), the arm
/// keeping to the branch of its solutions the space was fitted on.
fn reach(model: &mut ArmModel) -> ReachSpace {
    let fit = ReachSpace::fit(model, -0.22, 0.22).expect("a reach space");
    model.keep_branch(fit.branch);
    fit.space
}

/// How far (rad) any joint of `model` strays from `start`, and its camera (m), while the
/// arm runs free from `start` for `seconds` with its servos driven as `drive` says.
fn drift(model: &ArmModel, start: &Joints, drive: Drive, seconds: f64) -> (f64, f64) {
    let settings = DynamicSettings::default();
    let mut arm = FreeArm::new(model.clone(), start, settings, drive, true, true).unwrap();
    let camera = model.camera_position(start);
    let (mut joints, mut moved) = (0.0_f64, 0.0_f64);
    while arm.time() < seconds {
        arm.step();
        joints = joints.max((arm.joints() - start).amax());
        moved = moved.max((model.camera_position(&arm.joints()) - camera).norm());
    }
    (joints, moved)
}

#[test]
fn the_arms_hold_a_pose_under_gravity() {
    // At the pre-learning pose, for 5 simulated seconds: the servos with the gravity
    // feed-forward from the merged bodies hold every joint (measured: under 1e-18 rad, as
    // the OSCAR-6 holds below 1e-5 rad in 10 s); without the servos the arm falls.
    for mut model in [panda(), ur_style()] {
        let goal = reach(&mut model).prelearning_goal();
        let start = model.full_pose(&model.solve_camera_position(&goal).unwrap());
        let (joints, camera) = drift(&model, &start, Drive::Hold, 5.0);
        assert!(
            joints < 1e-6 && camera < 1e-6,
            "{}: held within {joints:.2e} rad, camera {camera:.2e} m",
            model.name()
        );
        let (fallen, _) = drift(&model, &start, Drive::Passive, 0.5);
        assert!(fallen > 0.05, "{}: fell only {fallen} rad", model.name());
    }
}

/// Eight moves of the arm of `model` to seeded targets of `space` on both simulators, the
/// dynamic one at the default settings: every move settles within the default tolerance
/// (0.0005°) where the kinematic model ends it, the cameras within 0.05 mm (the OSCAR-6's
/// contract, tests/dynamic_contract.rs), no joint beyond its URDF velocity limit.
fn eight_moves_settle(model: &ArmModel, space: &ReachSpace) {
    let mut rng = ChaCha8Rng::seed_from_u64(5);
    let settings = DynamicSettings::default();
    let mut kinematic = KinematicSim::new(model.clone(), settings.moves);
    let mut dynamic = DynamicSim::new(model.clone(), settings);
    let start = model
        .solve_camera_position(&space.prelearning_goal())
        .unwrap();
    kinematic.place(&start).unwrap();
    dynamic.place(&start).unwrap();
    let mut moves = 0;
    while moves < 8 {
        let Ok(target) = model.solve_camera_position(&space.sample(&mut rng)) else {
            continue;
        };
        let delta = target - model.controlled_of(&kinematic.joints());
        let (planned, done) = (kinematic.execute(&delta), dynamic.execute(&delta));
        assert!(done.settled, "{}: {done:?}", model.name());
        assert_eq!(planned.stopped_by_limit, done.stopped_by_limit);
        let gap = (kinematic.camera_pose().translation.vector
            - dynamic.camera_pose().translation.vector)
            .norm();
        assert!(
            gap < 0.05e-3,
            "{} move {moves}: {:.4} mm apart",
            model.name(),
            gap * 1e3
        );
        moves += 1;
    }
    let work = dynamic.work();
    assert_eq!(work.settle_timeouts, 0, "{}: {work:?}", model.name());
    assert_eq!(work.speed_faults, 0, "{}: {work:?}", model.name());
}

#[test]
fn moves_end_where_the_kinematic_model_ends_them() {
    // Measured at most 0.005 mm apart (Panda), 0.004 mm (UR-style). The UR-style arm's
    // base yaw has dry friction (0.1 N·m), which the servos feed forward.
    for mut model in [panda(), ur_style()] {
        let space = reach(&mut model);
        eight_moves_settle(&model, &space);
    }
}

#[test]
fn public_arms_settle_where_the_kinematic_model_ends_their_moves() {
    // Two arms as their makers describe them, from their URDFs alone: the UR5 (no joint
    // friction) and the xArm7, whose seven joints each have dry friction (1 N·m) and
    // damping (2–10 N·m·s/rad). Without the friction fed forward and solved with the
    // joints' equations, the xArm7's wrist stalled up to 0.5° short of its set-point.
    let robots = robot_data().join("robots");
    let config = Config::default_config();
    for urdf in [
        "ur_description/urdf/ur5_robot.urdf",
        "xarm_description/urdf/xarm7.urdf",
    ] {
        let mut model = load_arm(&config, Some(&robots.join(urdf))).unwrap().model;
        let space = fit_reach(&config, &mut model)
            .unwrap_or_else(|why| panic!("{urdf}: {why}"))
            .space;
        eight_moves_settle(&model, &space);
    }
}

#[test]
fn moves_keep_every_joint_within_its_urdf_velocity_limit() {
    // The SO-100 limits every joint to 57.3°/s (1 rad/s), below the default robot_speed of
    // 90°/s: its moves are paced to its limits, so eight of them settle with no joint
    // beyond its limit (unpaced, nearly every tick of a move was a fault).
    let robots = robot_data().join("robots");
    let config = Config::default_config();
    let so100 = robots.join("so_arm_description/urdf/so100.urdf");
    let mut model = load_arm(&config, Some(&so100)).unwrap().model;
    let space = fit_reach(&config, &mut model).unwrap().space;
    eight_moves_settle(&model, &space);
    // The OSCAR-6's θ5 keeps the camera looking down against θ2 and θ3 together (θ5 = 90° +
    // θ2 − θ3): raising θ2 by 30° while θ3 drops by 30° at 90°/s would turn it at up to
    // 147°/s, beyond its 114.6°/s.
    let model = ArmModel::oscar6();
    let settings = DynamicSettings::default();
    let start = Vector3::new(0.0, 10.0, 70.0).map(f64::to_radians);
    let delta = Vector3::new(0.0, 30.0, -30.0).map(f64::to_radians);
    let unpaced = TrapezoidProfile::new(delta.amax(), settings.moves.speed, settings.moves.accel);
    let mut kinematic = KinematicSim::new(model.clone(), settings.moves);
    let mut dynamic = DynamicSim::new(model, settings);
    kinematic.place(&start).unwrap();
    dynamic.place(&start).unwrap();
    let planned = kinematic.execute(&delta);
    let done = dynamic.execute(&delta);
    let off = (done.executed - planned.executed).amax();
    assert!(
        done.settled && off < 2.0 * settings.settle_position_tol,
        "{done:?}"
    );
    assert!(planned.duration > unpaced.duration(), "{planned:?}");
    let work = dynamic.work();
    assert_eq!(work.speed_faults, 0, "{work:?}");
}

#[test]
fn lin5_runs_on_the_dynamic_panda() {
    // 40 trials, seed 1 (about a second in the test profile): measured 1 failed trial,
    // no settle time-out, the mean distance 58.1 mm after step 1 and 2.3 mm after step 5.
    let data = tempfile::tempdir().unwrap();
    let mut config = Config::default_config();
    for (name, value) in PANDA.sets() {
        config.assign(name, &value).unwrap();
    }
    config.assign("sim", "dynamic").unwrap();
    // The study's standoff, given as a program would (the Panda's sized one is the same
    // 20 cm): the test stays on the study's value whatever the sizing gives.
    let mut sources = Sources::default();
    sources.record("standoff", Source::Program);
    config.trials = 40;
    config.seed = 1;
    config.check().unwrap();
    let options = RunOptions {
        sources,
        urdf: Some(PANDA.urdf()),
        ..RunOptions::new(config, data.path())
    };
    let summary = run(&options).unwrap().summary;
    assert_eq!(summary.sim, "dynamic");
    assert!(summary.failures <= 5, "{summary:?}");
    assert!(summary.physics_steps_per_trial > 100.0, "{summary:?}");
    assert_eq!(summary.settle_timeouts, 0, "{summary:?}");
    let [first, .., fifth] = summary.mean_distance_mm;
    let (first, fifth) = (first.unwrap(), fifth.unwrap());
    assert!(
        fifth < 0.1 * first,
        "{first} mm after step 1, {fifth} after step 5"
    );
}

#[test]
fn lowering_the_panda_hand_onto_a_box_stops_on_it_in_both_simulators() {
    // The camera looks down from the hand; the hand and its fingers below it meet the
    // box's top (15 cm up) with the camera about 26 cm up. Without the hand's shapes the
    // arm would go on until link 6 met the box, the camera 10 cm up.
    let model = panda();
    let point = |z: f64| Point3::new(0.55, 0.0, z);
    let above = model.solve_camera_position(&point(0.35)).unwrap();
    let below = model.solve_camera_position(&point(0.05)).unwrap();
    let block = vec![Obstacle {
        centre: point(0.0),
        size: Vector3::new(0.2, 0.2, 0.3),
    }];
    let settings = DynamicSettings::default();
    let mut kinematic =
        KinematicSim::new(model.clone(), settings.moves).with_obstacles(block.clone());
    let mut dynamic = DynamicSim::new(model, settings).with_obstacles(block.clone());
    let mut heights = Vec::new();
    for sim in [&mut kinematic as &mut dyn Simulator, &mut dynamic] {
        sim.place(&above).unwrap();
        let report = sim.execute(&(below - above));
        assert!(report.stopped_by_contact && report.settled, "{report:?}");
        assert_eq!(sim.work().contact_stops, 1);
        heights.push(sim.camera_pose().translation.vector.z);
    }
    let mut bare =
        KinematicSim::new(panda_without_hand_shapes(), settings.moves).with_obstacles(block);
    bare.place(&above).unwrap();
    bare.execute(&(below - above));
    let bare_height = bare.camera_pose().translation.vector.z;
    assert!((heights[0] - heights[1]).abs() < 0.05e-3, "{heights:?}");
    assert!(
        heights[0] > bare_height + 0.1,
        "{heights:?} against {bare_height}"
    );
}

#[test]
fn the_xarm7_wrist_passes_its_singularity_within_its_velocity_limits() {
    // The xArm7's joint 6 passes 0 where its forearm points straight down (θ2 close to θ4
    // here, joint 3 held at 0): joints 5 and 6 then tilt the camera the same way, and the
    // URDF's rounded rpy (1.5708 for π/2) leaves the arm a hair off planar. Solved exactly,
    // joint 5 whirls by up to 180° within a few ticks of such a move or hops between its
    // two solutions (these four moves: 2 speed faults, joint 5 at 227°/s against its
    // 180°/s); near the singularity the wrist leaves the tilt across it (under 1e-4 rad)
    // and joint 5 stays put.
    let robots = robot_data().join("robots");
    let config = Config::default_config();
    let urdf = robots.join("xarm_description/urdf/xarm7.urdf");
    let model = load_arm(&config, Some(&urdf)).unwrap().model;
    let settings = DynamicSettings::default();
    let mut kinematic = KinematicSim::new(model.clone(), settings.moves);
    let mut dynamic = DynamicSim::new(model.clone(), settings);
    let deg = |x: f64, y: f64, z: f64| Vector3::new(x, y, z).map(f64::to_radians);
    let start = deg(78.0, 26.2, 27.0);
    kinematic.place(&start).unwrap();
    dynamic.place(&start).unwrap();
    // Across θ2 = θ4 and back, at different base yaws.
    for delta in [
        deg(1.6, 0.02, -1.5),
        deg(-20.0, 5.0, 12.0),
        deg(10.0, -3.0, -15.0),
        deg(-30.0, 3.0, 14.0),
    ] {
        let (planned, done) = (kinematic.execute(&delta), dynamic.execute(&delta));
        assert!(done.settled, "{done:?}");
        let off = (kinematic.joints() - dynamic.joints()).amax();
        assert!(
            off < 2.0 * settings.settle_position_tol,
            "{planned:?} {done:?}"
        );
        let optical = kinematic.camera_pose().rotation * Vector3::z();
        assert!(optical.z < -(1.0 - 0.5e-8), "tilted: {optical}");
    }
    let work = dynamic.work();
    assert_eq!(work.speed_faults, 0, "{work:?}");
}
