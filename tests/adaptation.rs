//! Adapting to a changed robot, on scaled-down runs of lin5 on the kinematic simulator: the
//! study's absolute merge throws the tree away after a 90° camera turn and learning starts
//! over; change detection finds a 30° and a 90° camera turn within 10 trials, dates it, and
//! is back within 1.5× its 4-step level within 100 trials, the 30° turn also when frames
//! during moves are learned; and a long run without a change raises no alarm and cuts
//! nothing. LWPR under change detection finds a 90° camera turn, dates it, and recovers
//! faster than by its forgetting alone; so do I-SSGP and the replay MLP, faster than without
//! the watch.

use eyehand::experiment::{run, Config, FourStepTrace, RunOptions};
use eyehand::learn::{MergeStrategy, Method};
use std::path::{Path, PathBuf};

/// A lin5 run of `trials` trials with `events`, `merge_strategy` and `am_error_tresh` set;
/// returns its folder (inside `data`).
fn run_lin5(
    data: &Path,
    trials: usize,
    events: &[&str],
    strategy: MergeStrategy,
    am_error_tresh: f64,
) -> PathBuf {
    run_lin5_with(data, trials, events, strategy, am_error_tresh, |_| {})
}

/// [`run_lin5`] with the config changed further by `tweak`.
fn run_lin5_with(
    data: &Path,
    trials: usize,
    events: &[&str],
    strategy: MergeStrategy,
    am_error_tresh: f64,
    tweak: impl FnOnce(&mut Config),
) -> PathBuf {
    let mut config = Config::default_config();
    config.trials = trials;
    config.seed = 1;
    config.merge_strategy = strategy;
    config.am_error_tresh = am_error_tresh;
    tweak(&mut config);
    let options = RunOptions {
        events: events.iter().map(|e| e.parse().unwrap()).collect(),
        ..RunOptions::new(config, data)
    };
    run(&options).unwrap().folder
}

/// The lines of a data file, split into fields.
fn rows(folder: &Path, file: &str) -> Vec<Vec<String>> {
    std::fs::read_to_string(folder.join(file))
        .unwrap()
        .lines()
        .map(|l| l.split(' ').map(String::from).collect())
        .collect()
}

/// Column 1 of a data file by trial (column 0).
fn by_trial(folder: &Path, file: &str) -> Vec<(usize, f64)> {
    rows(folder, file)
        .iter()
        .map(|r| (r[0].parse().unwrap(), r[1].parse().unwrap()))
        .collect()
}

/// The mean 4-step distance (mm) over trials `from..to`.
fn four_step_mean(folder: &Path, from: usize, to: usize) -> f64 {
    let d: Vec<f64> = by_trial(folder, "4step")
        .into_iter()
        .filter(|&(t, d)| (from..to).contains(&t) && d.is_finite())
        .map(|(_, d)| d)
        .collect();
    d.iter().sum::<f64>() / d.len() as f64
}

#[test]
fn the_studys_90_degree_turn_merges_the_root_and_learning_starts_over() {
    let data = tempfile::tempdir().unwrap();
    // The study's run scaled down: the turn at trial 400 instead of 1,500, and the
    // threshold the README gives for repeating it.
    let folder = run_lin5(
        data.path(),
        900,
        &["rotate:400:90"],
        MergeStrategy::Thesis,
        12.0,
    );
    let merges = rows(&folder, "merges");
    assert_eq!(merges.len(), 1, "{merges:?}");
    let [trial, kind, depth, nodes] = &merges[0][..] else {
        panic!("{merges:?}");
    };
    let trial: usize = trial.parse().unwrap();
    assert!((401..=550).contains(&trial), "root merged at trial {trial}");
    assert_eq!((kind.as_str(), depth.as_str()), ("absolute", "0"));
    let nodes_then: Vec<(usize, f64)> = by_trial(&folder, "nodes");
    let before = nodes_then[trial - 2].1;
    assert_eq!(nodes.parse::<f64>().unwrap(), before, "every node was cut");
    assert!(nodes_then[trial - 1].1 <= 3.0, "the tree starts over");
    assert!(nodes_then.last().unwrap().1 > 30.0, "and grows again");
    assert!(changes(&folder).is_empty());
    let relearned = four_step_mean(&folder, 800, 901);
    assert!(relearned < 1.5, "4-step {relearned} mm after relearning");
}

fn changes(folder: &Path) -> Vec<Vec<String>> {
    rows(folder, "changes")
}

/// Change detection finds the camera turn `event` at trial 1500 within 10 trials, dates it
/// within 2, merges nothing and is back within 1.5× its 4-step level within 100 trials;
/// with `during_moves`, learning from the frames taken during moves too.
fn finds_and_dates_a_camera_turn_and_recovers_within_100_trials(event: &str, during_moves: bool) {
    let data = tempfile::tempdir().unwrap();
    let folder = run_lin5_with(
        data.path(),
        1700,
        &[event],
        MergeStrategy::ChangeDetection,
        20.0,
        |config| {
            if during_moves {
                config.learn_during_moves = 1;
                config.camera_fps = 30.0;
            }
        },
    );
    let changes = changes(&folder);
    assert_eq!(changes.len(), 1, "{changes:?}");
    let raised: usize = changes[0][0].parse().unwrap();
    let dated: usize = changes[0][1].parse().unwrap();
    assert!((1501..=1510).contains(&raised), "found at trial {raised}");
    assert!(dated.abs_diff(1500) <= 2, "dated to trial {dated}");
    assert_eq!(rows(&folder, "merges"), Vec::<Vec<String>>::new());
    assert_back_within_100_trials_of_trial_1500(&folder);
}

#[test]
fn change_detection_finds_and_dates_a_30_degree_turn_and_recovers_within_100_trials() {
    finds_and_dates_a_camera_turn_and_recovers_within_100_trials("rotate:1500:30", false);
}

/// With frames during moves most of a trial's pairs end away from the centre; before the
/// alarm they come from trials in which the old tree lost its way, and fitted by them the
/// correction took the 30° turn for 17° (529 trials back).
#[test]
fn change_detection_recovers_from_a_30_degree_turn_within_100_trials_learning_during_moves() {
    finds_and_dates_a_camera_turn_and_recovers_within_100_trials("rotate:1500:30", true);
}

/// After a 90° turn most trials lose the object after their first move: those failures
/// count as evidence too.
#[test]
fn change_detection_finds_and_dates_a_90_degree_turn_and_recovers_within_100_trials() {
    finds_and_dates_a_camera_turn_and_recovers_within_100_trials("rotate:1500:90", false);
}

#[test]
fn change_detection_without_a_change_raises_no_alarm_and_cuts_nothing() {
    let data = tempfile::tempdir().unwrap();
    let folder = run_lin5(
        data.path(),
        20_000,
        &[],
        MergeStrategy::ChangeDetection,
        20.0,
    );
    assert_eq!(changes(&folder), Vec::<Vec<String>>::new());
    assert_eq!(rows(&folder, "merges"), Vec::<Vec<String>>::new());
}

/// A run of `method` with its shipped config (`configs/<method>.conf`) of `trials`
/// trials, seed 1, with `events` and `merge_strategy`.
fn run_shipped(
    method: Method,
    data: &Path,
    trials: usize,
    events: &[&str],
    strategy: MergeStrategy,
) -> PathBuf {
    run_shipped_with(method, data, trials, events, strategy, |_| {})
}

/// [`run_shipped`] with the config changed further by `tweak`.
fn run_shipped_with(
    method: Method,
    data: &Path,
    trials: usize,
    events: &[&str],
    strategy: MergeStrategy,
    tweak: impl FnOnce(&mut Config),
) -> PathBuf {
    let path = format!("{}/configs/{method}.conf", env!("CARGO_MANIFEST_DIR"));
    let mut config = Config::from_file(Path::new(&path)).unwrap();
    config.trials = trials;
    config.seed = 1;
    config.merge_strategy = strategy;
    tweak(&mut config);
    let options = RunOptions {
        events: events.iter().map(|e| e.parse().unwrap()).collect(),
        ..RunOptions::new(config, data)
    };
    run(&options).unwrap().folder
}

#[test]
fn lwpr_change_detection_finds_a_camera_turn_and_recovers_sooner_than_forgetting_alone() {
    let data = tempfile::tempdir().unwrap();
    let watched = run_shipped(
        Method::Lwpr,
        data.path(),
        1500,
        &["rotate:600:90"],
        MergeStrategy::ChangeDetection,
    );
    let alarms = changes(&watched);
    assert_eq!(alarms.len(), 1, "{alarms:?}");
    let raised: usize = alarms[0][0].parse().unwrap();
    let dated: usize = alarms[0][1].parse().unwrap();
    assert!((601..=650).contains(&raised), "found at trial {raised}");
    assert!(dated.abs_diff(600) <= 10, "dated to trial {dated}");
    let forgetting = run_shipped(
        Method::Lwpr,
        data.path(),
        1500,
        &["rotate:600:90"],
        MergeStrategy::Thesis,
    );
    assert!(changes(&forgetting).is_empty());
    let after = |folder: &Path| four_step_mean(folder, 800, 1100);
    assert!(
        after(&watched) < 0.9 * after(&forgetting),
        "4-step over trials 800-1100: {} mm with the watch, {} mm without",
        after(&watched),
        after(&forgetting)
    );
}

/// `method` under change detection finds a 90° camera turn at trial 600 within 50 trials,
/// dates it within 10, and its 4-step mean over trials 800–1100 is below half of the same
/// run's without the watch.
fn finds_a_camera_turn_and_recovers_sooner_than_without_the_watch(method: Method) {
    let data = tempfile::tempdir().unwrap();
    let run = |strategy| run_shipped(method, data.path(), 1500, &["rotate:600:90"], strategy);
    let watched = run(MergeStrategy::ChangeDetection);
    let alarms = changes(&watched);
    assert_eq!(alarms.len(), 1, "{method}: {alarms:?}");
    let raised: usize = alarms[0][0].parse().unwrap();
    let dated: usize = alarms[0][1].parse().unwrap();
    assert!(
        (601..=650).contains(&raised),
        "{method}: found at trial {raised}"
    );
    assert!(
        dated.abs_diff(600) <= 10,
        "{method}: dated to trial {dated}"
    );
    let unwatched = run(MergeStrategy::Thesis);
    assert!(changes(&unwatched).is_empty());
    let after = |folder: &Path| four_step_mean(folder, 800, 1100);
    assert!(
        after(&watched) < 0.5 * after(&unwatched),
        "{method}, 4-step over trials 800-1100: {} mm with the watch, {} mm without",
        after(&watched),
        after(&unwatched)
    );
}

#[test]
fn issgp_change_detection_finds_a_camera_turn_and_recovers_sooner_than_without() {
    finds_a_camera_turn_and_recovers_sooner_than_without_the_watch(Method::Issgp);
}

#[test]
fn mlp_change_detection_finds_a_camera_turn_and_recovers_sooner_than_without() {
    finds_a_camera_turn_and_recovers_sooner_than_without_the_watch(Method::Mlp);
}

/// lin8 learning during moves: its correction of a 90° turn was fixed while refits still
/// moved it (at 59°), and the arm did not come back within 1.5× in 1,500 trials.
#[test]
fn lin8_learning_during_moves_recovers_from_a_90_degree_turn_within_100_trials() {
    let data = tempfile::tempdir().unwrap();
    let folder = run_shipped_with(
        Method::Lin8,
        data.path(),
        1700,
        &["rotate:1500:90"],
        MergeStrategy::ChangeDetection,
        |config| {
            config.learn_during_moves = 1;
            config.camera_fps = 30.0;
        },
    );
    assert_back_within_100_trials_of_trial_1500(&folder);
}

/// The run in `folder` is back within 1.5× its 4-step level within 100 trials of an event at
/// trial 1500.
fn assert_back_within_100_trials_of_trial_1500(folder: &Path) {
    let trace = FourStepTrace::read(folder).unwrap();
    let recovered = trace.recovered_after(1500);
    assert!(
        recovered.is_some_and(|t| t <= 100),
        "within 1.5x of {:?} mm after {recovered:?} trials",
        trace.level_before(1500)
    );
}
