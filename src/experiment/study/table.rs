//! A study's results: the markdown tables (compare: mean ± s.d. over seeds per method of
//! the distance after each feedback step, then each seed's trials to two 4-step levels and to recover after each event; sweep:
//! one row per cell), each under a line saying which trials its figures cover, and the
//! distance curves, from its finished cells.

use super::plan::{Cell, StudyKind};
use crate::experiment::plot::{moving_average, Curve, PlotError, Series};
use crate::experiment::{FourStepTrace, RunSummary};
use crate::learn::Method;
use std::collections::BTreeMap;
use std::path::PathBuf;

/// Trials the curves are smoothed over.
pub(super) const CURVE_SMOOTHING: usize = 50;
/// Trials in the running 4-step mean whose first reach of a level the compare table gives.
pub const TRIALS_TO_WINDOW: usize = 200;
/// The 4-step levels (mm) the compare table gives each seed's trials to.
pub const TRIALS_TO_LEVELS_MM: [f64; 2] = [1.0, 0.1];

/// A finished cell.
#[derive(Debug, Clone, PartialEq)]
pub struct CellResult {
    /// Its index in the study.
    pub index: usize,
    /// The cell.
    pub cell: Cell,
    /// Its run folder.
    pub folder: PathBuf,
    /// Its summary.
    pub summary: RunSummary,
    /// Its 4-step distances by trial.
    pub trace: FourStepTrace,
}

/// The table of a study of `kind`.
pub fn study_table(kind: StudyKind, runs: &[CellResult]) -> String {
    match kind {
        StudyKind::Compare => compare_table(runs),
        StudyKind::Sweep => sweep_table(runs),
    }
}

/// Mean and sample standard deviation.
fn mean_sd(values: &[f64]) -> (f64, f64) {
    let n = values.len() as f64;
    let mean = values.iter().sum::<f64>() / n;
    let var = if values.len() > 1 {
        values.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / (n - 1.0)
    } else {
        0.0
    };
    (mean, var.sqrt())
}

/// Runs grouped by label, in first-seen order.
fn by_label(runs: &[CellResult]) -> Vec<(&str, Vec<&CellResult>)> {
    let mut groups: Vec<(&str, Vec<&CellResult>)> = Vec::new();
    for run in runs {
        match groups.iter_mut().find(|(l, _)| *l == run.cell.label) {
            Some((_, group)) => group.push(run),
            None => groups.push((&run.cell.label, vec![run])),
        }
    }
    groups
}

/// The comparison's markdown table: one row per method, mean ± s.d. over seeds of the
/// distance after every feedback step some run took (`steps_taken`), then per
/// seed (in cell order) the trials to a [`TRIALS_TO_WINDOW`]-trial 4-step mean of each of
/// [`TRIALS_TO_LEVELS_MM`] and the trials to recover after each event
/// ([`FourStepTrace::recovered_after`]); `never` where a seed did not.
pub fn compare_table(runs: &[CellResult]) -> String {
    let mut events: Vec<_> = runs
        .first()
        .map(|r| r.cell.request.events.clone())
        .unwrap_or_default();
    events.sort_by_key(|e| e.trial());
    let steps = steps_taken(runs);
    let mut table = window_line(runs);
    table += "| method | seeds |";
    let mut rule = String::from("|---|---|");
    for step in 1..=steps {
        table += &match step {
            1 => " 1 step (mm) |".to_string(),
            _ => format!(" {step} steps |"),
        };
        rule += "---|";
    }
    table += " trials/s | memory (MB) | nodes |";
    rule += "---|---|---|";
    for level in TRIALS_TO_LEVELS_MM {
        table += &format!(" trials to {level} mm |");
        rule += "---|";
    }
    for event in &events {
        table += &format!(" trials to recover after {event} |");
        rule += "---|";
    }
    table += &format!("\n{rule}\n");
    let cell = |values: Vec<f64>, digits: usize| {
        if values.is_empty() {
            return "-".to_string();
        }
        let (mean, sd) = mean_sd(&values);
        format!("{} ± {}", figure(mean, digits), figure(sd, digits))
    };
    for (label, group) in by_label(runs) {
        let mut row = format!("| {label} | {} |", group.len());
        for step in 0..steps {
            let values = group
                .iter()
                .filter_map(|r| r.summary.mean_distance_by_step_mm.get(step).copied()?)
                .collect();
            row += &format!(" {} |", cell(values, 4));
        }
        let of = |f: fn(&CellResult) -> f64| group.iter().map(|r| f(r)).collect::<Vec<_>>();
        row += &format!(" {} |", cell(of(|r| r.summary.trials_per_second), 0));
        row += &format!(
            " {} |",
            cell(of(|r| r.summary.peak_rss_kb as f64 / 1024.0), 1)
        );
        let nodes = if group.iter().all(|r| has_nodes(&r.summary)) {
            cell(of(|r| r.summary.nodes as f64), 0)
        } else {
            "-".to_string()
        };
        row += &format!(" {nodes} |");
        for level in TRIALS_TO_LEVELS_MM {
            row += &per_seed(&group, |t| t.first_within(level, TRIALS_TO_WINDOW));
        }
        for event in &events {
            row += &per_seed(&group, |t| t.recovered_after(event.trial()));
        }
        table += &row;
        table += "\n";
    }
    table
}

/// The feedback steps the compare table has a column for: up to the last step after which
/// some run has a mean distance (at least 1).
fn steps_taken(runs: &[CellResult]) -> usize {
    runs.iter()
        .filter_map(|r| {
            let by_step = &r.summary.mean_distance_by_step_mm;
            by_step.iter().rposition(Option::is_some)
        })
        .max()
        .map_or(1, |last| last + 1)
}

/// The line above a table saying which trials its distances cover: the last `window`
/// trials of each run (every run's, when they differ).
fn window_line(runs: &[CellResult]) -> String {
    let mut windows: Vec<usize> = runs.iter().map(|r| r.summary.window).collect();
    windows.sort_unstable();
    windows.dedup();
    let windows: Vec<String> = windows.iter().map(ToString::to_string).collect();
    format!(
        "Distances: mean over the last {} trials of each run (summary.json's `window`); \
         trials to a level: the first trial at which the mean 4-step distance of the last \
         {TRIALS_TO_WINDOW} trials is below it (`never`: not reached); `-`: no such figure \
         (no such step, or a learner that counts no nodes).\n\n",
        windows.join(" or ")
    )
}

/// True when the run's learner counts nodes (see [`MethodFacts::counts_nodes`](crate::learn::MethodFacts::counts_nodes)).
fn has_nodes(summary: &RunSummary) -> bool {
    summary
        .method
        .parse::<Method>()
        .is_ok_and(|method: Method| method.facts().counts_nodes)
}

/// A figure with `digits` decimals, in scientific notation when below 1e-4 (but not 0),
/// where the decimals would hide it.
fn figure(value: f64, digits: usize) -> String {
    if value != 0.0 && value.abs() < 1e-4 {
        format!("{value:.2e}")
    } else {
        format!("{value:.digits$}")
    }
}

/// A table cell listing each run's count of trials (`never`: `None`).
fn per_seed(group: &[&CellResult], count: impl Fn(&FourStepTrace) -> Option<usize>) -> String {
    let counts: Vec<String> = group
        .iter()
        .map(|r| count(&r.trace).map_or("never".into(), |n| n.to_string()))
        .collect();
    format!(" {} |", counts.join(", "))
}

/// The sweep's markdown table: one row per finished cell, in cell order.
pub fn sweep_table(runs: &[CellResult]) -> String {
    let mut table = window_line(runs);
    table += "| cell | setting | seed | 1 step (mm) | 2 steps | 3 steps | 4 steps | 5 steps | trials/s | nodes |\n";
    table += "|---|---|---|---|---|---|---|---|---|---|\n";
    for run in runs {
        let s = &run.summary;
        let steps: Vec<String> = s
            .mean_distance_mm
            .iter()
            .map(|d| d.map_or("-".into(), |d| figure(d, 4)))
            .collect();
        let nodes = if has_nodes(s) {
            s.nodes.to_string()
        } else {
            "-".to_string()
        };
        table += &format!(
            "| {} | {} | {} | {} | {:.0} | {nodes} |\n",
            run.index,
            run.cell.label,
            run.cell.seed,
            steps.join(" | "),
            s.trials_per_second,
        );
    }
    table
}

/// Each label's distance after feedback step `step` (1..5), smoothed over the last 50
/// trials and averaged over its seeds, at the trials every seed has.
pub fn step_curves(runs: &[CellResult], step: usize) -> Result<Vec<Curve>, PlotError> {
    by_label(runs)
        .into_iter()
        .map(|(label, group)| {
            let seeds = group.len();
            let mut sums: BTreeMap<u64, (f64, usize)> = BTreeMap::new();
            for run in group {
                let path = run.folder.join(format!("{step}step"));
                let series =
                    Series::read(&path).map_err(|source| PlotError::Read { path, source })?;
                for (trial, value) in moving_average(&series.points, CURVE_SMOOTHING) {
                    let entry = sums.entry(trial as u64).or_default();
                    *entry = (entry.0 + value, entry.1 + 1);
                }
            }
            // Only trials every seed has: a mean over some of them would jump.
            let points = sums
                .into_iter()
                .filter(|(_, (_, n))| *n == seeds)
                .map(|(t, (s, n))| (t as f64, s / n as f64))
                .collect();
            Ok(Curve {
                label: label.to_string(),
                points,
            })
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::experiment::plot::Series;
    use crate::experiment::{run, Config, Event, RunOptions, RunRequest};

    /// A finished lin5 run's summary (20 trials) to build cells from.
    fn summary() -> RunSummary {
        let data = tempfile::tempdir().unwrap();
        let mut config = Config::default_config();
        config.trials = 20;
        run(&RunOptions::new(config, data.path())).unwrap().summary
    }

    fn cell(summary: &RunSummary, method: &str, step5: f64, events: &[Event]) -> CellResult {
        let mut summary = summary.clone();
        summary.method = method.to_string();
        summary.mean_distance_mm[4] = Some(step5);
        // Seven of eight steps taken: the table's step columns end at the seventh.
        summary.mean_distance_by_step_mm = vec![Some(9.0); 8];
        summary.mean_distance_by_step_mm[4] = Some(step5);
        summary.mean_distance_by_step_mm[7] = None;
        let points = (1..=600).map(|t| (f64::from(t), if t % 300 < 20 { 50.0 } else { 1.0 }));
        CellResult {
            index: 0,
            cell: Cell {
                label: method.to_string(),
                seed: 1,
                request: RunRequest {
                    events: events.to_vec(),
                    ..RunRequest::default()
                },
            },
            folder: PathBuf::new(),
            trace: FourStepTrace::from_series(&Series {
                points: points.collect(),
                minutes: Vec::new(),
            }),
            summary,
        }
    }

    #[test]
    fn the_compare_table_states_its_window_and_gives_nodes_tiny_values_and_every_recovery() {
        let summary = summary();
        let events: Vec<Event> = ["rotate:300:30", "elongate:600:2:-10"]
            .iter()
            .map(|e| e.parse().unwrap())
            .collect();
        let runs = [
            cell(&summary, "lin5", 0.25, &events),
            cell(&summary, "issgp", 3.2e-7, &events),
        ];
        let table = compare_table(&runs);
        let lines: Vec<&str> = table.lines().collect();
        assert!(
            lines[0].starts_with("Distances: mean over the last 2 trials of each run"),
            "{table}"
        );
        assert!(
            lines[2].starts_with("| method | seeds | 1 step (mm) | 2 steps |")
                && lines[2].contains("| 7 steps | trials/s |"),
            "{table}"
        );
        assert!(lines[2].ends_with(
            "trials to recover after rotate:300:30 | trials to recover after elongate:600:2:-10 |"
        ), "{table}");
        let lin5 = lines[4];
        let issgp = lines[5];
        assert!(lin5.contains("| 0.2500 ± 0.0000 |"), "{lin5}");
        assert!(issgp.contains("| 3.20e-7 ± 0.0000 |"), "{issgp}");
        let nodes = format!("| {} ± 0 |", summary.nodes);
        assert!(lin5.contains(&nodes), "{lin5}");
        assert!(issgp.contains(" | - | "), "issgp has no nodes: {issgp}");
        // Both events get a recovery column (the second event is past the trace: never).
        assert!(lin5.ends_with("| 65 | never |"), "{lin5}");
    }

    #[test]
    fn tiny_figures_are_written_in_scientific_notation() {
        assert_eq!(figure(3.2e-7, 4), "3.20e-7");
        assert_eq!(figure(0.0, 4), "0.0000");
        assert_eq!(figure(0.00012, 4), "0.0001");
        assert_eq!(figure(-5e-5, 4), "-5.00e-5");
        assert_eq!(figure(1234.5, 0), "1234");
    }
}
