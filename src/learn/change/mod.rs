//! Global change detection (the study's §4.4.6, never built there): watch the tree-wide
//! stream of pattern errors for the moment the mapping changed.

mod corrected_learner;
mod detector;
mod reading_correction;
mod settings;
mod trial_miss;
mod watch;

pub use corrected_learner::CorrectedLearner;
pub use detector::{Alarm, ChangeDetector, DetectorSettings};
pub(crate) use reading_correction::ReadingCorrection;
pub use settings::{ChangeRecovery, ChangeSettings};
pub(crate) use trial_miss::TrialMiss;
pub(crate) use watch::{ChangeWatch, WatchStep};
