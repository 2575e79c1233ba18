//! `change_recovery correct` for every learner with a model: on the kinematic simulator,
//! seed 1, its shipped config under `merge_strategy change_detection`, a 30° camera turn
//! before trial 600 of 1,500, the learner is back within 1.5× its 4-step level
//! (`FourStepTrace::recovered_after`) sooner with `correct` than without it: than with
//! `forget` for the learners that have one (lin5, lin8, nnw, lwpr, issgp, mlp), than
//! without change detection for those that have none (kohonen).

use eyehand::experiment::{run, Config, FourStepTrace, RunOptions};
use eyehand::learn::change::ChangeRecovery;
use eyehand::learn::{MergeStrategy, Method};
use std::path::Path;

const TRIALS: usize = 1500;
const EVENT: usize = 600;

/// Trials `method` takes to recover from the turn under `strategy` and `recovery`
/// (`usize::MAX`: not by the last trial).
fn recovered_after(method: Method, strategy: MergeStrategy, recovery: ChangeRecovery) -> usize {
    let data = tempfile::tempdir().unwrap();
    let path = format!("{}/configs/{method}.conf", env!("CARGO_MANIFEST_DIR"));
    let mut config = Config::from_file(Path::new(&path)).unwrap();
    config.trials = TRIALS;
    config.seed = 1;
    config.merge_strategy = strategy;
    config.change_recovery = recovery;
    let options = RunOptions {
        events: vec![format!("rotate:{EVENT}:30").parse().unwrap()],
        ..RunOptions::new(config, data.path())
    };
    let folder = run(&options).unwrap().folder;
    FourStepTrace::read(&folder)
        .unwrap()
        .recovered_after(EVENT)
        .unwrap_or(usize::MAX)
}

/// `method` recovers sooner with `correct` than with `without`.
fn corrects_sooner(method: Method, without: (MergeStrategy, ChangeRecovery)) {
    let correct = recovered_after(
        method,
        MergeStrategy::ChangeDetection,
        ChangeRecovery::Correct,
    );
    let other = recovered_after(method, without.0, without.1);
    assert!(
        correct < other,
        "{method}: recovered after {correct} trials with correct, {other} without"
    );
}

const FORGET: (MergeStrategy, ChangeRecovery) =
    (MergeStrategy::ChangeDetection, ChangeRecovery::Forget);
const UNWATCHED: (MergeStrategy, ChangeRecovery) = (MergeStrategy::Thesis, ChangeRecovery::Correct);

#[test]
fn lin5_corrects_sooner_than_it_forgets() {
    corrects_sooner(Method::Lin5, FORGET);
}

#[test]
fn lin8_corrects_sooner_than_it_forgets() {
    corrects_sooner(Method::Lin8, FORGET);
}

#[test]
fn nnw_corrects_sooner_than_it_forgets() {
    corrects_sooner(Method::Nnw, FORGET);
}

#[test]
fn lwpr_corrects_sooner_than_it_forgets() {
    corrects_sooner(Method::Lwpr, FORGET);
}

#[test]
fn issgp_corrects_sooner_than_it_forgets() {
    corrects_sooner(Method::Issgp, FORGET);
}

#[test]
fn mlp_corrects_sooner_than_it_forgets() {
    corrects_sooner(Method::Mlp, FORGET);
}

#[test]
fn kohonen_corrects_sooner_than_without_a_watch() {
    corrects_sooner(Method::Kohonen, UNWATCHED);
}

#[test]
fn ffn_corrects_sooner_than_without_a_watch() {
    corrects_sooner(Method::Ffn, UNWATCHED);
}
