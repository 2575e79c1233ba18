//! The learners: everything that maps a camera reading and two joint angles to a joint move.
//!
//! Every learner implements [`Learner`] (`contract/`); the trial loop only talks to that
//! trait. What they learn from is in `inputs/`; the study's nested learners in `nested/`,
//! the online peers in `online/`, the study's baselines and the model-based reference in
//! `baselines/`, change detection in `change/`. Each learner takes its own settings;
//! `experiment::setup` builds the one a run's config names.

mod baselines;
pub mod change;
mod contract;
mod inputs;
mod method;
mod nested;
mod online;

pub use baselines::net;
pub use baselines::{Broyden, BroydenSettings, BroydenUpdate, ImageJacobian};
pub use baselines::{FfnLearner, FfnSettings, IkLearner, KohonenLearner, KohonenSettings};
pub use baselines::{Lattice, Neighbourhood};
pub use contract::{LearnError, Learner, LearnerStats, LevelStats, MergeKind, ModelEvent};
pub use inputs::{
    adjusted_pattern, centred, pose_pairs, unadjusted_pattern, Observation, Pattern, Pattern5,
    Pattern8, PatternSettings, Query,
};
pub use method::{Method, MethodFacts};
pub use nested::{Lin5, Lin5Settings, Lin8, Lin8Settings, MergeStrategy, Nnw, NnwSettings};
pub use nested::{NestedLearner, NestedSettings, PerceptronSettings, TreeSettings};
pub use online::{Issgp, IssgpSettings, Lwpr, LwprSettings, Mlp, MlpSettings};
