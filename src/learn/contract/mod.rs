//! What a learner is to the rest of the program: the [`Learner`] trait, the figures it
//! reports, the events it raises and the error it may fail with.

mod error;
mod learner;
mod model_event;
mod stats;

pub use error::LearnError;
pub use learner::Learner;
pub use model_event::{MergeKind, ModelEvent};
pub use stats::{LearnerStats, LevelStats};
