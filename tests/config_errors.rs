//! The config file format: every error kind stops with `file:line: reason`, and every
//! shipped config parses.

use eyehand::experiment::{Config, ENTRY_NAMES};
use std::process::Command;

fn shipped() -> String {
    std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/configs/lin5.conf")).unwrap()
}

/// The shipped config with the line holding `name` replaced by `replacement`.
fn with_line(name: &str, replacement: &str) -> (String, usize) {
    let text = shipped();
    let line = text
        .lines()
        .position(|l| l.split_whitespace().next() == Some(name))
        .unwrap_or_else(|| panic!("{name} not in the config"));
    let lines: Vec<&str> = text
        .lines()
        .enumerate()
        .map(|(i, l)| if i == line { replacement } else { l })
        .collect();
    (lines.join("\n"), line + 1)
}

#[test]
fn every_shipped_config_parses() {
    let dir = concat!(env!("CARGO_MANIFEST_DIR"), "/configs");
    let mut count = 0;
    for entry in std::fs::read_dir(dir).unwrap() {
        let path = entry.unwrap().path();
        if path.extension().is_some_and(|e| e == "conf") {
            let config = Config::from_file(&path).unwrap_or_else(|e| panic!("{e}"));
            let stem = path.file_stem().unwrap().to_str().unwrap();
            assert_eq!(
                config.method.name(),
                stem,
                "{} names its method",
                path.display()
            );
            count += 1;
        }
    }
    assert!(count >= 4, "lin5, lin8, nnw and ik configs ship");
}

#[test]
fn every_entry_is_in_the_shipped_config_once() {
    let text = shipped();
    for name in ENTRY_NAMES {
        let n = text
            .lines()
            .filter(|l| l.split_whitespace().next() == Some(name))
            .count();
        assert_eq!(n, 1, "{name}");
    }
}

#[test]
fn an_unknown_name_is_reported_at_its_line() {
    let (text, line) = with_line("split_error", "split_eror 0.0001");
    let err = Config::parse(&text, "x.conf").unwrap_err();
    assert_eq!(err.line, line);
    assert!(
        err.to_string()
            .starts_with(&format!("x.conf:{line}: unknown entry `split_eror`")),
        "{err}"
    );
}

#[test]
fn a_name_given_twice_is_reported_at_the_second() {
    let text = shipped() + "\ntree_depth 6\n";
    let last = text.lines().count();
    let err = Config::parse(&text, "x.conf").unwrap_err();
    assert_eq!(err.line, last);
    assert!(
        err.reason
            .contains("`tree_depth` is given twice (first on line"),
        "{err}"
    );
}

#[test]
fn a_missing_name_is_reported() {
    let (text, _) = with_line("monitor_ave", "# monitor_ave removed");
    let err = Config::parse(&text, "x.conf").unwrap_err();
    assert_eq!(err.line, text.lines().count());
    assert_eq!(err.reason, "missing entries: monitor_ave");
}

#[test]
fn a_real_number_for_an_integer_is_reported() {
    let (text, line) = with_line("feedback_steps", "feedback_steps 10.5");
    let err = Config::parse(&text, "x.conf").unwrap_err();
    assert_eq!(err.line, line);
    assert!(
        err.reason
            .contains("real number, but this entry takes an integer"),
        "{err}"
    );
}

#[test]
fn bad_values_and_bad_lines_are_reported() {
    for (name, replacement, why) in [
        ("split_error", "split_error abc", "not a finite real number"),
        ("method", "method lin9", "unknown method `lin9`"),
        ("sim", "sim rapier", "unknown simulator"),
        ("tree_depth", "tree_depth 0", "tree_depth: must be 1 to 12"),
        (
            "boundary_2_high",
            "boundary_2_high -600",
            "must be above boundary_2_low",
        ),
        (
            "min_feedback_steps",
            "min_feedback_steps 11",
            "must not exceed feedback_steps",
        ),
        ("seed", "seed", "expected `name value`"),
        ("trials", "trials 5 6", "expected `name value`"),
    ] {
        let (text, line) = with_line(name, replacement);
        let err = Config::parse(&text, "x.conf").unwrap_err();
        assert_eq!(err.line, line, "{replacement}: {err}");
        assert!(err.reason.contains(why), "{replacement}: {err}");
    }
}

#[test]
fn comments_blank_lines_and_any_order_are_fine() {
    let mut lines: Vec<String> = shipped().lines().map(str::to_string).collect();
    lines.reverse();
    lines.push("   # a comment".into());
    lines.push(String::new());
    let config = Config::parse(&lines.join("\n"), "x.conf").unwrap();
    assert_eq!(config, Config::default_config());
}

#[test]
fn overrides_are_checked_like_config_lines() {
    let mut config = Config::default_config();
    config.set("split_error", "1e-5").unwrap();
    assert_eq!(config.split_error, 1e-5);
    assert!(config
        .set("tree_depth", "2.5")
        .unwrap_err()
        .contains("real number"));
    assert!(config
        .set("no_such", "1")
        .unwrap_err()
        .contains("unknown entry"));
}

#[test]
fn check_config_exits_2_with_file_and_line() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("bad.conf");
    let (text, line) = with_line("bin_size", "bin_size 2.5");
    std::fs::write(&path, text).unwrap();
    let out = Command::new(env!("CARGO_BIN_EXE_eyehand"))
        .arg("check-config")
        .arg(&path)
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(
        stderr.contains(&format!("bad.conf:{line}: bin_size:")),
        "{stderr}"
    );
    let good = concat!(env!("CARGO_MANIFEST_DIR"), "/configs/lin8.conf");
    let out = Command::new(env!("CARGO_BIN_EXE_eyehand"))
        .args(["check-config", good])
        .output()
        .unwrap();
    assert!(out.status.success());
}
