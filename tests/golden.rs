//! Golden runs: a short run of every method with its shipped config gives exactly the data
//! files it gave when the golden figures in `tests/data/golden.json` were recorded (minutes
//! and `mem` aside). A refactor must not change a byte; a change of results that is meant
//! is measured, written down, and recorded anew with `EYEHAND_BLESS=1 cargo test --test
//! golden`.

use eyehand::experiment::{run, Config, Event, RunOptions};
use eyehand::learn::{MergeStrategy, Method};
use serde_json::{json, Map, Value};
use std::path::{Path, PathBuf};

/// The data files whose bytes are checked (the minutes column stripped).
const DATA_FILES: [&str; 11] = [
    "1step", "2step", "3step", "4step", "5step", "nodes", "bins", "patterns", "abs_err", "merges",
    "changes",
];

/// One golden run: a name, a method, its trials and what else is set.
struct GoldenRun {
    name: &'static str,
    method: Method,
    trials: usize,
    change_detection: bool,
    events: &'static [&'static str],
}

const RUNS: [GoldenRun; 8] = [
    GoldenRun::plain("lin5", Method::Lin5, 600),
    GoldenRun::plain("lin8", Method::Lin8, 400),
    GoldenRun::plain("nnw", Method::Nnw, 40),
    GoldenRun::plain("ffn", Method::Ffn, 40),
    GoldenRun::plain("kohonen", Method::Kohonen, 500),
    GoldenRun::plain("ik", Method::Ik, 200),
    GoldenRun::plain("lwpr", Method::Lwpr, 300),
    GoldenRun {
        name: "lin5_change_detection",
        method: Method::Lin5,
        trials: 900,
        change_detection: true,
        events: &["rotate:500:30"],
    },
];

impl GoldenRun {
    const fn plain(name: &'static str, method: Method, trials: usize) -> GoldenRun {
        GoldenRun {
            name,
            method,
            trials,
            change_detection: false,
            events: &[],
        }
    }

    /// Runs it into `data` with seed 1 and returns what is compared.
    fn figures(&self, data: &Path) -> Value {
        let path = format!(
            "{}/configs/{}.conf",
            env!("CARGO_MANIFEST_DIR"),
            self.method
        );
        let mut config = Config::from_file(Path::new(&path)).expect("shipped config");
        config.trials = self.trials;
        config.seed = 1;
        if self.change_detection {
            config.merge_strategy = MergeStrategy::ChangeDetection;
        }
        let events: Vec<Event> = self.events.iter().map(|e| e.parse().unwrap()).collect();
        let options = RunOptions {
            events,
            ..RunOptions::new(config, data)
        };
        let result = run(&options).expect("the golden run runs");
        let summary = &result.summary;
        let digests: Map<String, Value> = DATA_FILES
            .iter()
            .map(|name| {
                let text = without_minutes(&result.folder.join(name));
                (name.to_string(), json!(format!("{:016x}", fnv1a(&text))))
            })
            .collect();
        json!({
            "trials": summary.trials,
            "nodes": summary.nodes,
            "bins": summary.bins,
            "patterns": summary.patterns,
            "failures": summary.failures,
            "mean_distance_mm": summary.mean_distance_mm,
            "files": digests,
        })
    }
}

/// A data file without its minutes column (the last of three fields).
fn without_minutes(path: &Path) -> String {
    let text = std::fs::read_to_string(path).unwrap_or_default();
    let is_series = !["abs_err", "merges", "changes"]
        .iter()
        .any(|n| path.ends_with(n));
    text.lines()
        .map(|line| {
            let fields: Vec<&str> = line.split(' ').collect();
            if is_series && fields.len() == 3 {
                fields[..2].join(" ")
            } else {
                line.to_string()
            }
        })
        .collect::<Vec<_>>()
        .join("\n")
}

/// 64-bit FNV-1a: a stable digest that needs no crate.
fn fnv1a(text: &str) -> u64 {
    text.bytes().fold(0xcbf2_9ce4_8422_2325, |hash, byte| {
        (hash ^ u64::from(byte)).wrapping_mul(0x0100_0000_01b3)
    })
}

fn golden_path() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/golden.json")
}

#[test]
fn every_method_gives_the_golden_files_for_seed_1() {
    let data = tempfile::tempdir().unwrap();
    let measured: Map<String, Value> = RUNS
        .iter()
        .map(|golden| (golden.name.to_string(), golden.figures(data.path())))
        .collect();
    if std::env::var_os("EYEHAND_BLESS").is_some() {
        let text = serde_json::to_string_pretty(&measured).unwrap() + "\n";
        std::fs::write(golden_path(), text).unwrap();
        return;
    }
    let text = std::fs::read_to_string(golden_path()).expect("tests/data/golden.json");
    let golden: Map<String, Value> = serde_json::from_str(&text).unwrap();
    // Compared as the file holds them: both sides through the same text round trip.
    let measured: Map<String, Value> =
        serde_json::from_str(&serde_json::to_string(&measured).unwrap()).unwrap();
    for golden_run in &RUNS {
        assert_eq!(
            measured[golden_run.name], golden[golden_run.name],
            "{}: the run differs from its golden figures",
            golden_run.name
        );
    }
    assert_eq!(golden.len(), RUNS.len(), "every golden run is checked");
}
