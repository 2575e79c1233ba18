//! The dynamic arm against MuJoCo 4.0 on the same URDF (tests/data/mujoco_*.csv, written
//! by tools/mujoco_reference.py): joint accelerations from rest at 50 poses, passive swings
//! from three regular start poses, servoed moves (MuJoCo driven by eyehand's servo law),
//! and the arm with link 2 stretched by 10 cm (holding torques and accelerations).

mod mujoco;
#[path = "common/test_arms.rs"]
mod test_arms;

use eyehand::robot::{ArmModel, DynamicSettings, DynamicSim, Simulator};
use mujoco::{
    acceleration_gaps, gap_at, held_out_arms, joints, move_gaps, relative, rows, swing_gaps,
    swing_gaps_of,
};
use test_arms::PANDA;

/// Accelerations agree to this, relative to the pose's largest.
const ACCELERATION_TOL: f64 = 1e-3;
/// Accelerations from rest are the speed after one step of 0.1 ms over the step: the
/// instant's accelerations (with 2 solver iterations a 5 ms step's mean differs from them
/// by up to 1.3e-3; with the default 1 it does not).
const ACCELERATION_DT: f64 = 1e-4;
/// Holding torques agree to this, relative to the pose's largest.
const TORQUE_TOL: f64 = 1e-9;
/// Passive swings stay this close (degrees) at 0.2 s, 0.5 s and 1 s at the runs' own
/// settings (a 5 ms tick): the issue asked for 0.1° and 1° at 0.2 and 0.5 s; the
/// fourth-order steps give 2e-6°, 3e-4° and under 0.01° (docs/DYNAMIC.md).
const SWING_TOL_DEG: [(f64, f64); 3] = [(0.2, 1e-3), (0.5, 1e-2), (1.0, 0.05)];

#[test]
fn accelerations_from_rest_match_mujoco_at_50_poses() {
    let gaps = acceleration_gaps(
        &ArmModel::oscar6(),
        "mujoco_accelerations.csv",
        6,
        ACCELERATION_DT,
    );
    assert_eq!(gaps.len(), 50);
    for (q, gap) in gaps {
        assert!(gap < ACCELERATION_TOL, "at {q}: {gap:.2e} relative");
    }
}

#[test]
fn passive_swings_from_regular_poses_follow_mujoco() {
    // Swing 1 from the zero pose, 2 and 3 from bent poses (see tools/mujoco_reference.py);
    // all three stay regular for 0.5 s.
    for n in 1..=3 {
        let settings = DynamicSettings::default();
        let gaps = swing_gaps(n, settings);
        for (at, tol) in SWING_TOL_DEG {
            let gap = gap_at(&gaps, at);
            assert!(gap < tol, "swing {n}: {gap:.3}° apart at {at} s");
        }
    }
}

/// Servoed moves stay this close to MuJoCo's run of the same servo law (degrees, mm).
const MOVE_TOL: (f64, f64) = (0.01, 0.1);
/// Each move's settle time is this close to MuJoCo's (ticks). Move 3 ends on a joint's
/// limit (the OSCAR-6's joint 3, the Panda's joint 4), where eyehand's arm stops (a hard
/// stop) and MuJoCo's, run without limits (its limits are soft constraints, not a stop),
/// overshoots: on the OSCAR-6 by 1.0e-5 rad, past the settle tolerance (8.7e-6 rad), and
/// comes back two ticks later (the goal of one tick is missed there; with MuJoCo's
/// limits on and stiff, four).
const SETTLE_TICKS: [usize; 3] = [1, 1, 2];

#[test]
fn passive_swings_of_held_out_arms_follow_mujoco() {
    // Masses ×1.3, a rotated tensor with a repeated moment, centres of mass off the axis,
    // joint damping, and all of them (tools/mujoco_reference.py).
    for (name, model) in held_out_arms() {
        let file = format!("held_out/mujoco_swing_{name}.csv");
        let gaps = swing_gaps_of(model, &file, DynamicSettings::default());
        for (at, tol) in SWING_TOL_DEG {
            let gap = gap_at(&gaps, at);
            assert!(gap < tol, "{name}: {gap:.3e}° apart at {at} s");
        }
    }
}

#[test]
fn servoed_moves_follow_mujoco_driven_by_the_same_servo_law() {
    // Small, large, and onto joint 3's upper limit (tools/mujoco_reference.py).
    let arms = [
        (ArmModel::oscar6(), "mujoco_"),
        (PANDA.model(), "mujoco_panda_"),
    ];
    for (model, prefix) in arms {
        for (n, settle) in (1..=3).zip(SETTLE_TICKS) {
            let gaps = move_gaps(&model, prefix, n);
            assert!(gaps.joints_deg < MOVE_TOL.0, "{prefix} move {n}: {gaps:?}");
            assert!(gaps.camera_mm < MOVE_TOL.1, "{prefix} move {n}: {gaps:?}");
            let (ours, theirs) = gaps.settle_ticks;
            assert!(
                ours.abs_diff(theirs) <= settle,
                "{prefix} move {n}: {gaps:?}"
            );
            assert!(ours > 10, "{prefix} move {n} moved: {gaps:?}");
        }
    }
}

#[test]
fn a_stretched_link_weighs_and_swings_as_mujoco_says() {
    let mut sim = DynamicSim::new(ArmModel::oscar6(), DynamicSettings::default());
    sim.stretch_link(2, 0.1).expect("a valid stretch");
    for row in rows("mujoco_stretched.csv") {
        let q = joints(&row);
        let torques = sim.holding_torques(&q);
        let error = relative(&torques, &joints(&row[6..]));
        assert!(error < TORQUE_TOL, "at {q}: {torques} vs {:?}", &row[6..12]);
    }
    let mut long = ArmModel::oscar6();
    long.stretch_link(2, 0.1).expect("a valid stretch");
    for (q, gap) in acceleration_gaps(&long, "mujoco_stretched.csv", 12, ACCELERATION_DT) {
        assert!(gap < ACCELERATION_TOL, "at {q}: {gap:.2e} relative");
    }
}
