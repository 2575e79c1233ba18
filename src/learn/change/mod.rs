//! Global change detection (the study's §4.4.6, never built there): watch a learner's
//! stream of pattern errors for the moment the mapping changed, and recover from it — the
//! corrections of the readings every learner with a model can answer through, and the one
//! wrapper of the single-model learners.

mod corrections;
mod detector;
mod reading_correction;
mod settings;
mod single_model;
mod trial_miss;
mod watch;
mod watched_learner;

pub(crate) use corrections::{Corrections, SEED_TRIALS};
pub use detector::{Alarm, ChangeDetector, DetectorSettings};
pub(crate) use reading_correction::ReadingCorrection;
pub use settings::{ChangeRecovery, ChangeSettings};
pub use single_model::SingleModel;
pub(crate) use trial_miss::TrialMiss;
pub(crate) use watch::{ChangeWatch, WatchStep};
pub use watched_learner::WatchedLearner;
