//! Re-simulating a run: the run's config, seed, URDF and events give the same simulator,
//! camera, learner and trial loop, driven through trials 1..=N exactly as the run drove
//! them (runs are deterministic), with the trials of interest watched.

use super::divergence::StepOneLog;
use super::replay_bar::ReplayBar;
use super::tracer::{Look, SharedLog, WatchLog, WatchedCamera, WatchedSim};
use super::{RecordedRun, ShowError};
use crate::control::{Failure, TrialLoop, TrialOutcome};
use crate::experiment::run::trial_driver::TrialDriver;
use crate::experiment::Event;
use crate::robot::{ArmModel, Joints};
use std::path::Path;

/// What one replayed trial did, pose by pose.
#[derive(Debug, Clone)]
pub struct TrialTrace {
    /// The trial (1-based).
    pub trial: usize,
    /// The start pose's look and one look after every feedback step (the last one may not
    /// see the object); empty when no target or start was drawn.
    pub looks: Vec<Look>,
    /// Joint angles of every physics tick from the start pose on, with their simulated
    /// time (s); empty on the kinematic simulator or when ticks were not asked for.
    pub ticks: Vec<(f64, Joints)>,
    /// The distances and failure the run logged for this trial.
    pub outcome: TrialOutcome,
    /// The robot as it was during the trial (links stretched, camera turned).
    pub model: ArmModel,
    /// The events in effect: those applied before or at this trial.
    pub events: Vec<Event>,
}

/// Replays trials 1..=`last` of `run`, handing every trial for which `watched` is true to
/// `on_trial`. `ticks` keeps the dynamic simulator's physics ticks. A learner that stores
/// its patterns in a file puts it in `scratch`. Every trial's distance after step 1 must be
/// the run's (its `1step` file), else the replay stops with [`ShowError::Diverged`]. A
/// replay that takes more than a second shows a bar on stderr when it is a terminal.
pub fn replay(
    run: &RecordedRun,
    last: usize,
    watched: impl Fn(usize) -> bool,
    ticks: bool,
    scratch: &Path,
    mut on_trial: impl FnMut(TrialTrace) -> Result<(), ShowError>,
) -> Result<(), ShowError> {
    run.check_trials(1, last)?;
    let mut step_one = StepOneLog::read(run)?;
    let setup = &run.setup;
    let log = SharedLog::default();
    let sim = WatchedSim::new(setup.simulator(), log.clone());
    let camera = WatchedCamera::new(setup.camera(), log.clone());
    let learner = setup
        .learner(Some(scratch))
        .map_err(crate::experiment::RunError::from)?;
    let trials = setup.trial_loop_around(Box::new(sim), Box::new(camera));
    let mut bar = ReplayBar::new(last);
    let mut driver = TrialDriver::start(trials, learner, setup.events.clone())?;
    for trial in 1..=last {
        log.borrow_mut().clear();
        driver
            .trials_mut()
            .sim_mut()
            .keep_ticks(ticks && watched(trial));
        let outcome = driver.next(trial, &mut |_: usize, _: f64| {})?;
        step_one.check(run, trial, outcome.distances_mm.first().copied())?;
        bar.done(trial);
        if watched(trial) {
            on_trial(trace_of(
                trial,
                outcome,
                &log,
                driver.trials(),
                &setup.events,
            ))?;
        }
    }
    Ok(())
}

fn trace_of(
    trial: usize,
    outcome: TrialOutcome,
    log: &SharedLog,
    trials: &TrialLoop,
    events: &[Event],
) -> TrialTrace {
    let mut log = log.borrow_mut();
    let drawn = !matches!(
        outcome.failure,
        Some(Failure::UnreachableTarget | Failure::NoStartSeen)
    );
    let WatchLog { looks, ticks, .. } = &mut *log;
    TrialTrace {
        trial,
        looks: if drawn {
            std::mem::take(looks)
        } else {
            Vec::new()
        },
        ticks: std::mem::take(ticks),
        outcome,
        model: trials.sim().model().clone(),
        events: events
            .iter()
            .filter(|e| e.trial() <= trial)
            .copied()
            .collect(),
    }
}
