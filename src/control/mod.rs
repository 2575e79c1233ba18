//! The control loop: trials of feedback steps towards a target, and pre-learning.

mod prelearn;
mod trial;

pub use prelearn::{prelearning_moves, PrelearnMove};
pub use trial::{Failure, TrialLoop, TrialOutcome, TrialSettings, MAX_RECORDED_STEPS};
