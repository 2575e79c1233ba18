//! The config file format: every error kind stops with `file:line: reason` and is matched
//! here by its kind, at the line of the complete default config it was put on; every
//! shipped config parses.

use eyehand::experiment::{
    declarations, Config, ConfigErrorKind, Scope, Source, ValueError, ENTRY_NAMES,
};
use eyehand::learn::Method;
use std::process::Command;

/// The complete config at its defaults (`eyehand config defaults`).
fn shipped() -> String {
    eyehand::experiment::defaults_text()
}

/// The mark beside an entry the complete default config leaves commented out because some
/// methods have their own default for it.
const METHODS_OWN: &str = "(methods' own: ";

/// Whether `line` of the complete default config is entry `name`'s left commented out.
fn commented_entry(line: &str, name: &str) -> bool {
    let rest = line.strip_prefix("# ").unwrap_or("");
    rest.split_whitespace().next() == Some(name) && line.contains(METHODS_OWN)
}

/// The complete default config with the line holding `name` (or, for an entry some
/// methods have their own default for, its commented line) replaced by `replacement`.
fn with_line(name: &str, replacement: &str) -> (String, usize) {
    let text = shipped();
    let line = text
        .lines()
        .position(|l| l.split_whitespace().next() == Some(name) || commented_entry(l, name))
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
            if stem != "study" {
                assert_eq!(
                    config.method.name(),
                    stem,
                    "{} names its method",
                    path.display()
                );
            }
            count += 1;
        }
    }
    assert!(count >= 10, "every method's config and the study's ship");
}

#[test]
fn every_entry_is_in_the_complete_default_config_once() {
    let text = shipped();
    let unused = |name: &str| {
        declarations()
            .iter()
            .any(|d| d.name == name && d.scope == Scope::Unused)
    };
    let methods_own = |name: &str| {
        Method::ALL
            .iter()
            .any(|m| m.facts().shared_defaults.iter().any(|(n, _)| *n == name))
    };
    for name in ENTRY_NAMES.iter().filter(|n| !unused(n)) {
        let given = text
            .lines()
            .filter(|l| l.split_whitespace().next() == Some(name))
            .count();
        let commented = text.lines().filter(|l| commented_entry(l, name)).count();
        let expected = if methods_own(name) { (0, 1) } else { (1, 0) };
        assert_eq!((given, commented), expected, "{name}: given, commented");
    }
    assert_eq!(Config::parse(&text, "x.conf"), Ok(Config::default_config()));
}

#[test]
fn an_unknown_name_is_reported_at_its_line() {
    let (text, line) = with_line("split_error", "split_eror 0.0001");
    let err = Config::parse(&text, "x.conf").unwrap_err();
    assert_eq!(err.line, Some(line));
    assert_eq!(
        err.kind,
        ConfigErrorKind::UnknownEntry {
            name: "split_eror".into()
        }
    );
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
    assert_eq!(err.line, Some(last));
    assert!(
        matches!(
            err.kind,
            ConfigErrorKind::Repeated {
                name: "tree_depth",
                first_line
            } if first_line < last
        ),
        "{err}"
    );
}

#[test]
fn a_missing_name_takes_its_default() {
    let (text, _) = with_line("monitor_ave", "# monitor_ave removed");
    let (config, sources) = Config::read(&text, "x.conf").unwrap();
    assert_eq!(config, Config::default_config());
    assert_eq!(sources.of("monitor_ave"), None);
    assert!(matches!(
        sources.of("tree_depth"),
        Some(Source::Line { .. })
    ));
    let text = config.explained_text(&sources);
    let line = text
        .lines()
        .find(|l| l.starts_with("monitor_ave "))
        .unwrap();
    assert!(line.ends_with("# default"), "{line}");
}

#[test]
fn a_real_number_for_an_integer_is_reported() {
    let (text, line) = with_line("feedback_steps", "feedback_steps 10.5");
    let err = Config::parse(&text, "x.conf").unwrap_err();
    assert_eq!(err.line, Some(line));
    assert_eq!(
        err.kind,
        ConfigErrorKind::BadValue {
            name: "feedback_steps",
            problem: ValueError::RealForInteger("10.5".into())
        }
    );
}

/// Which kind of error a replaced line gives, for the table below.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Expected {
    BadValue,
    OutOfRange,
    NotNameValue,
    EventAfterLastTrial,
    TooMuchMemory,
}

fn expected_kind(kind: &ConfigErrorKind) -> Option<Expected> {
    Some(match kind {
        ConfigErrorKind::BadValue { .. } => Expected::BadValue,
        ConfigErrorKind::OutOfRange { .. } => Expected::OutOfRange,
        ConfigErrorKind::NotNameValue { .. } => Expected::NotNameValue,
        ConfigErrorKind::EventAfterLastTrial { .. } => Expected::EventAfterLastTrial,
        ConfigErrorKind::TooMuchMemory { .. } => Expected::TooMuchMemory,
        _ => return None,
    })
}

#[test]
fn bad_values_and_bad_lines_are_reported() {
    use Expected::*;
    for (name, replacement, kind) in [
        ("split_error", "split_error abc", BadValue),
        ("method", "method lin9", BadValue),
        ("sim", "sim rapier", BadValue),
        ("tree_depth", "tree_depth 0", OutOfRange),
        ("boundary_2_high", "boundary_2_high -600", OutOfRange),
        ("min_feedback_steps", "min_feedback_steps 11", OutOfRange),
        ("seed", "seed", NotNameValue),
        ("trials", "trials 5 6", NotNameValue),
        ("split_error", "split_error -1", OutOfRange),
        ("min_pats_for_split", "min_pats_for_split 0", OutOfRange),
        ("am_error_tresh", "am_error_tresh -1", OutOfRange),
        ("merge_error", "merge_error -5", OutOfRange),
        ("min_target_distance", "min_target_distance 1e9", OutOfRange),
        ("minimal_joint_move", "minimal_joint_move 1e9", OutOfRange),
        ("bin_size", "bin_size 1000000000000", OutOfRange),
        ("robot_speed", "robot_speed 1e300", OutOfRange),
        ("feedback_steps", "feedback_steps 1000000", OutOfRange),
        (
            "feedback_steps",
            "feedback_steps 1000000000000",
            TooMuchMemory,
        ),
        ("monitor_ave", "monitor_ave 1000000000000", TooMuchMemory),
        (
            "am_error_iters",
            "am_error_iters 1000000000000",
            TooMuchMemory,
        ),
        ("ffn_window", "ffn_window 1000000000000", TooMuchMemory),
        ("hidden_units", "hidden_units 100000000000", TooMuchMemory),
        (
            "ffn_hidden_units",
            "ffn_hidden_units 100000000000",
            TooMuchMemory,
        ),
        ("issgp_features", "issgp_features 0", OutOfRange),
        ("issgp_features", "issgp_features -5", OutOfRange),
        ("issgp_noise", "issgp_noise -0.1", OutOfRange),
        ("issgp_noise", "issgp_noise 0", OutOfRange),
        ("issgp_signal", "issgp_signal 0", OutOfRange),
        ("issgp_forgetting", "issgp_forgetting 1.5", OutOfRange),
        (
            "issgp_length_scales",
            "issgp_length_scales 0.5,0.5,0,0.5,0.5",
            OutOfRange,
        ),
        (
            "issgp_length_scales",
            "issgp_length_scales 0.5,0.5",
            BadValue,
        ),
        ("mlp_buffer", "mlp_buffer 0", OutOfRange),
        ("mlp_batch", "mlp_batch 0", OutOfRange),
        ("mlp_hidden", "mlp_hidden 0", OutOfRange),
        ("mlp_rate", "mlp_rate -0.001", OutOfRange),
        ("mlp_steps_per_trial", "mlp_steps_per_trial 0", OutOfRange),
        ("rotate_trial", "rotate_trial 20000", EventAfterLastTrial),
        (
            "elongate_trial",
            "elongate_trial 10001",
            EventAfterLastTrial,
        ),
    ] {
        let (text, line) = with_line(name, replacement);
        let err = Config::parse(&text, "x.conf").unwrap_err();
        assert_eq!(err.line, Some(line), "{replacement}: {err}");
        assert_eq!(expected_kind(&err.kind), Some(kind), "{replacement}: {err}");
        assert_eq!(
            err.kind.entry(),
            (kind != NotNameValue).then_some(name),
            "{replacement}: {err}"
        );
        assert!(
            err.to_string().starts_with(&format!("x.conf:{line}: ")),
            "{replacement}: {err}"
        );
    }
}

#[test]
fn a_byte_order_mark_is_skipped_and_a_huge_value_is_cut_short() {
    let text = format!("\u{feff}{}", shipped());
    assert_eq!(
        Config::parse(&text, "x.conf").unwrap(),
        Config::default_config()
    );
    let huge = "7".repeat(1_000_000);
    let (text, _) = with_line("seed", &format!("seed {huge}"));
    let message = Config::parse(&text, "x.conf").unwrap_err().to_string();
    assert!(message.len() < 200, "{} characters", message.len());
    assert!(message.contains("(1000000 characters)"), "{message}");
}

#[test]
fn an_unreadable_file_is_named_without_a_line() {
    let err = Config::from_file(std::path::Path::new("/no/such.conf")).unwrap_err();
    assert_eq!(err.line, None);
    assert!(matches!(err.kind, ConfigErrorKind::Unreadable { .. }));
    assert!(
        err.to_string().starts_with("/no/such.conf: cannot read"),
        "{err}"
    );
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
    assert!(matches!(
        config.set("tree_depth", "2.5"),
        Err(ConfigErrorKind::BadValue {
            name: "tree_depth",
            problem: ValueError::RealForInteger(_)
        })
    ));
    assert!(matches!(
        config.set("no_such", "1"),
        Err(ConfigErrorKind::UnknownEntry { .. })
    ));
}

#[test]
fn values_set_together_are_checked_together_in_any_order() {
    let mut config = Config::default_config();
    assert!(config.set("feedback_steps", "2").is_err());
    for order in [
        [("feedback_steps", "2"), ("min_feedback_steps", "1")],
        [("min_feedback_steps", "1"), ("feedback_steps", "2")],
    ] {
        let mut config = Config::default_config();
        for (name, value) in order {
            config.assign(name, value).unwrap();
        }
        assert_eq!(config.check(), Ok(()));
    }
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
