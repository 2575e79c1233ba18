//! Whether a config's merges cut the learner's tree at its root while it learns an
//! unchanged arm: `check-config` learns the config's first trials without its events and
//! counts the root merges, so a file whose absolute merge fires on plain learning is
//! caught before a run throws its tree away.

use crate::experiment::run::trial_driver::TrialDriver;
use crate::experiment::{RunError, RunSetup};
use crate::learn::{Method, ModelEvent};

/// Trials a probe of `lin5` or `lin8` learns at most.
pub const PROBE_TRIALS: usize = 2000;
/// Trials a probe of `nnw` learns at most: its nets are re-trained as they learn, which
/// makes a trial several times dearer (500 trials of the study's nnw file take about 3 s of
/// CPU in an optimized build).
pub const NNW_PROBE_TRIALS: usize = 500;

/// What learning a config's first trials without its events did to the tree's root.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct RootCuts {
    /// Trials learned: those before the config's first event, at most [`PROBE_TRIALS`]
    /// ([`NNW_PROBE_TRIALS`] for `nnw`).
    pub trials: usize,
    /// Times the root was merged.
    pub cuts: usize,
    /// The trial of the first.
    pub first: Option<usize>,
}

/// Learns the first trials of `setup`'s config without any event (the trials before its
/// first event, at most [`PROBE_TRIALS`], or [`NNW_PROBE_TRIALS`] for `nnw`) and counts the
/// root merges. `None` for a method without the study's merges.
pub fn root_cuts_in_plain_learning(setup: &RunSetup) -> Result<Option<RootCuts>, RunError> {
    let config = &setup.config;
    let most = match config.method {
        Method::Lin5 | Method::Lin8 => PROBE_TRIALS,
        Method::Nnw => NNW_PROBE_TRIALS,
        _ => return Ok(None),
    };
    let first_event = setup.events.iter().map(|e| e.trial()).min();
    let trials = first_event
        .map_or(config.trials, |t| t.saturating_sub(1))
        .min(config.trials)
        .min(most);
    let mut driver = TrialDriver::start(setup.trial_loop(), setup.learner(None)?, Vec::new())?;
    let mut probe = RootCuts {
        trials,
        cuts: 0,
        first: None,
    };
    for trial in 1..=trials {
        driver.next(trial, &mut |_, _| {})?;
        let events = driver.model_events();
        if events.iter().any(ModelEvent::is_root_merge) {
            probe.first.get_or_insert(trial);
        }
        probe.cuts += events.iter().filter(|e| e.is_root_merge()).count();
    }
    Ok(Some(probe))
}
