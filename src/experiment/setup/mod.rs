//! Setting a run up: the one place where a [`Config`] becomes the simulator, the camera,
//! the learner and the trial loop's settings.

mod arm;
pub(super) mod events;
mod learners;
mod mounts_tried;
mod other_mount;
pub(super) mod preflight;
pub(super) mod run_request;
pub(super) mod run_setup;
mod sizing;
pub(super) mod start_check;

pub use arm::{
    arm_entry, arm_settings, fit_reach, fitted_boundaries, learned_ranges, load_arm,
    load_description, reach_space, LoadedArm, BOUNDARY_MARGIN_DEG,
};
pub use learners::{
    broyden_settings, ffn_settings, input_bounds, issgp_settings, kohonen_settings, lin5_settings,
    lin8_settings, lwpr_settings, mlp_settings, nnw_settings, pattern_settings,
    single_model_watch_settings,
};
pub use mounts_tried::NoOtherMount;
pub use other_mount::{proposed_mount, refused_where_it_looks, refuses_where_it_looks, OtherMount};
pub use sizing::{
    size_readings_to_arm, size_standoff_to_arm, sized_standoff_cm, FULL_STANDOFF_HEIGHT_CM,
    MIN_SIZED_STANDOFF_CM,
};

use super::{CameraKind, Config, ObstacleBox, SimKind};
use crate::camera::{Camera, CameraModel, ProjectionCamera, RaycastCamera};
use crate::control::{CameraTiming, MoveFrames, SensorNoise, TrialSettings};
use crate::learn::change::{SingleModel, WatchedLearner};
use crate::learn::{
    Broyden, FfnLearner, IkLearner, Issgp, KohonenLearner, LearnError, Learner, Lin5, Lin8, Lwpr,
    Method, Mlp, Nnw,
};
use crate::robot::{
    ArmModel, DynamicSettings, DynamicSim, KinematicSim, MoveSettings, Obstacle, Simulator,
};
use crate::units::M_PER_CM;
use std::path::Path;

/// The simulator the config names, moving `model` among the config's obstacles.
pub fn build_simulator(config: &Config, model: ArmModel) -> Box<dyn Simulator> {
    let obstacles = obstacles(config);
    match config.sim {
        SimKind::Kinematic => {
            Box::new(KinematicSim::new(model, move_settings(config)).with_obstacles(obstacles))
        }
        SimKind::Dynamic => {
            Box::new(DynamicSim::new(model, dynamic_settings(config)).with_obstacles(obstacles))
        }
    }
}

/// The `obstacle` boxes (m).
pub fn obstacles(config: &Config) -> Vec<Obstacle> {
    config.obstacle.iter().map(ObstacleBox::obstacle).collect()
}

/// The camera's model with the config's `standoff`.
pub fn camera_model(config: &Config) -> CameraModel {
    CameraModel {
        standoff: config.standoff * M_PER_CM,
        ..CameraModel::default()
    }
}

/// The camera the config names.
pub fn build_camera(config: &Config) -> Box<dyn Camera> {
    let model = camera_model(config);
    match config.camera {
        CameraKind::Projection => Box::new(ProjectionCamera::new(model)),
        CameraKind::Raycast => Box::new(
            RaycastCamera::new(model, config.raycast_resolution)
                .with_pixel_noise(config.raycast_noise, config.seed),
        ),
    }
}

/// The trial loop's settings: `feedback_steps`, `min_feedback_steps`,
/// `min_target_distance`, the sensor noise entries and the camera's
/// timing (`camera_fps`, `camera_latency_ms`, `servo_mode`) and the frames learned during
/// moves (`learn_during_moves`, `move_frames_learned`).
pub fn trial_settings(config: &Config) -> TrialSettings {
    TrialSettings {
        feedback_steps: config.feedback_steps,
        min_feedback_steps: config.min_feedback_steps,
        epsilon: config.min_target_distance * M_PER_CM,
        noise: SensorNoise {
            centroid_px: config.camera_noise_px,
            area_relative: config.camera_area_noise,
            joint_deg: config.joint_noise_deg,
        },
        timing: CameraTiming {
            fps: config.camera_frame_rate(),
            latency: config.camera_latency_ms / 1000.0,
            servo: config.servo_mode,
        },
        move_frames: (config.learn_during_moves == 1).then_some(MoveFrames {
            fps: config.camera_frame_rate(),
            per_move: config.move_frames_learned,
        }),
    }
}

/// The dynamic simulator's settings (SI units) from `robot_speed`, `robot_accel`, `engine`,
/// `dt`, `solver_iterations`, `rapier_substeps`, the motor gains and the settling entries.
pub fn dynamic_settings(config: &Config) -> DynamicSettings {
    DynamicSettings {
        moves: move_settings(config),
        engine: config.engine,
        dt: config.dt,
        solver_iterations: config.solver_iterations,
        rapier_substeps: config.rapier_substeps,
        motor_stiffness: config.motor_stiffness,
        motor_damping: config.motor_damping,
        settle_position_tol: config.settle_position_tol.to_radians(),
        settle_speed_tol: config.settle_speed_tol.to_radians(),
        settle_timeout: config.settle_timeout,
    }
}

/// The moves' speed profile from `robot_speed` and `robot_accel`, and the floor from
/// `floor_z`.
pub fn move_settings(config: &Config) -> MoveSettings {
    MoveSettings::from_degrees(config.robot_speed, config.robot_accel)
        .with_floor(config.floor_z * M_PER_CM)
}

/// The learner the config names. `model` is the nominal robot (for `ik`); a learner that
/// stores patterns in a file (`use_pat_file` 0) puts it in `run_dir`. A learner with a
/// single model runs in a [`WatchedLearner`], which under `merge_strategy
/// change_detection` watches it for a change.
pub fn build_learner(
    config: &Config,
    model: &ArmModel,
    run_dir: Option<&Path>,
) -> Result<Box<dyn Learner>, LearnError> {
    let pat_file = run_dir
        .filter(|_| config.use_pat_file == 0)
        .map(|dir| dir.join("pat_file"));
    let bounds = input_bounds(config);
    let single: Box<dyn SingleModel> = match config.method {
        Method::Lin5 => return Ok(Box::new(Lin5::new(&lin5_settings(config), pat_file)?)),
        Method::Lin8 => return Ok(Box::new(Lin8::new(&lin8_settings(config), pat_file)?)),
        Method::Nnw => return Ok(Box::new(Nnw::new(&nnw_settings(config), pat_file)?)),
        Method::Ik => {
            return Ok(Box::new(IkLearner::new(
                model.clone(),
                camera_model(config),
            )))
        }
        Method::Broyden => return Ok(Box::new(Broyden::new(broyden_settings(config)))),
        Method::Ffn => Box::new(FfnLearner::new(ffn_settings(config), bounds, config.seed)),
        Method::Kohonen => Box::new(KohonenLearner::new(kohonen_settings(config), bounds)),
        Method::Lwpr => Box::new(Lwpr::new(lwpr_settings(config), bounds)),
        Method::Issgp => Box::new(Issgp::new(issgp_settings(config), bounds)),
        Method::Mlp => Box::new(Mlp::new(mlp_settings(config), bounds)),
    };
    Ok(Box::new(match single_model_watch_settings(config) {
        Some(change) => WatchedLearner::watched(single, &change, pattern_settings(config), bounds),
        None => WatchedLearner::unwatched(single),
    }))
}
