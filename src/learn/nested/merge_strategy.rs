//! How a nested learner gets rid of what a change of the mapping made wrong.

/// How a nested learner gets rid of what a change of the mapping made wrong (the config's
/// `merge_strategy`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub enum MergeStrategy {
    /// The study's absolute and relative merges (§2.4.3), as it ran them (`thesis`, the
    /// default).
    #[default]
    Thesis,
    /// Global change detection on the stream of pattern errors (§4.4.6) on top of them
    /// (`change_detection`).
    ChangeDetection,
}
