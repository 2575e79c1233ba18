//! The control loop: trials of feedback steps towards a target, pre-learning, and the
//! learning patterns each trial's poses give.

mod observation;
mod patterns;
mod prelearn;
mod trial;

pub use observation::{Observation, Query};
pub use patterns::{adjusted_pattern, pose_pairs, unadjusted_pattern, Pattern, Pattern5, Pattern8};
pub use prelearn::{prelearning_moves, PrelearnMove};
pub use trial::{Failure, TrialLoop, TrialOutcome, TrialSettings, MAX_RECORDED_STEPS};
