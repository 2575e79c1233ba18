//! The control loop: trials of feedback steps towards a target, pre-learning, the noise
//! of the sensors the loop reads and the camera's clock.

mod clocked;
mod feedback;
mod prelearn;
mod sensors;
mod timing;
mod trial;

pub use feedback::{StepError, StepReport, TrialEnd};
pub use prelearn::{prelearning_moves, PrelearnMove};
pub use sensors::SensorNoise;
pub use timing::{CameraTiming, ServoMode};
pub use trial::{Failure, TrialLoop, TrialOutcome, TrialSettings, MAX_RECORDED_STEPS};
