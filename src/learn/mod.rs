//! The learners: everything that maps a camera reading and two joint angles to a joint move.
//!
//! Every learner implements [`Learner`]; the trial loop only talks to that trait. A learner
//! is built by [`build_learner`] from the run's [`Config`](crate::experiment::Config).

pub mod change;
mod error;
mod ffn;
mod ik;
mod kohonen;
mod lin5;
mod lin8;
mod method;
mod model_event;
pub mod net;
mod nnw;
mod perceptron;
mod stats;
#[cfg(test)]
mod synthetic;
mod tree;

pub use error::LearnError;
pub use ffn::{FfnLearner, FfnSettings};
pub use ik::IkLearner;
pub use kohonen::{KohonenLearner, KohonenSettings, Lattice, Neighbourhood};
pub use lin5::Lin5;
pub use lin8::Lin8;
pub use method::Method;
pub use model_event::{MergeKind, ModelEvent};
pub use nnw::Nnw;
pub use stats::{LearnerStats, LevelStats};

use crate::camera::CameraModel;
use crate::control::{Observation, Query};
use crate::experiment::Config;
use crate::robot::ArmModel;
use nalgebra::Vector3;
use std::path::Path;

/// A learner of the eye-hand mapping `Δθ = N(c, θ2, θ3)`.
///
/// Angles are in degrees, camera readings in the camera's units (pixels for cx, cy; the
/// area measure for cz).
pub trait Learner: std::fmt::Debug {
    /// The method this learner implements.
    fn method(&self) -> Method;

    /// The joint move (Δθ1, Δθ2, Δθ3 in degrees) this learner proposes for `query`.
    /// Must always be finite.
    fn propose(&mut self, query: &Query) -> Vector3<f64>;

    /// Learns from the observations of one finished trial (or pre-learning move), in the
    /// order they were made: every pair of poses gives a learning pattern. Fails only when
    /// the learner's storage (a pattern file) fails; the run then stops with what it wrote.
    fn learn(&mut self, path: &[Observation]) -> Result<(), LearnError>;

    /// Figures for the run's data files.
    fn stats(&self) -> LearnerStats;

    /// True once after the learner threw away everything it knew (a root merge), or after a
    /// detected change left it nothing valid to answer from: the trial loop then repeats
    /// pre-learning before the next trial.
    fn take_relearn_request(&mut self) -> bool {
        false
    }

    /// Tells the learner which trial comes next (1-based; 0 is pre-learning), so it can
    /// date what it learns. A learner watching for changes of the mapping weighs the trial
    /// before here, and may forget or cut before this trial's first move.
    fn start_trial(&mut self, _trial: usize) {}

    /// Moves the merges and detected changes since the last call into `sink`.
    fn drain_events(&mut self, _sink: &mut Vec<ModelEvent>) {}
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
