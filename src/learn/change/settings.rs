//! What the change watch is set up by.

use super::DetectorSettings;

/// Settings of change detection and of the recovery that follows an alarm.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ChangeSettings {
    /// The CUSUM test on the per-trial values (`change_drift`, `change_threshold`,
    /// `change_baseline`, `change_lag`, `change_warmup`); see [`DetectorSettings`].
    pub detector: DetectorSettings,
    /// Trials after an alarm (and between later checks) before starved subtrees are cut
    /// (`change_grace`); 200 by default.
    pub grace: usize,
    /// Patterns from after a change a node needs before it answers again
    /// (`change_min_fresh`); 20 by default.
    pub min_fresh: usize,
    /// What a nested learner does at an alarm (`change_recovery`); by default it corrects
    /// the readings.
    pub recovery: ChangeRecovery,
    /// Under `correct`: patterns since a change its correction is fitted from before it is
    /// fixed and the tree learns again (`change_fit_patterns`); 300 by default.
    pub fit_patterns: usize,
    /// Under `correct`: stored patterns a sub-box needs before it is split off once a
    /// correction is fixed (`change_split_patterns`; never more than the tree's own
    /// `min_pats_for_split`); 20 by default.
    pub split_patterns: usize,
}

/// What a nested learner does when a change is detected (the config's `change_recovery`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub enum ChangeRecovery {
    /// Keep the tree and fit a correction of the readings that carries the new ones back to
    /// those it learned (`correct`, the default).
    #[default]
    Correct,
    /// Forget what was learned before the change, and cut the subtrees left starved
    /// (`forget`).
    Forget,
}

impl Default for ChangeSettings {
    fn default() -> Self {
        ChangeSettings {
            detector: DetectorSettings::default(),
            grace: 200,
            min_fresh: 20,
            recovery: ChangeRecovery::Correct,
            fit_patterns: 300,
            split_patterns: 20,
        }
    }
}
