//! The control loop: trials of feedback steps towards a target, pre-learning, and the
//! noise of the sensors the loop reads.

mod feedback;
mod prelearn;
mod sensors;
mod trial;

pub use feedback::{StepError, StepReport, TrialEnd};
pub use prelearn::{prelearning_moves, PrelearnMove};
pub use sensors::SensorNoise;
pub use trial::{Failure, TrialLoop, TrialOutcome, TrialSettings, MAX_RECORDED_STEPS};
