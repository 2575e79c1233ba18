//! Reading MuJoCo's reference files (tests/data/mujoco_*.csv, written by
//! tools/mujoco_reference.py) and measuring the dynamic arm against them; shared by
//! tests/dynamic_reference.rs and benches/dynamic.rs, for either engine.

use eyehand::robot::{parse_urdf, ArmModel, Drive, DynamicSettings, Engine, FreeArm, Joints};

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

/// The default settings on `engine`, with time step `dt` (s).
pub fn with_dt(dt: f64, engine: Engine) -> DynamicSettings {
    DynamicSettings {
        dt,
        engine,
        ..DynamicSettings::default()
    }
}

/// At each of MuJoCo's 50 poses: the pose and the relative difference of the arm's
/// accelerations from rest (one step of `settings`, servos, limits and contacts off).
pub fn acceleration_gaps(
    model: &ArmModel,
    file: &str,
    columns: usize,
    settings: DynamicSettings,
) -> Vec<(Joints, f64)> {
    rows(file)
        .iter()
        .map(|row| {
            let q = joints(row);
            let ours = FreeArm::accelerations_at_rest(model.clone(), &q, settings)
                .expect("a pose inside the limits");
            (q, relative(&ours, &joints(&row[columns..])))
        })
        .collect()
}

/// The passive swing of the arm `model` stepped with `settings` beside MuJoCo's swing of
/// reference file `file`: at each of its rows the time (s) and the largest joint angle
/// difference (°).
pub fn swing_gaps_of(model: ArmModel, file: &str, settings: DynamicSettings) -> Vec<(f64, f64)> {
    let reference = rows(file);
    let start = joints(&reference[0][1..]);
    let dt = settings.dt;
    // MuJoCo's arm has no limits and no contacts.
    let mut arm = FreeArm::new(model, &start, settings, Drive::Passive, false, false)
        .expect("a finite start");
    reference[1..]
        .iter()
        .map(|row| {
            while arm.time() < row[0] - 0.5 * dt {
                arm.step();
            }
            (
                row[0],
                apart(&arm.joints(), &joints(&row[1..])).to_degrees(),
            )
        })
        .collect()
}

/// The OSCAR-6 variants of tests/data/held_out (written by tools/mujoco_reference.py):
/// each name and arm.
pub fn held_out_arms() -> Vec<(&'static str, ArmModel)> {
    ["heavy", "rotated", "off_axis", "damped", "everything"]
        .into_iter()
        .map(|name| {
            let file = format!("held_out/oscar6_{name}.urdf");
            let path = format!("{}/tests/data/{file}", env!("CARGO_MANIFEST_DIR"));
            let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"));
            let model = parse_urdf(&text, &file).unwrap_or_else(|e| panic!("{path}: {e}"));
            (name, model)
        })
        .collect()
}

/// The largest joint difference between `ours` and `theirs` (rad); infinite when one is
/// not finite (a maximum that skipped it would hide an arm that blew up).
fn apart(ours: &Joints, theirs: &Joints) -> f64 {
    let gaps = (*ours - *theirs)
        .iter()
        .map(|d| d.abs())
        .collect::<Vec<_>>();
    if gaps.iter().all(|d| d.is_finite()) {
        gaps.into_iter().fold(0.0, f64::max)
    } else {
        f64::INFINITY
    }
}

/// The gap of `gaps` at time `t` (s).
pub fn gap_at(gaps: &[(f64, f64)], t: f64) -> f64 {
    gaps.iter()
        .find(|(at, _)| (at - t).abs() < 1e-9)
        .map_or(f64::NAN, |(_, gap)| *gap)
}

/// How far the dynamic arm strays from MuJoCo over a servoed move.
#[derive(Debug, Clone)]
pub struct MoveGaps {
    /// The largest distance between the camera centres at any tick (mm), both placed by
    /// the model's kinematics.
    pub camera_mm: f64,
    /// The ticks each arm took to settle at the goal (ours, MuJoCo's): the first tick
    /// from which every joint stays within the settle tolerances of it.
    pub settle_ticks: (usize, usize),
    /// At each of MuJoCo's rows the time (s) and the largest joint difference (°), for
    /// [`gap_at`].
    pub over_time: Vec<(f64, f64)>,
}

impl MoveGaps {
    /// The largest joint difference at any tick (degrees).
    pub fn joints_deg(&self) -> f64 {
        self.over_time
            .iter()
            .map(|(_, gap)| *gap)
            .fold(0.0, f64::max)
    }
}

/// Move `n` of tests/data/PREFIXmoves.csv on `model` stepped with `settings`, held
/// against MuJoCo's run of it (PREFIXmove_N.csv, a row every tick).
pub fn move_gaps(model: &ArmModel, prefix: &str, n: usize, settings: DynamicSettings) -> MoveGaps {
    let (start, goal) = move_ends(prefix, n, model.dof());
    trace_gaps(
        model,
        &start,
        &goal,
        &format!("{prefix}move_{n}.csv"),
        settings,
    )
}

/// The start and goal (rad) of move `n` of tests/data/PREFIXmoves.csv, of an arm of `dof`
/// joints.
pub fn move_ends(prefix: &str, n: usize, dof: usize) -> (Joints, Joints) {
    let pose = |values: &[f64]| Joints::from_slice(&values[..dof]);
    let moves = rows(&format!("{prefix}moves.csv"));
    let row = moves
        .iter()
        .find(|row| row[0] as usize == n)
        .unwrap_or_else(|| panic!("no move {n}"));
    (pose(&row[1..]), pose(&row[1 + dof..]))
}

/// The move of `model` from `start` to `goal` stepped with `settings`, held against
/// MuJoCo's run of it in reference file `file` (a row every tick).
pub fn trace_gaps(
    model: &ArmModel,
    start: &Joints,
    goal: &Joints,
    file: &str,
    settings: DynamicSettings,
) -> MoveGaps {
    let dof = model.dof();
    let pose = |values: &[f64]| Joints::from_slice(&values[..dof]);
    let (start, goal) = (*start, *goal);
    let mut arm = FreeArm::new(
        model.clone(),
        &start,
        settings,
        Drive::MoveTo(goal),
        true,
        false,
    )
    .expect("a move inside the limits");
    let reference = rows(file);
    let settled = |q: &Joints, v: &Joints| {
        (*q - goal).amax() <= settings.settle_position_tol && v.amax() <= settings.settle_speed_tol
    };
    let (mut ours, mut theirs) = (Vec::new(), Vec::new());
    let mut camera_mm = 0.0f64;
    let mut over_time = Vec::with_capacity(reference.len());
    for (tick, row) in reference.iter().enumerate() {
        if tick > 0 {
            arm.step();
        }
        let (q, v) = (pose(&row[1..]), pose(&row[1 + dof..]));
        over_time.push((row[0], apart(&arm.joints(), &q).to_degrees()));
        let camera = model.camera_position(&arm.joints()) - model.camera_position(&q);
        camera_mm = camera_mm.max(1000.0 * camera.norm());
        ours.push(settled(&arm.joints(), &arm.speeds()));
        theirs.push(settled(&q, &v));
    }
    let settle = |flags: &[bool]| flags.iter().rposition(|s| !s).map_or(0, |last| last + 1);
    MoveGaps {
        camera_mm,
        settle_ticks: (settle(&ours), settle(&theirs)),
        over_time,
    }
}

/// The bent pose (rad) the OSCAR-6's undamped swing starts from.
pub fn oscar6_swing_start() -> Joints {
    Joints::from_slice(&[0.0, 30.0, 20.0, 0.0, 40.0, 0.0]).map(f64::to_radians)
}

/// A 20 s passive swing of `model` (undamped where its URDF is) from `start` at 5 ms on
/// `engine`, limits and contacts off: its change of total energy from start to end (J)
/// and its peak kinetic energy (J).
pub fn undamped_swing_energy(model: &ArmModel, start: &Joints, engine: Engine) -> (f64, f64) {
    let settings = with_dt(5e-3, engine);
    let mut arm = FreeArm::new(model.clone(), start, settings, Drive::Passive, false, false)
        .expect("a finite start");
    let first = arm.energy().total();
    let mut peak = 0.0f64;
    while arm.time() < 20.0 - 1e-9 {
        arm.step();
        peak = peak.max(arm.energy().kinetic);
    }
    (arm.energy().total() - first, peak)
}
