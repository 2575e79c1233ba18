//! A seeded fuzz over the config: short runs with one entry at a value drawn within its
//! rule, at its bounds or just outside them. Each must be refused before its folder is made,
//! fail with a reason (`"learned": false`, or an error), or learn; none may write a number
//! that is not finite, and none may run longer than its bound.

use eyehand::experiment::{
    declarations, run, Config, Declaration, NotLearnedKind, Rule, RunOptions, Scope, SimKind,
};
use eyehand::learn::Method;
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use std::collections::BTreeMap;
use std::path::Path;
use std::time::{Duration, Instant};

/// Cases drawn.
const CASES: usize = 160;
/// Trials of a kinematic run, and of a dynamic one.
const TRIALS: usize = 20;
const DYNAMIC_TRIALS: usize = 6;
/// Trials of an `mlp` or `ffn` run: their entries may set a trial's learning up to the
/// cost bound (about 10⁹ multiply-adds for mlp, a second or two here), which 20 trials of
/// would take past [`RUN_BOUND`] without hanging.
const COSTLY_TRIALS: usize = 8;
/// The longest a short run may take: a guard against a hang, not a speed goal (speeds are
/// measured in the benches). The costliest case (mlp at its cost bound, 8 trials) takes
/// about 15 s alone and over 30 s on two cores shared with other builds.
const RUN_BOUND: Duration = Duration::from_secs(120);

/// How a case ended.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
enum Outcome {
    RefusedUpFront,
    FailedWithReason,
    Learned,
}

/// The bounds of a rule (low, high), open ends at ±∞.
fn bounds(rule: Rule) -> Option<(f64, f64)> {
    match rule {
        Rule::Any => None,
        Rule::Within(low, high) => Some((low, high)),
        Rule::PositiveUpTo(high) => Some((0.0, high)),
        Rule::Positive | Rule::NonNegative => Some((0.0, f64::INFINITY)),
        Rule::AtLeast(low) => Some((low, f64::INFINITY)),
        Rule::OpenUnit | Rule::UnitBelowOne => Some((0.0, 1.0)),
    }
}

/// A value for `declaration`: a bound, just outside one, or inside.
fn draw_value(declaration: &Declaration, rng: &mut ChaCha8Rng) -> Option<String> {
    let (low, high) = bounds(declaration.rule)?;
    let integer = declaration.kind == "integer";
    let step = |bound: f64| {
        if integer {
            1.0
        } else {
            (bound.abs() * 1e-6).max(1e-9)
        }
    };
    let top = if high.is_finite() {
        high
    } else {
        low.abs().max(1.0) * 1e3
    };
    let value = match rng.random_range(0..5) {
        0 => low,
        1 => low - step(low),
        2 if high.is_finite() => high,
        3 if high.is_finite() => high + step(high),
        _ => low + (top - low) * rng.random::<f64>().powi(3),
    };
    Some(if integer {
        format!("{}", value.round() as i64)
    } else {
        format!("{value}")
    })
}

/// The default config with `name` at `value`, on a method and simulator the entry applies
/// to; `None` when the value is refused as it is set.
fn config_with(declaration: &Declaration, value: &str) -> Option<Config> {
    let mut config = Config::default_config();
    config.trials = TRIALS;
    match declaration.scope {
        Scope::Methods(methods) => {
            config.method = methods[0];
            if matches!(config.method, Method::Mlp | Method::Ffn) {
                config.trials = COSTLY_TRIALS;
            }
        }
        Scope::Sim(SimKind::Dynamic) => {
            config.sim = SimKind::Dynamic;
            config.trials = DYNAMIC_TRIALS;
        }
        Scope::Camera(camera) => config.camera = camera,
        _ => {}
    }
    config.set(declaration.name, value).ok()?;
    Some(config)
}

/// The first word of a file in `folder` that reads as a number but is not finite.
fn non_finite_word(folder: &Path) -> Option<String> {
    for entry in std::fs::read_dir(folder).ok()?.flatten() {
        let path = entry.path();
        let Ok(text) = std::fs::read_to_string(&path) else {
            continue; // plot.png and binary pattern files
        };
        let bad = text
            .split(|c: char| c.is_whitespace() || ",[]:".contains(c))
            .find(|w| w.parse::<f64>().is_ok_and(|v| !v.is_finite()));
        if let Some(word) = bad {
            return Some(format!("{}: {word}", path.display()));
        }
    }
    None
}

/// Runs one case and says how it ended.
fn run_case(name: &str, value: &str, config: Config, data: &Path) -> Outcome {
    match run(&RunOptions::new(config, data)) {
        Err(e) if e.refused_before_work() => Outcome::RefusedUpFront,
        Err(e) => {
            assert!(
                !e.to_string().is_empty(),
                "{name} {value}: an error says why"
            );
            println!("failed: {name} {value}: {e}");
            Outcome::FailedWithReason
        }
        Ok(result) => {
            if let Some(word) = non_finite_word(&result.folder) {
                panic!("{name} {value}: a number that is not finite: {word}");
            }
            let summary = result.summary;
            assert_eq!(
                summary.learned,
                summary.not_learned.is_none(),
                "{name} {value}"
            );
            match summary.not_learned {
                Some(why) => {
                    assert!(!why.reason.is_empty(), "{name} {value}");
                    println!("failed: {name} {value}: {}", why.reason);
                    Outcome::FailedWithReason
                }
                None => {
                    assert!(
                        summary.mean_final_distance_mm.is_some_and(f64::is_finite),
                        "{name} {value}: a run that learned has finite distances over its window"
                    );
                    Outcome::Learned
                }
            }
        }
    }
}

#[test]
fn configs_at_and_beyond_every_bound_are_refused_fail_with_a_reason_or_learn() {
    let entries: Vec<Declaration> = declarations()
        .into_iter()
        .filter(|d| d.scope != Scope::Unused && d.name != "trials" && d.name != "seed")
        .filter(|d| bounds(d.rule).is_some())
        .collect();
    let mut rng = ChaCha8Rng::seed_from_u64(32);
    let data = tempfile::tempdir().unwrap();
    let mut counts: BTreeMap<Outcome, usize> = BTreeMap::new();
    let mut slow = Vec::new();
    for case in 0..CASES {
        let declaration = &entries[rng.random_range(0..entries.len())];
        let Some(value) = draw_value(declaration, &mut rng) else {
            continue;
        };
        let started = Instant::now();
        let outcome = match config_with(declaration, &value) {
            None => Outcome::RefusedUpFront,
            Some(config) => {
                let folder = data.path().join(case.to_string());
                run_case(declaration.name, &value, config, &folder)
            }
        };
        let took = started.elapsed();
        if took > RUN_BOUND / 10 {
            slow.push((took, format!("{} {value}", declaration.name)));
        }
        *counts.entry(outcome).or_default() += 1;
    }
    println!("| outcome | cases |\n|---|---|");
    for (outcome, count) in &counts {
        println!("| {outcome:?} | {count} |");
    }
    println!("over {:?}: {slow:#?}", RUN_BOUND / 10);
    assert_eq!(counts.values().sum::<usize>(), CASES);
    assert!(
        slow.iter().all(|(took, _)| *took < RUN_BOUND),
        "runs over {RUN_BOUND:?}: {slow:?}"
    );
    for outcome in [Outcome::RefusedUpFront, Outcome::Learned] {
        assert!(
            counts.get(&outcome).is_some_and(|&n| n > 0),
            "{outcome:?} occurs"
        );
    }
}

/// The learners whose own entries are drawn in runs long enough for the verdict to judge
/// their last trials against their first (a window of 10 trials).
const JUDGED_METHODS: [Method; 4] = [Method::Issgp, Method::Mlp, Method::Ffn, Method::Lwpr];
/// Cases drawn per learner, and the trials of each.
const CASES_PER_LEARNER: usize = 10;
const JUDGED_TRIALS: usize = 100;

/// How a judged case ended: learned, or the kind of `not_learned` (or refused).
fn judged_case(declaration: &Declaration, value: &str, method: Method, data: &Path) -> String {
    let mut config = Config::default_config();
    config.method = method;
    config.trials = JUDGED_TRIALS;
    if config.set(declaration.name, value).is_err() {
        return "refused up front".into();
    }
    let changed = config
        .entries()
        .iter()
        .any(|(name, v)| *name == declaration.name && Some(v) != declaration.default.as_ref());
    let summary = match run(&RunOptions::new(config, data)) {
        Ok(result) => result.summary,
        Err(e) => return format!("failed: {e}"),
    };
    let case = format!("{method} {} {value}", declaration.name);
    match summary.not_learned {
        None => {
            let first = summary.mean_distance_mm[0].expect("a window trial took a step");
            let last = summary.mean_final_distance_mm.expect("and ended somewhere");
            assert!(
                last <= first,
                "{case}: learned, yet its last trials ended farther ({last} mm) than after their first step ({first} mm)"
            );
            "learned".into()
        }
        Some(why) => {
            println!("not learned: {case}: {}", why.reason);
            let judged = matches!(
                why.kind,
                NotLearnedKind::NoCloser | NotLearnedKind::LostAsOften
            );
            if judged && changed {
                assert!(
                    why.reason.contains(declaration.name),
                    "{case}: the reason names the entry: {}",
                    why.reason
                );
            }
            format!("{:?}", why.kind)
        }
    }
}

#[test]
fn each_learner_at_its_own_entries_bounds_learns_or_names_the_entry() {
    let mut rng = ChaCha8Rng::seed_from_u64(49);
    let data = tempfile::tempdir().unwrap();
    let mut counts: BTreeMap<(String, String), usize> = BTreeMap::new();
    for method in JUDGED_METHODS {
        let own: Vec<Declaration> = declarations()
            .into_iter()
            .filter(|d| matches!(d.scope, Scope::Methods(ms) if ms.contains(&method)))
            .filter(|d| bounds(d.rule).is_some())
            .collect();
        for case in 0..CASES_PER_LEARNER {
            let declaration = &own[rng.random_range(0..own.len())];
            let Some(value) = draw_value(declaration, &mut rng) else {
                continue;
            };
            let folder = data.path().join(format!("{method}{case}"));
            let outcome = judged_case(declaration, &value, method, &folder);
            *counts.entry((method.to_string(), outcome)).or_default() += 1;
        }
        // the learner at its defaults learns
        let started = Instant::now();
        let mut config = Config::default_config();
        config.method = method;
        config.trials = JUDGED_TRIALS;
        let summary = run(&RunOptions::new(
            config,
            data.path().join(method.to_string()),
        ))
        .unwrap()
        .summary;
        assert!(
            summary.learned,
            "{method} at its defaults: {:?}",
            summary.not_learned
        );
        println!("{method} at its defaults: {:?}", started.elapsed());
    }
    println!("| learner | outcome | cases |\n|---|---|---|");
    for ((method, outcome), count) in &counts {
        println!("| {method} | {outcome} | {count} |");
    }
}
