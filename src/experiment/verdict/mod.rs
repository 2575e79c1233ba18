//! Judging a run: its step figures, failed trials by reason, the learning verdict and the
//! milestones (trials to a level, recovery after an event).

pub(super) mod failures;
pub(super) mod learning_progress;
pub(super) mod learning_verdict;
pub(super) mod milestones;
pub(super) mod step_figures;
