//! The one driver of a run's trials: the learner started and pre-learned, then each trial
//! with the events due before it, the learner told, pre-learning repeated when it asks, the
//! trial run and learned, and the merges and changes it raised collected. A run, its replay
//! (`eyehand show`, `eyehand report`) and `check-config`'s probe all go through it, so a
//! replay reproduces its run exactly; the Python `Testbed`, whose trials Python steps
//! itself, starts its learners and begins their trials through the same
//! [`start_learning`] and [`begin_learner_trial`].

use super::run_options::RunError;
use crate::control::{TrialLoop, TrialObserver, TrialOutcome};
use crate::experiment::Event;
use crate::learn::{LearnError, Learner, ModelEvent};

/// Starts `learner` on `trials` as every run does before its first trial: the learner told
/// trial 0 (its pre-learning) begins, then the pre-learning moves made and learned.
pub fn start_learning(trials: &mut TrialLoop, learner: &mut dyn Learner) -> Result<(), LearnError> {
    learner.start_trial(0);
    trials.prelearn(learner)
}

/// Begins trial `trial` for `learner` as every run does once the trial's events are in:
/// the learner told, then the pre-learning moves made and learned again if it asks.
pub fn begin_learner_trial(
    trials: &mut TrialLoop,
    learner: &mut dyn Learner,
    trial: usize,
) -> Result<(), LearnError> {
    learner.start_trial(trial);
    if learner.take_relearn_request() {
        trials.prelearn(learner)?;
    }
    Ok(())
}

/// A trial loop and a learner driven trial by trial through a run's events.
#[derive(Debug)]
pub(crate) struct TrialDriver {
    trials: TrialLoop,
    learner: Box<dyn Learner>,
    events: Vec<Event>,
    model_events: Vec<ModelEvent>,
}

impl TrialDriver {
    /// Starts `learner` on `trials` ([`start_learning`]); `events` are applied each before
    /// its trial.
    pub(crate) fn start(
        mut trials: TrialLoop,
        mut learner: Box<dyn Learner>,
        events: Vec<Event>,
    ) -> Result<TrialDriver, RunError> {
        start_learning(&mut trials, learner.as_mut())?;
        Ok(TrialDriver {
            trials,
            learner,
            events,
            model_events: Vec::new(),
        })
    }

    /// Trial `trial`: the events due before it applied, the learner told, pre-learning
    /// repeated if the learner asks, then the trial run and learned (`observer` told of
    /// every feedback step and of the learning: see [`TrialLoop::run_trial_observed`]),
    /// and the learner's merges and detected changes collected
    /// ([`model_events`](Self::model_events)).
    pub(crate) fn next(
        &mut self,
        trial: usize,
        observer: &mut dyn TrialObserver,
    ) -> Result<TrialOutcome, RunError> {
        for event in self.events.iter().filter(|e| e.trial() == trial) {
            event
                .apply(self.trials.sim_mut())
                .map_err(|source| RunError::Event {
                    event: *event,
                    source,
                })?;
        }
        let learner = self.learner.as_mut();
        begin_learner_trial(&mut self.trials, learner, trial)?;
        let outcome = self.trials.run_trial_observed(learner, observer)?;
        self.model_events.clear();
        learner.drain_events(&mut self.model_events);
        Ok(outcome)
    }

    /// The merges and detected changes the learner raised in the last trial.
    pub(crate) fn model_events(&self) -> &[ModelEvent] {
        &self.model_events
    }

    /// The trial loop.
    pub(crate) fn trials(&self) -> &TrialLoop {
        &self.trials
    }

    /// The trial loop, to change what it keeps (the simulator's ticks, say).
    pub(crate) fn trials_mut(&mut self) -> &mut TrialLoop {
        &mut self.trials
    }

    /// The learner.
    pub(crate) fn learner(&self) -> &dyn Learner {
        self.learner.as_ref()
    }
}
