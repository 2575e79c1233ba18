//! The camera's clock on the dynamic simulator: a frame with latency shows the arm as it
//! was that long before it arrives, continuous servoing takes `ik` to ε, and the same seed
//! gives the same figures with noise and latency; a continuous goal past a joint limit or
//! into the floor stops the arm there, as a step move would.

use eyehand::camera::{CameraModel, ProjectionCamera};
use eyehand::control::{CameraTiming, SensorNoise, ServoMode, TrialLoop, TrialSettings};
use eyehand::learn::{IkLearner, Learner};
use eyehand::robot::{
    ArmModel, Controlled, DynamicSettings, DynamicSim, Joints, KinematicSim, Simulator,
    DEFAULT_FLOOR_Z,
};

const EPSILON_MM: f64 = 0.5;
const DT: f64 = 0.005;

fn continuous_loop(latency: f64, noise: SensorNoise, seed: u64) -> TrialLoop {
    let sim = DynamicSim::new(ArmModel::oscar6(), DynamicSettings::default());
    let settings = TrialSettings {
        feedback_steps: 150,
        min_feedback_steps: 1,
        epsilon: EPSILON_MM / 1000.0,
        noise,
        timing: CameraTiming {
            fps: 30.0,
            latency,
            servo: ServoMode::Continuous,
        },
        move_frames: None,
    };
    TrialLoop::new(
        Box::new(sim),
        Box::new(ProjectionCamera::new(CameraModel::default())),
        settings,
        seed,
    )
}

fn ik() -> IkLearner {
    IkLearner::new(ArmModel::oscar6(), CameraModel::default())
}

fn controlled_deg(q: &Joints) -> [f64; 3] {
    [q[0], q[1], q[2]].map(f64::to_degrees)
}

#[test]
fn a_frame_with_latency_shows_the_pose_of_latency_ago() {
    let latency_ticks = 10;
    let mut trials = continuous_loop(latency_ticks as f64 * DT, SensorNoise::default(), 5);
    let mut ik = ik();
    let mut here = trials.begin_trial().unwrap();
    let start = here.theta_deg;
    trials.sim_mut().keep_ticks(true);
    let mut ticks: Vec<Joints> = Vec::new();
    trials.sim_mut().drain_ticks(&mut Vec::new());
    let (mut checked, mut stale) = (0, 0);
    loop {
        let report = trials.step_trial(&ik.propose(&here.query())).unwrap();
        trials.sim_mut().drain_ticks(&mut ticks);
        let now = (report.seconds / DT).round() as usize;
        assert_eq!(
            now,
            ticks.len(),
            "one kept tick per tick since the first frame"
        );
        here = *trials.path().last().unwrap();
        let shown: [f64; 3] = here.theta_deg.into();
        let taken = now as i64 - latency_ticks;
        let then = if taken <= 0 {
            start.into()
        } else {
            controlled_deg(&ticks[taken as usize - 1])
        };
        assert_eq!(shown, then, "frame {} shows tick {taken}", report.step);
        let moved = (0..3).any(|i| (controlled_deg(&ticks[now - 1])[i] - shown[i]).abs() > 0.1);
        stale += usize::from(moved);
        checked += 1;
        if report.end.is_some() {
            break;
        }
    }
    assert!(
        checked > 10 && stale > 5,
        "{checked} frames, {stale} of a moving arm"
    );
}

#[test]
fn continuous_servoing_takes_ik_to_epsilon_on_the_dynamic_simulator() {
    let mut trials = continuous_loop(0.05, SensorNoise::default(), 11);
    let mut ik = ik();
    for _ in 0..5 {
        let outcome = trials.run_trial(&mut ik).unwrap();
        assert_eq!(outcome.failure, None);
        assert!(outcome.reached, "{outcome:?}");
        let last = *outcome.distances_mm.last().unwrap();
        assert!(last <= EPSILON_MM, "ended {last} mm away");
        let frames = outcome.distances_mm.len() as f64;
        assert!(
            (outcome.seconds - frames / 30.0).abs() < 2.0 * DT,
            "{outcome:?}"
        );
        assert_eq!(trials.path().len(), outcome.distances_mm.len() + 1);
    }
}

#[test]
fn the_same_seed_gives_the_same_figures_with_noise_and_latency() {
    let noise = SensorNoise {
        centroid_px: 0.25,
        area_relative: 0.02,
        joint_deg: 0.01,
    };
    let run = || {
        let mut trials = continuous_loop(0.05, noise, 3);
        let mut ik = ik();
        (0..3)
            .map(|_| {
                let outcome = trials.run_trial(&mut ik).unwrap();
                (outcome, trials.path().to_vec())
            })
            .collect::<Vec<_>>()
    };
    let (first, second) = (run(), run());
    let bits = |runs: &[(
        eyehand::control::TrialOutcome,
        Vec<eyehand::learn::Observation>,
    )]| {
        runs.iter()
            .flat_map(|(outcome, path)| {
                let poses = path
                    .iter()
                    .flat_map(|o| o.theta_deg.iter().chain(o.c.iter()));
                outcome
                    .distances_mm
                    .iter()
                    .chain([outcome.seconds].iter())
                    .chain(poses)
                    .map(|v| v.to_bits())
                    .collect::<Vec<_>>()
            })
            .collect::<Vec<u64>>()
    };
    assert_eq!(bits(&first), bits(&second));
    assert!(first.iter().all(|(outcome, _)| outcome.reached));
}

/// Servo ticks toward `goal` from `start` until the arm has had two seconds to get there.
fn servo_to(start: &Controlled, goal: &Controlled) -> DynamicSim {
    let mut sim = DynamicSim::new(ArmModel::oscar6(), DynamicSettings::default());
    sim.place(start).expect("inside the limits");
    sim.servo_toward(goal);
    for _ in 0..400 {
        sim.servo_tick();
    }
    sim
}

#[test]
fn a_continuous_goal_past_a_joint_limit_stops_the_arm_where_a_step_move_stops() {
    let start = Controlled::new(0.0, 20f64.to_radians(), 90f64.to_radians());
    let upper = ArmModel::oscar6().joints()[1].upper;
    let goal = Controlled::new(0.3, upper + 0.5, 90f64.to_radians());
    let sim = servo_to(&start, &goal);
    let mut step = KinematicSim::new(ArmModel::oscar6(), DynamicSettings::default().moves);
    step.place(&start).expect("inside the limits");
    assert_eq!(step.execute(&(goal - start)).stopped_by_limit, Some(1));
    let (q, want) = (sim.joints(), step.joints());
    assert!((q[1] - upper).abs() < 1e-4, "θ2 {} against {upper}", q[1]);
    for i in 0..3 {
        assert!(
            (q[i] - want[i]).abs() < 1e-4,
            "θ{} {} against {}",
            i + 1,
            q[i],
            want[i]
        );
    }
}

#[test]
fn a_continuous_goal_into_the_floor_stops_on_it() {
    let start = Controlled::new(0.0, 20f64.to_radians(), 90f64.to_radians());
    let sim = servo_to(
        &start,
        &Controlled::new(0.0, (-30f64).to_radians(), 20f64.to_radians()),
    );
    assert!(sim.work().contact_stops >= 1, "{:?}", sim.work());
    // On the floor or above it (to rounding: the servos hold the arm where the set-point,
    // stopped on the floor, put it).
    let camera_z = sim.camera_pose().translation.z;
    assert!(camera_z > DEFAULT_FLOOR_Z - 1e-12, "camera at {camera_z} m");
    assert_eq!(sim.work().moves, 0, "no step move was made");
}
