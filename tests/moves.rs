//! Moves of the kinematic simulator: joint limits stop them, nothing makes them panic.

use eyehand::robot::{ArmModel, Controlled, KinematicSim, MoveSettings, Simulator};
use proptest::prelude::*;

fn sim_at(t1: f64, t2: f64, t3: f64) -> KinematicSim {
    let mut sim = KinematicSim::new(ArmModel::oscar6(), MoveSettings::from_degrees(90.0, 180.0));
    sim.place(&Controlled::new(t1, t2, t3).map(f64::to_radians))
        .unwrap();
    sim
}

#[test]
fn a_move_past_a_joint_limit_stops_at_it() {
    let mut sim = sim_at(0.0, 30.0, 90.0);
    let upper = sim.model().joints()[1].upper;
    let report = sim.execute(&Controlled::new(0.1, 2.0, 0.0));
    assert_eq!(report.stopped_by_limit, Some(1));
    let q = sim.joints();
    assert!((q[1] - upper).abs() < 1e-12, "θ2 stops on its limit");
    let fraction = (upper - 30f64.to_radians()) / 2.0;
    assert!(
        (q[0] - 0.1 * fraction).abs() < 1e-12,
        "θ1 stops at the same point of the line"
    );
    // Pushing further into the limit does nothing; moving away works.
    let again = sim.execute(&Controlled::new(0.0, 0.5, 0.0));
    assert_eq!(again.executed, Controlled::zeros());
    let back = sim.execute(&Controlled::new(0.0, -0.5, 0.0));
    assert_eq!(back.stopped_by_limit, None);
    assert!((sim.joints()[1] - (upper - 0.5)).abs() < 1e-12);
}

#[test]
fn the_wrist_limit_stops_a_move_too() {
    // θ5 = 90° + θ2 − θ3 reaches its +120° limit before θ2 or θ3 reach theirs.
    let mut sim = sim_at(0.0, 60.0, 40.0);
    let report = sim.execute(&Controlled::new(0.0, 0.0, -50f64.to_radians()));
    assert_eq!(report.stopped_by_limit, Some(4));
    let wrist = sim.model().joints()[4].clone();
    assert!((sim.joints()[4] - wrist.upper).abs() < 1e-9);
}

#[test]
fn a_move_lasts_as_the_trapezoid_says() {
    let mut sim = sim_at(0.0, 30.0, 90.0);
    // 90°: 0.5 s ramps of 22.5° each at 180°/s², 45° cruise at 90°/s: 1.5 s.
    let report = sim.execute(&Controlled::new(0.0, 0.0, 90f64.to_radians()).map(|v| -v * 0.5));
    assert!(report.settled);
    let small = sim.execute(&Controlled::new(90f64.to_radians(), 0.0, 0.0));
    assert!((small.duration - 1.5).abs() < 1e-9, "{}", small.duration);
    assert!(report.duration < small.duration);
}

proptest! {
    #[test]
    fn no_command_makes_a_move_panic_or_leave_the_limits(
        d1 in prop_oneof![any::<f64>(), -10.0f64..10.0],
        d2 in prop_oneof![any::<f64>(), -10.0f64..10.0],
        d3 in prop_oneof![any::<f64>(), -10.0f64..10.0],
    ) {
        let mut sim = sim_at(10.0, 30.0, 90.0);
        let report = sim.execute(&Controlled::new(d1, d2, d3));
        let q = sim.joints();
        prop_assert!(q.iter().all(|v| v.is_finite()));
        prop_assert!(sim.model().violated_limit(&q).is_none());
        if !(d1.is_finite() && d2.is_finite() && d3.is_finite()) {
            prop_assert_eq!(report.executed, Controlled::zeros());
        }
    }
}
