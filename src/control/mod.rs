//! The control loop: trials of feedback steps towards a target, pre-learning, the noise
//! of the sensors the loop reads, the camera's clock, and the simulator's world as the
//! camera's scene.

mod clocked;
mod feedback;
mod move_frames;
mod prelearn;
mod sensors;
mod timing;
mod trial;
mod world_scene;

pub use feedback::{StepError, StepReport, TrialEnd, TrialObserver};
pub use move_frames::MoveFrames;
pub use prelearn::{prelearning_moves, PrelearnMove};
pub use sensors::SensorNoise;
pub use timing::{CameraTiming, ServoMode};
pub use trial::{Failure, TrialLoop, TrialOutcome, TrialSettings, MAX_RECORDED_STEPS};
pub use world_scene::{ARM_GREY, FLOOR_GREYS, OBSTACLE_GREY};
