//! Errors of building or running a learner.

use std::path::PathBuf;

/// A learner that cannot be built or cannot go on.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum LearnError {
    /// The run's `pat_file` cannot be created, written or read.
    #[error("pattern file {path}: {source}")]
    PatFile {
        /// The file.
        path: PathBuf,
        /// Why.
        source: std::io::Error,
    },
    /// A learner written outside the crate (a Python learner, say) failed; the run stops
    /// with what it wrote.
    #[error("learner `{learner}` failed: {reason}")]
    Failed {
        /// The learner's name.
        learner: String,
        /// What went wrong, in the learner's words.
        reason: String,
    },
}
