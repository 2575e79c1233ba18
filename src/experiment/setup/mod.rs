//! Setting a run up: the one place where a [`Config`] becomes the simulator, the camera,
//! the learner and the trial loop's settings.

use super::{CameraKind, Config, SimKind};
use crate::camera::{Camera, CameraModel, ProjectionCamera, RaycastCamera};
use crate::control::TrialSettings;
use crate::learn::{
    FfnLearner, FfnSettings, IkLearner, KohonenLearner, KohonenSettings, LearnError, Learner, Lin5,
    Lin8, Method, Nnw,
};
use crate::robot::{ArmModel, DynamicSim, KinematicSim, MoveSettings, Simulator};
use crate::units::M_PER_CM;
use std::path::Path;

/// The simulator the config names, moving `model`.
pub fn build_simulator(config: &Config, model: ArmModel) -> Box<dyn Simulator> {
    match config.sim {
        SimKind::Kinematic => Box::new(KinematicSim::new(
            model,
            MoveSettings::from_degrees(config.robot_speed, config.robot_accel),
        )),
        SimKind::Dynamic => Box::new(DynamicSim::new(model, config.dynamic_settings())),
    }
}

/// The camera the config names.
pub fn build_camera(config: &Config) -> Box<dyn Camera> {
    let model = CameraModel::default();
    match config.camera {
        CameraKind::Projection => Box::new(ProjectionCamera::new(model)),
        CameraKind::Raycast => Box::new(RaycastCamera::new(model, config.raycast_resolution)),
    }
}

/// The trial loop's settings: `feedback_steps`, `min_feedback_steps`,
/// `min_target_distance` and `minimal_joint_move`.
pub fn trial_settings(config: &Config) -> TrialSettings {
    TrialSettings {
        feedback_steps: config.feedback_steps,
        min_feedback_steps: config.min_feedback_steps,
        epsilon: config.min_target_distance * M_PER_CM,
        minimal_joint_move_deg: config.minimal_joint_move,
    }
}

/// Builds the learner the config names. `model` is the nominal robot (for `ik`); a
/// learner that stores patterns in a file puts it in `run_dir`.
pub fn build_learner(
    config: &Config,
    model: &ArmModel,
    run_dir: Option<&Path>,
) -> Result<Box<dyn Learner>, LearnError> {
    match config.method {
        Method::Lin5 | Method::Lin8 | Method::Nnw => {
            let pat_file = run_dir
                .filter(|_| config.use_pat_file == 0)
                .map(|dir| dir.join("pat_file"));
            let learner: Box<dyn Learner> = match config.method {
                Method::Lin8 => Box::new(Lin8::new(config, pat_file)?),
                Method::Nnw => Box::new(Nnw::new(config, pat_file)?),
                _ => Box::new(Lin5::new(config, pat_file)?),
            };
            Ok(learner)
        }
        Method::Ik => Ok(Box::new(IkLearner::new(
            model.clone(),
            CameraModel::default(),
        ))),
        Method::Ffn => {
            let settings = FfnSettings {
                hidden_units: config.ffn_hidden_units,
                wrange: config.wrange,
                window: config.ffn_window,
                cg_iterations: config.ffn_cg_iterations,
                minimal_joint_move: config.minimal_joint_move,
            };
            Ok(Box::new(FfnLearner::new(
                settings,
                input_bounds(config),
                config.seed,
            )))
        }
        Method::Kohonen => {
            let settings = KohonenSettings {
                side: config.kohonen_side,
                anneal_patterns: config.kohonen_anneal_patterns,
                minimal_joint_move: config.minimal_joint_move,
                ..KohonenSettings::default()
            };
            Ok(Box::new(KohonenLearner::new(
                settings,
                input_bounds(config),
            )))
        }
    }
}

/// The config's boundaries of the five inputs (θ2, θ3, cx, cy, cz).
fn input_bounds(config: &Config) -> [(f64, f64); 5] {
    std::array::from_fn(|i| config.boundary(i))
}
