//! The replay test: a pattern stream recorded from a run of this task (7,222 patterns),
//! trained pattern by pattern, gives the reference LWPR library's field counts after
//! every pattern exactly and its predictions (after every 5th, at the next pattern's
//! input) to 1e-6°. The fixture in `tests/data/lwpr_reference/` was made once by
//! `tools/lwpr_reference.sh` (the stream by `examples/lwpr_patterns.rs`, the library's
//! answers by `tools/lwpr_reference_driver.c`).

use super::projection::Input;
use super::{Lwpr, LwprSettings};
use nalgebra::Vector3;
use std::path::PathBuf;

/// How far an answer may be from the library's (degrees).
const TOLERANCE_DEG: f64 = 1e-6;

/// The recorded stream: input boundaries, `norm_out` and the patterns.
struct Stream {
    bounds: [(f64, f64); 5],
    norm_out: f64,
    patterns: Vec<(Input, Vector3<f64>)>,
}

/// What the library gave after one pattern: field counts and, after every 5th, the
/// answers at the next pattern's input (`None`: no trusted field there).
struct LibraryStep {
    fields: [usize; 3],
    answers: Option<[Option<f64>; 3]>,
}

fn fixture(name: &str) -> String {
    let path: PathBuf = [
        env!("CARGO_MANIFEST_DIR"),
        "tests/data/lwpr_reference",
        name,
    ]
    .iter()
    .collect();
    std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

fn numbers(text: &str) -> Vec<f64> {
    text.split_whitespace()
        .map(|v| v.parse().expect("a number"))
        .collect()
}

fn stream() -> Stream {
    let text = fixture("stream.txt");
    let mut stream = Stream {
        bounds: [(0.0, 0.0); 5],
        norm_out: 0.0,
        patterns: Vec::new(),
    };
    for line in text.lines() {
        if let Some(rest) = line.strip_prefix("bounds ") {
            let b = numbers(rest);
            stream.bounds = std::array::from_fn(|i| (b[2 * i], b[2 * i + 1]));
        } else if let Some(rest) = line.strip_prefix("norm_out ") {
            stream.norm_out = rest.trim().parse().expect("norm_out");
        } else if let Some(rest) = line.strip_prefix("p ") {
            let v = numbers(rest);
            let x = Input::from_fn(|i, _| v[i]);
            stream.patterns.push((x, Vector3::new(v[5], v[6], v[7])));
        }
    }
    stream
}

fn library_steps(name: &str) -> Vec<LibraryStep> {
    fixture(name)
        .lines()
        .map(|line| {
            let words: Vec<&str> = line.split_whitespace().collect();
            assert_eq!(words[0], "n", "{line}");
            let fields = std::array::from_fn(|i| words[1 + i].parse().expect("a count"));
            let answers = (words.len() > 4).then(|| {
                std::array::from_fn(|i| match words[4 + i] {
                    "-" => None,
                    v => Some(v.parse().expect("an answer")),
                })
            });
            LibraryStep { fields, answers }
        })
        .collect()
}

/// Replays the stream with `settings` against the library's steps in `name`; returns the
/// number of answers compared.
fn replay(settings: LwprSettings, name: &str) -> usize {
    let stream = stream();
    let steps = library_steps(name);
    assert_eq!(steps.len(), stream.patterns.len(), "a step per pattern");
    let settings = LwprSettings {
        norm_out: stream.norm_out,
        ..settings
    };
    let mut lwpr = Lwpr::new(settings, stream.bounds);
    let mut compared = 0;
    for (k, ((x, target), step)) in stream.patterns.iter().zip(&steps).enumerate() {
        lwpr.train(x, target);
        assert_eq!(lwpr.fields(), step.fields, "fields after pattern {k}");
        let Some(expected) = step.answers else {
            continue;
        };
        let answers = lwpr.answer_trusted(&stream.patterns[k + 1].0);
        for (i, (ours, theirs)) in answers.iter().zip(expected).enumerate() {
            match (ours, theirs) {
                (Some(a), Some(b)) => {
                    assert!(
                        (a - b).abs() <= TOLERANCE_DEG,
                        "output {i} after pattern {k}: {a} against the library's {b}"
                    );
                    compared += 1;
                }
                (None, None) => {}
                _ => panic!("output {i} after pattern {k}: {ours:?} against {theirs:?}"),
            }
        }
    }
    compared
}

#[test]
fn the_library_defaults_replay_to_the_reference_library() {
    let compared = replay(LwprSettings::default(), "defaults.txt");
    assert!(compared > 4_000, "{compared} answers compared");
}

#[test]
fn narrow_kernels_replay_to_the_reference_library() {
    let settings = LwprSettings {
        init_d: 200.0,
        w_gen: 0.2,
        ..LwprSettings::default()
    };
    let compared = replay(settings, "init_D_200_w_gen_0.2.txt");
    assert!(compared > 4_000, "{compared} answers compared");
}
