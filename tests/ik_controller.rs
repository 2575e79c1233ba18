//! The `ik` reference controller: exact on the nominal robot, measurably off once the robot
//! is no longer as modelled.

use eyehand::camera::{CameraModel, ProjectionCamera};
use eyehand::control::{SensorNoise, TrialLoop, TrialSettings};
use eyehand::learn::{IkLearner, Learner};
use eyehand::robot::{ArmModel, KinematicSim, MoveSettings};

const EPSILON_MM: f64 = 0.5;

fn trial_loop(seed: u64) -> TrialLoop {
    let sim = KinematicSim::new(ArmModel::oscar6(), MoveSettings::from_degrees(90.0, 180.0));
    let settings = TrialSettings {
        feedback_steps: 10,
        min_feedback_steps: 5,
        epsilon: EPSILON_MM / 1000.0,
        noise: SensorNoise::default(),
        timing: Default::default(),
        move_frames: None,
    };
    TrialLoop::new(
        Box::new(sim),
        Box::new(ProjectionCamera::new(CameraModel::default())),
        settings,
        seed,
    )
}

/// Distances after step 1 over `trials` trials.
fn first_steps(trials: &mut TrialLoop, learner: &mut dyn Learner, n: usize) -> Vec<f64> {
    (0..n)
        .map(|_| {
            let outcome = trials.run_trial(learner).unwrap();
            assert_eq!(outcome.failure, None);
            outcome.distances_mm[0]
        })
        .collect()
}

#[test]
fn ik_reaches_the_target_in_one_step_on_the_nominal_robot() {
    let mut trials = trial_loop(3);
    let mut ik = IkLearner::new(ArmModel::oscar6(), CameraModel::default());
    let distances = first_steps(&mut trials, &mut ik, 1000);
    let worst = distances.iter().cloned().fold(0.0, f64::max);
    assert!(worst < EPSILON_MM, "worst first step {worst} mm");
    assert!(worst < 1e-6, "the model is exact: worst {worst} mm");
}

#[test]
fn ik_misses_after_link_2_is_stretched() {
    let mut trials = trial_loop(4);
    trials.sim_mut().stretch_link(2, 0.10).unwrap();
    let mut ik = IkLearner::new(ArmModel::oscar6(), CameraModel::default());
    let distances = first_steps(&mut trials, &mut ik, 300);
    let missed = distances.iter().filter(|&&d| d > EPSILON_MM).count();
    let mean = distances.iter().sum::<f64>() / distances.len() as f64;
    println!(
        "after link 2 +10 cm: mean first-step distance {mean:.2} mm, {missed}/300 trials miss ε"
    );
    assert!(missed > 290, "{missed} of 300 first steps miss ε");
    assert!(mean > 10.0, "mean first-step miss {mean} mm");
}

#[test]
fn ik_misses_after_the_camera_is_turned() {
    let mut trials = trial_loop(5);
    trials.sim_mut().rotate_camera(30f64.to_radians());
    let mut ik = IkLearner::new(ArmModel::oscar6(), CameraModel::default());
    let distances: Vec<f64> = (0..300)
        .filter_map(|_| {
            trials
                .run_trial(&mut ik)
                .unwrap()
                .distances_mm
                .first()
                .copied()
        })
        .collect();
    let mean = distances.iter().sum::<f64>() / distances.len() as f64;
    println!("after a 30° camera turn: mean first-step distance {mean:.2} mm");
    assert!(mean > 10.0, "mean first-step miss {mean} mm");
}
