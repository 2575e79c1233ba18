//! The control loop: trials of feedback steps towards a target, pre-learning, and the
//! noise of the sensors the loop reads.

mod prelearn;
mod sensors;
mod trial;

pub use prelearn::{prelearning_moves, PrelearnMove};
pub use sensors::SensorNoise;
pub use trial::{Failure, TrialLoop, TrialOutcome, TrialSettings, MAX_RECORDED_STEPS};
