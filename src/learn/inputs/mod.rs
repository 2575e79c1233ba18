//! What learners see and learn from: the observation of a pose, a learner's query, and the
//! learning patterns made of pairs of poses.

mod observation;
mod patterns;
#[cfg(test)]
pub(crate) mod synthetic;

pub(crate) use observation::finite_or_still;
pub use observation::{Observation, Query};
pub use patterns::{
    adjusted_pattern, centred, pose_pairs, unadjusted_pattern, Pattern, Pattern5, Pattern8,
    PatternSettings,
};
