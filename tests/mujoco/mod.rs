//! Reading MuJoCo's reference files (tests/data/mujoco_*.csv, written by
//! tools/mujoco_reference.py) and measuring the dynamic arm against them; shared by
//! tests/dynamic_reference.rs and benches/dynamic.rs.

use eyehand::robot::{ArmModel, Drive, DynamicSettings, FreeArm, Joints};

/// The rows of a reference file, `#` lines skipped.
pub fn rows(name: &str) -> Vec<Vec<f64>> {
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

/// Six values from the start of `values`.
pub fn joints(values: &[f64]) -> Joints {
    Joints::from_slice(&values[..6])
}

/// The largest difference relative to the largest reference value.
pub fn relative(ours: &Joints, reference: &Joints) -> f64 {
    (*ours - reference).amax() / reference.amax()
}

/// Settings with time step `dt` (s).
pub fn with_dt(dt: f64) -> DynamicSettings {
    DynamicSettings {
        dt,
        ..DynamicSettings::default()
    }
}

/// At each of MuJoCo's 50 poses: the pose and the relative difference of the arm's
/// accelerations from rest (one step of `dt`, servos, limits and contacts off).
pub fn acceleration_gaps(
    model: &ArmModel,
    file: &str,
    columns: usize,
    dt: f64,
) -> Vec<(Joints, f64)> {
    rows(file)
        .iter()
        .map(|row| {
            let q = joints(row);
            let ours = FreeArm::accelerations_at_rest(model.clone(), &q, with_dt(dt))
                .expect("a pose inside the limits");
            (q, relative(&ours, &joints(&row[columns..])))
        })
        .collect()
}

/// Passive swing `n` (1–3) stepped with `settings` beside MuJoCo's: at each of its rows
/// the time (s) and the largest joint angle difference (°).
pub fn swing_gaps(n: usize, settings: DynamicSettings) -> Vec<(f64, f64)> {
    let reference = rows(&format!("mujoco_swing_{n}.csv"));
    let start = joints(&reference[0][1..]);
    let dt = settings.dt;
    // MuJoCo's arm has no limits and no contacts.
    let mut arm = FreeArm::new(
        ArmModel::oscar6(),
        &start,
        settings,
        Drive::Passive,
        false,
        false,
    )
    .expect("a finite start");
    reference[1..]
        .iter()
        .map(|row| {
            while arm.time() < row[0] - 0.5 * dt {
                arm.step();
            }
            (
                row[0],
                (arm.joints() - joints(&row[1..])).amax().to_degrees(),
            )
        })
        .collect()
}

/// The gap of `gaps` at time `t` (s).
pub fn gap_at(gaps: &[(f64, f64)], t: f64) -> f64 {
    gaps.iter()
        .find(|(at, _)| (at - t).abs() < 1e-9)
        .map_or(f64::NAN, |(_, gap)| *gap)
}
