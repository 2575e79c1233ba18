//! The config's declarations are the one source of its defaults and docs: a file carries
//! only what it changes, `info` and `check-config --explain` say where every value came
//! from, docs/CONFIG.md is the declarations' table, and the study's own config (its
//! appendix A.2, as printed) runs unchanged.

use eyehand::experiment::{declarations, docs_table, Config, Rule, Scope, Source, TREE_LINES_FILE};
use std::path::{Path, PathBuf};
use std::process::{Command, Output};

const ROOT: &str = env!("CARGO_MANIFEST_DIR");

fn eyehand(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_eyehand"))
        .args(args)
        .output()
        .unwrap()
}

fn text(bytes: &[u8]) -> String {
    String::from_utf8_lossy(bytes).into_owned()
}

#[test]
fn every_declared_default_meets_its_rules_and_every_rule_is_on_a_number() {
    assert_eq!(Config::default_config().check(), Ok(()));
    for declaration in declarations() {
        if declaration.rule != Rule::Any {
            let default = declaration.default.as_deref().unwrap();
            assert!(
                default.parse::<f64>().is_ok(),
                "{}: a rule on a value that is not a number ({default})",
                declaration.name
            );
        }
        assert!(
            !declaration.doc.is_empty(),
            "{} has a doc line",
            declaration.name
        );
    }
}

/// docs/CONFIG.md's text before its table, the table (between its markers) and after.
fn documented_table(doc: &str) -> Option<(&str, &str, &str)> {
    let start = doc.find("<!-- entries -->\n")? + "<!-- entries -->\n".len();
    let end = doc.find("<!-- /entries -->")?;
    Some((doc.get(..start)?, doc.get(start..end)?, doc.get(end..)?))
}

#[test]
fn the_docs_table_is_the_declarations() {
    let path = Path::new(ROOT).join("docs/CONFIG.md");
    let doc = std::fs::read_to_string(&path).expect("docs/CONFIG.md");
    let (before, table, after) =
        documented_table(&doc).expect("docs/CONFIG.md has <!-- entries --> markers");
    if std::env::var_os("EYEHAND_BLESS").is_some() {
        std::fs::write(&path, format!("{before}{}{after}", docs_table())).unwrap();
        return;
    }
    assert_eq!(
        table,
        docs_table(),
        "docs/CONFIG.md disagrees with the declarations \
         (EYEHAND_BLESS=1 cargo test --test config_declarations writes it anew)"
    );
}

#[test]
fn config_defaults_prints_a_complete_config_that_parses_to_the_defaults() {
    let out = eyehand(&["config", "defaults"]);
    assert!(out.status.success(), "{}", text(&out.stderr));
    let printed = text(&out.stdout);
    assert_eq!(
        Config::parse(&printed, "defaults"),
        Ok(Config::default_config())
    );
    assert!(printed.contains("\ntree_depth"), "{printed}");
    assert!(
        printed.contains("[lin5 lin8 nnw; must be 1 to 12]"),
        "{printed}"
    );
    assert!(printed.contains("# obstacle"), "{printed}");
}

/// The entries of the study's appendix A.2 config listing, as the study prints them (its
/// comments left out), committed under tests/data.
fn study_listing() -> String {
    let listing = Path::new(ROOT).join("tests/data/study_a2_entries.conf");
    std::fs::read_to_string(&listing)
        .unwrap_or_else(|e| panic!("the study's listing at {}: {e}", listing.display()))
}

#[test]
fn the_study_listing_as_printed_is_configs_study_conf() {
    let listing = study_listing();
    let given = listing
        .lines()
        .filter(|l| !l.trim().is_empty() && !l.trim_start().starts_with('#'))
        .count();
    assert_eq!(given, 42, "the listing gives 42 entries");
    let (config, sources) = Config::read(&listing, "A.2").unwrap_or_else(|e| panic!("{e}"));
    let shipped = Config::from_file(&Path::new(ROOT).join("configs/study.conf")).unwrap();
    assert_eq!(config, shipped);
    assert_eq!(config.rotate_trial, 1500);
    assert_eq!(config.rotate_degrees, 90.0);
    assert_eq!(config.am_error_tresh, 5.0);
    assert!(matches!(
        sources.of("split_extension"),
        Some(Source::Line { .. })
    ));
    let unused: Vec<&str> = declarations()
        .into_iter()
        .filter(|d| d.scope == Scope::Unused)
        .map(|d| d.name)
        .collect();
    assert_eq!(unused, ["split_extension"]);
}

#[test]
fn check_config_notes_the_unused_entry_and_explains_every_source() {
    let study = format!("{ROOT}/configs/study.conf");
    let out = eyehand(&["check-config", &study, "--explain"]);
    assert!(out.status.success(), "{}", text(&out.stderr));
    let printed = text(&out.stdout);
    assert!(
        printed.contains("note: ") && printed.contains("split_extension is accepted"),
        "{printed}"
    );
    let line_of = |name: &str| {
        printed
            .lines()
            .find(|l| l.split_whitespace().next() == Some(name))
            .unwrap_or_else(|| panic!("{name} in {printed}"))
            .to_string()
    };
    assert!(line_of("trials").ends_with("# default"), "{printed}");
    assert!(line_of("rotate_trial").contains("study.conf:"), "{printed}");
    assert!(
        line_of("split_extension").ends_with(", unused"),
        "{printed}"
    );
    assert!(printed.ends_with("study.conf: ok\n"), "{printed}");
}

/// The run folder a finished `eyehand run` printed.
fn run_folder(out: &Output) -> PathBuf {
    assert!(out.status.success(), "{}", text(&out.stderr));
    let stdout = text(&out.stdout);
    let folder = stdout.lines().next().expect("the folder's line");
    PathBuf::from(folder.trim())
}

#[test]
fn a_two_line_config_runs_and_info_says_where_every_value_came_from() {
    let dir = tempfile::tempdir().unwrap();
    let conf = dir.path().join("two.conf");
    std::fs::write(&conf, "method lin8\ntrials 500\n").unwrap();
    let data = dir.path().join("data");
    let out = eyehand(&[
        "run",
        "--config",
        conf.to_str().unwrap(),
        "--data",
        data.to_str().unwrap(),
        "--seed",
        "3",
        "--set",
        "tree_depth=6",
        "--quiet",
        "--no-plot",
    ]);
    let folder = run_folder(&out);
    assert!(
        folder.starts_with(data.join("lin8")),
        "{}",
        folder.display()
    );
    let info = std::fs::read_to_string(folder.join("info")).unwrap();
    let line_of = |name: &str| {
        info.lines()
            .find(|l| l.split_whitespace().next() == Some(name))
            .unwrap_or_else(|| panic!("{name} in {info}"))
    };
    assert!(line_of("method").contains("two.conf:1"), "{info}");
    assert!(line_of("trials").contains("two.conf:2"), "{info}");
    assert!(line_of("seed").ends_with("# --seed"), "{info}");
    assert!(line_of("tree_depth").ends_with("# --set"), "{info}");
    assert!(line_of("split_error").ends_with("# default"), "{info}");
    let nodes = std::fs::read_to_string(folder.join("nodes")).unwrap();
    assert_eq!(nodes.lines().count(), 500, "a line per finished trial");
}

/// The distances after step `step` of a run folder's trials `range` (mm).
fn distances(folder: &Path, step: usize, range: std::ops::Range<usize>) -> Vec<f64> {
    let text = std::fs::read_to_string(folder.join(format!("{step}step"))).unwrap();
    text.lines()
        .filter_map(|l| {
            let mut fields = l.split_whitespace();
            let trial: usize = fields.next()?.parse().ok()?;
            let distance: f64 = fields.next()?.parse().ok()?;
            range.contains(&trial).then_some(distance)
        })
        .collect()
}

fn mean(values: &[f64]) -> f64 {
    values.iter().sum::<f64>() / values.len() as f64
}

/// `eyehand run --config configs/study.conf --trials TRIALS` with `sets`.
fn study_run(data: &Path, trials: &str, sets: &[&str]) -> Output {
    let study = format!("{ROOT}/configs/study.conf");
    let mut args = vec!["run", "--config", &study, "--trials", trials, "--no-plot"];
    args.extend(["--data", data.to_str().unwrap()]);
    for set in sets {
        args.extend(["--set", set]);
    }
    eyehand(&args)
}

#[test]
fn the_study_config_runs_cuts_its_root_once_after_the_turn_and_logs_its_tree_to_a_file() {
    let dir = tempfile::tempdir().unwrap();
    let out = study_run(dir.path(), "2000", &[]);
    let folder = run_folder(&out);
    let info = std::fs::read_to_string(folder.join("info")).unwrap();
    assert!(info.contains("\nevent rotate:1500:90"), "{info}");
    assert!(std::fs::metadata(folder.join("pat_file")).unwrap().len() > 0);
    let summary = std::fs::read_to_string(folder.join("summary.json")).unwrap();
    let summary: serde_json::Value = serde_json::from_str(&summary).unwrap();
    assert_eq!(summary["root_merges"].as_u64(), Some(1), "{summary}");
    let stderr = text(&out.stderr);
    assert!(
        !stderr.contains("trial 5: "),
        "no terminal, no tree lines: {stderr}"
    );
    assert!(!stderr.contains("cut at its root"), "{stderr}");
    let lines = std::fs::read_to_string(folder.join(TREE_LINES_FILE)).unwrap();
    assert!(
        lines.starts_with("trial 5: ") && lines.lines().count() == 2000 / 5,
        "verbose_output 1 logs the tree every depth_info trials: {lines}"
    );
}

#[test]
fn the_study_config_learns_and_turns_the_camera_at_trial_1500_with_merges_that_hold() {
    let dir = tempfile::tempdir().unwrap();
    // Nothing cuts the root after the turn: the run ends soon after it, before the arm,
    // still lost, is judged to have learned nothing.
    let out = study_run(
        dir.path(),
        "1520",
        &["am_error_tresh=20", "am_error_iters=300"],
    );
    let folder = run_folder(&out);
    assert!(!text(&out.stderr).contains("cut at its root"));
    let early = mean(&distances(&folder, 4, 1..101));
    let before = mean(&distances(&folder, 4, 1400..1500));
    let after = mean(&distances(&folder, 4, 1500..1520));
    assert!(
        before < early / 5.0,
        "it learns: {early} mm, then {before} mm"
    );
    assert!(
        after > 2.0 * before,
        "the turn shows: {before} mm, then {after} mm"
    );
}

#[test]
fn run_method_lin8_without_a_config_records_lin8s_values() {
    let dir = tempfile::tempdir().unwrap();
    let data = dir.path().to_str().unwrap();
    let out = eyehand(&[
        "run",
        "--method",
        "lin8",
        "--trials",
        "20",
        "--data",
        data,
        "--quiet",
        "--no-plot",
    ]);
    let folder = run_folder(&out);
    let info = std::fs::read_to_string(folder.join("info")).unwrap();
    // Its own entry at the entry's default, and a shared one at lin8's own default.
    for (value, source) in [
        ("error_area_shrink 0.5 ", "# default"),
        ("change_fit_patterns 600 ", "# lin8's default"),
    ] {
        let name = value.split(' ').next().unwrap();
        let line = info.lines().find(|l| l.starts_with(name)).unwrap();
        assert!(line.starts_with(value) && line.ends_with(source), "{line}");
    }
    let compared = Config::from_file(&Path::new(ROOT).join("configs/lin8.conf")).unwrap();
    assert_eq!(
        compared.error_area_shrink, 0.5,
        "compare's lin8 row runs the same"
    );
    assert!(info.contains("\nconfig_file defaults\n"), "{info}");
}
