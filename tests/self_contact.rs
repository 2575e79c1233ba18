//! Self-contact (issue 13): a move folding the wrist onto the upper arm stops where the
//! links touch, in both simulators alike (the kinematic rule plans it; the dynamic arm
//! follows and settles there), reported and counted as a contact stop; a move into an
//! obstacle box stops on it the same way.

use eyehand::robot::{
    ArmModel, Controlled, DynamicSettings, DynamicSim, KinematicSim, MoveReport, Obstacle,
    RobotError, Simulator,
};
use nalgebra::{Point3, Vector3};

/// With the upper arm raised to θ2 = 76° the elbow folds from 90° to 170° (inside its
/// limit): the wrist comes down onto the upper arm at about 166° (lower, it would meet the
/// column first; the shared rule stops either).
fn folding() -> (Controlled, Controlled) {
    let start = Controlled::new(0.0, 76f64.to_radians(), 90f64.to_radians());
    let end = Controlled::new(0.0, 76f64.to_radians(), 170f64.to_radians());
    (start, end - start)
}

/// Runs the move from `start` by `delta` in both simulators (among `obstacles`) and checks
/// that both stop at contact, settled, with their cameras together.
fn both_stop(start: Controlled, delta: Controlled, obstacles: Vec<Obstacle>) -> [MoveReport; 2] {
    let model = ArmModel::oscar6();
    let settings = DynamicSettings::default();
    let mut kinematic =
        KinematicSim::new(model.clone(), settings.moves).with_obstacles(obstacles.clone());
    let mut dynamic = DynamicSim::new(model, settings).with_obstacles(obstacles);
    kinematic.place(&start).unwrap();
    dynamic.place(&start).unwrap();
    let reports = [kinematic.execute(&delta), dynamic.execute(&delta)];
    for (name, report) in ["kinematic", "dynamic"].iter().zip(&reports) {
        assert!(
            report.stopped_by_contact && report.settled,
            "{name}: {report:?}"
        );
        assert!(
            report.executed.norm() < 0.97 * delta.norm(),
            "{name}: {report:?}"
        );
    }
    assert_eq!(kinematic.work().contact_stops, 1);
    assert_eq!(dynamic.work().contact_stops, 1);
    let gap = (dynamic.camera_pose().translation.vector
        - kinematic.camera_pose().translation.vector)
        .norm();
    assert!(
        gap < 0.05e-3,
        "the simulators stop {:.4} mm apart",
        gap * 1e3
    );
    reports
}

#[test]
fn folding_the_wrist_onto_the_upper_arm_stops_at_contact_in_both_simulators() {
    let (start, delta) = folding();
    let [kinematic, _] = both_stop(start, delta, vec![]);
    // The elbow stopped short of 170°, where the wrist sphere meets the upper arm.
    let elbow = (start.z + kinematic.executed.z).to_degrees();
    assert!(elbow > 165.0 && elbow < 167.0, "elbow at {elbow}°");
}

#[test]
fn a_move_into_an_obstacle_stops_on_it_in_both_simulators() {
    // Lowering the camera from 30 cm to 5 cm above the base plane, straight down onto a
    // box whose top is 15 cm up.
    let model = ArmModel::oscar6();
    let above = model
        .solve_camera_position(&Point3::new(0.7, 0.0, 0.3))
        .unwrap();
    let below = model
        .solve_camera_position(&Point3::new(0.7, 0.0, 0.05))
        .unwrap();
    let block = Obstacle {
        centre: Point3::new(0.7, 0.0, 0.0),
        size: Vector3::new(0.2, 0.2, 0.3),
    };
    both_stop(above, below - above, vec![block]);
    // Nor can the arm be put inside the box: a start there is refused (and redrawn).
    let settings = DynamicSettings::default();
    let mut kinematic =
        KinematicSim::new(model.clone(), settings.moves).with_obstacles(vec![block]);
    let mut dynamic = DynamicSim::new(model, settings).with_obstacles(vec![block]);
    for sim in [&mut kinematic as &mut dyn Simulator, &mut dynamic] {
        let refused = sim.place(&below);
        assert!(
            matches!(refused, Err(RobotError::InsideObstacle { obstacle: 1, .. })),
            "{refused:?}"
        );
        assert!(sim.place(&above).is_ok());
    }
}
