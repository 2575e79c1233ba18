//! The study's own config (configs/study.conf, its appendix A.2 listing) learns as the
//! study says (§4.4.3, §5.3.1): nothing cuts the tree at its root while the arm is
//! unchanged, and after the camera turns by 90° at trial 1,500 the root is cut within a few
//! trials and learning starts over. Seed 1, kinematic OSCAR-6, 3,000 trials.

use eyehand::experiment::{run, Config, RunOptions, RunResult};
use std::path::{Path, PathBuf};

/// Runs configs/study.conf for 3,000 trials, seed 1, with `edit` applied; the run folder.
fn study_run(data: &Path, edit: impl FnOnce(&mut Config)) -> PathBuf {
    run_file(data, "configs/study.conf", |config| {
        config.trials = 3000;
        config.seed = 1;
        edit(config);
    })
    .folder
}

/// Runs the shipped config `file` with `edit` applied.
fn run_file(data: &Path, file: &str, edit: impl FnOnce(&mut Config)) -> RunResult {
    let file = Path::new(env!("CARGO_MANIFEST_DIR")).join(file);
    let mut config = Config::from_file(&file).unwrap();
    edit(&mut config);
    run(&RunOptions::new(config, data)).unwrap()
}

/// The trials at which the root was merged, from the run's `merges` file.
fn root_merges(folder: &Path) -> Vec<usize> {
    let text = std::fs::read_to_string(folder.join("merges")).unwrap_or_default();
    text.lines()
        .map(|l| l.split_whitespace().collect::<Vec<_>>())
        .filter(|fields| fields[2] == "0")
        .map(|fields| fields[0].parse().unwrap())
        .collect()
}

/// The mean distance after 4 steps over trials `from..to` (mm).
fn four_step_mean(folder: &Path, from: usize, to: usize) -> f64 {
    let text = std::fs::read_to_string(folder.join("4step")).unwrap();
    let values: Vec<f64> = text
        .lines()
        .filter_map(|l| {
            let mut fields = l.split_whitespace();
            let trial: usize = fields.next()?.parse().ok()?;
            let distance: f64 = fields.next()?.parse().ok()?;
            (from..to).contains(&trial).then_some(distance)
        })
        .collect();
    assert!(values.len() > (to - from) / 2, "{} values", values.len());
    values.iter().sum::<f64>() / values.len() as f64
}

#[test]
fn the_studys_file_learns_without_cutting_its_root() {
    let data = tempfile::tempdir().unwrap();
    let folder = study_run(data.path(), |config| config.rotate_trial = 0);
    assert_eq!(root_merges(&folder), Vec::<usize>::new());
    let early = four_step_mean(&folder, 1, 101);
    let late = four_step_mean(&folder, 1000, 1500);
    assert!(late < 0.2, "4-step mean {late} mm over trials 1000-1499");
    assert!(late < early / 5.0, "it learns: {early} mm, then {late} mm");
}

#[test]
fn the_studys_90_degree_turn_cuts_the_root_within_a_few_trials_and_it_relearns() {
    let data = tempfile::tempdir().unwrap();
    let folder = study_run(data.path(), |_| {});
    let cuts = root_merges(&folder);
    assert!(!cuts.is_empty(), "the turn was not seen");
    assert!(
        (1500..=1520).contains(&cuts[0]),
        "root cut at trials {cuts:?}"
    );
    let before = four_step_mean(&folder, 1000, 1500);
    let relearned = four_step_mean(&folder, 2500, 3001);
    assert!(
        relearned < 2.0 * before.max(0.2),
        "relearned to {relearned} mm (before the turn {before} mm)"
    );
}

#[test]
fn lin8_relearns_after_a_turn_cuts_its_root() {
    // The study's lin8 file (fig. 5.14) with the 90° turn at trial 200: the root is cut
    // while a trial is learned, and the fresh tree must start from pre-learning alone.
    let data = tempfile::tempdir().unwrap();
    let result = run_file(
        data.path(),
        "configs/study/fig5.14_lin8_camera_90.conf",
        |config| {
            config.seed = 1;
            config.rotate_trial = 200;
            config.trials = 600;
        },
    );
    let cuts = root_merges(&result.folder);
    assert!(
        cuts.first().is_some_and(|&t| (200..=230).contains(&t)),
        "root cut at trials {cuts:?}"
    );
    assert!(result.summary.learned, "lin8 learned nothing after the cut");
    let relearned = four_step_mean(&result.folder, 400, 601);
    assert!(
        relearned < 30.0,
        "4-step mean {relearned} mm over trials 400-600"
    );
}

/// `eyehand check-config FILE`'s stderr.
fn check_config_stderr(file: &Path) -> String {
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_eyehand"))
        .arg("check-config")
        .arg(file)
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8_lossy(&out.stderr).into_owned()
}

/// `check-config`'s stderr for the shipped `file` as it is (it must say nothing) and with
/// `am_error_tresh 0.5` (it must warn of root cuts in `trials` trials).
fn assert_warns_of_a_low_threshold_only(file: &str, trials: usize) {
    let shipped = Path::new(env!("CARGO_MANIFEST_DIR")).join(file);
    assert_eq!(check_config_stderr(&shipped), "", "{file} cuts nothing");
    let dir = tempfile::tempdir().unwrap();
    let low = dir.path().join("low.conf");
    let listing = std::fs::read_to_string(&shipped).unwrap();
    std::fs::write(
        &low,
        listing.replace("am_error_tresh         5.0", "am_error_tresh 0.5"),
    )
    .unwrap();
    let warned = check_config_stderr(&low);
    assert!(
        warned.contains("am_error_tresh 0.5 over am_error_iters 50 cut the tree at its root")
            && warned.contains(&format!("in {trials} trials of plain learning")),
        "{warned}"
    );
}

#[test]
fn check_config_warns_of_merges_that_cut_the_root_while_the_arm_is_unchanged() {
    assert_warns_of_a_low_threshold_only("configs/study.conf", 1499);
}

#[test]
fn check_config_probes_an_nnw_file_for_root_cuts_too() {
    assert_warns_of_a_low_threshold_only("configs/study/sec3.2.3_nnw.conf", 500);
}
