//! The dynamic arm against MuJoCo 4.0 on the same URDF (tests/data/mujoco_*.csv, written
//! by tools/mujoco_reference.py): joint accelerations from rest at 50 poses, passive swings
//! from three regular start poses, and the arm with link 2 stretched by 10 cm (holding
//! torques and accelerations).

use eyehand::robot::{ArmModel, Drive, DynamicSettings, DynamicSim, FreeArm, Joints, Simulator};

/// Accelerations agree to this, relative to the pose's largest.
const ACCELERATION_TOL: f64 = 1e-3;
/// Holding torques agree to this, relative to the pose's largest.
const TORQUE_TOL: f64 = 1e-9;
/// Passive swings stay this close (degrees) at 0.2 s and at 0.5 s.
const SWING_TOL_DEG: [(f64, f64); 2] = [(0.2, 0.1), (0.5, 1.0)];
/// Time step of the swings (s).
const SWING_DT: f64 = 1e-3;

/// Accelerations from rest are the speed after one step of 0.1 ms over the step: the
/// instant's accelerations (a 5 ms step's mean differs from them by up to 1e-3).
fn acceleration_settings() -> DynamicSettings {
    DynamicSettings {
        dt: 1e-4,
        ..DynamicSettings::default()
    }
}

/// The rows of a reference file, `#` lines skipped.
fn rows(name: &str) -> Vec<Vec<f64>> {
    let path = format!("{}/tests/data/{name}", env!("CARGO_MANIFEST_DIR"));
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"));
    text.lines()
        .filter(|line| !line.starts_with('#') && !line.trim().is_empty())
        .map(|line| {
            line.split(',')
                .map(|v| v.parse().unwrap_or_else(|e| panic!("{path}: {v}: {e}")))
                .collect()
        })
        .collect()
}

fn joints(values: &[f64]) -> Joints {
    Joints::from_column_slice(&values[..6])
}

/// The largest difference relative to the largest reference value.
fn relative(ours: &Joints, reference: &Joints) -> f64 {
    (ours - reference).amax() / reference.amax()
}

#[test]
fn accelerations_from_rest_match_mujoco_at_50_poses() {
    let reference = rows("mujoco_accelerations.csv");
    assert_eq!(reference.len(), 50);
    let mut worst = 0.0f64;
    for row in &reference {
        let q = joints(row);
        let ours = FreeArm::accelerations_at_rest(ArmModel::oscar6(), &q, acceleration_settings())
            .expect("a pose inside the limits");
        let error = relative(&ours, &joints(&row[6..]));
        assert!(
            error < ACCELERATION_TOL,
            "at {q}: {ours} vs {:?}",
            &row[6..]
        );
        worst = worst.max(error);
    }
    println!("largest relative acceleration difference: {worst:.2e}");
}

#[test]
fn passive_swings_from_regular_poses_follow_mujoco() {
    let settings = DynamicSettings {
        dt: SWING_DT,
        ..DynamicSettings::default()
    };
    for n in 1..=3 {
        let reference = rows(&format!("mujoco_swing_{n}.csv"));
        let mut arm = FreeArm::new(
            ArmModel::oscar6(),
            &joints(&reference[0][1..]),
            settings,
            Drive::Passive,
            false,
            false, // MuJoCo's arm has no contacts
        )
        .expect("a finite start");
        let mut gaps = Vec::new();
        for row in &reference[1..] {
            while arm.time() < row[0] - 0.5 * SWING_DT {
                arm.step();
            }
            let gap = (arm.joints() - joints(&row[1..])).amax().to_degrees();
            for (at, tol) in SWING_TOL_DEG {
                if (row[0] - at).abs() < 1e-9 {
                    assert!(gap < tol, "swing {n}: {gap:.3}° apart at {at} s");
                }
            }
            gaps.push((row[0], gap));
        }
        let at = |t: f64| gaps.iter().find(|g| (g.0 - t).abs() < 1e-9).map(|g| g.1);
        println!(
            "swing {n}: {:?}° apart at 0.2 s, {:?}° at 0.5 s, {:?}° at 1 s",
            at(0.2),
            at(0.5),
            at(1.0)
        );
    }
}

#[test]
fn a_stretched_link_weighs_and_swings_as_mujoco_says() {
    let reference = rows("mujoco_stretched.csv");
    let mut sim = DynamicSim::new(ArmModel::oscar6(), DynamicSettings::default());
    sim.stretch_link(2, 0.1).expect("a valid stretch");
    let mut long = ArmModel::oscar6();
    long.stretch_link(2, 0.1).expect("a valid stretch");
    for row in &reference {
        let q = joints(row);
        let torques = Joints::from(sim.holding_torques(&q));
        let error = relative(&torques, &joints(&row[6..]));
        assert!(error < TORQUE_TOL, "at {q}: {torques} vs {:?}", &row[6..12]);
        let ours = FreeArm::accelerations_at_rest(long.clone(), &q, acceleration_settings())
            .expect("a pose inside the limits");
        let error = relative(&ours, &joints(&row[12..]));
        assert!(
            error < ACCELERATION_TOL,
            "at {q}: {ours} vs {:?}",
            &row[12..]
        );
    }
}
