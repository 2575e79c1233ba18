//! A study's results: the markdown tables (compare: mean ± s.d. over seeds per method,
//! then each seed's trials to two 4-step levels and to recover after the first event;
//! sweep: one row per cell) and the 4-step curves, from its finished cells.

use super::plan::{Cell, StudyKind};
use crate::experiment::plot::{moving_average, Curve, PlotError, Series};
use crate::experiment::{FourStepTrace, RunSummary};
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

/// The comparison's markdown table: one row per method, mean ± s.d. over seeds, then per
/// seed (in cell order) the trials to a [`TRIALS_TO_WINDOW`]-trial 4-step mean of each of
/// [`TRIALS_TO_LEVELS_MM`] and, when the runs have events, the trials to recover after the
/// first ([`FourStepTrace::recovered_after`]); `never` where a seed did not.
pub fn compare_table(runs: &[CellResult]) -> String {
    let event = runs
        .first()
        .and_then(|r| r.cell.request.events.iter().min_by_key(|e| e.trial()))
        .copied();
    let mut table = String::from("| method | seeds | 1 step (mm) | 2 steps | 3 steps | 4 steps | 5 steps | trials/s | memory (MB) | nodes |");
    let mut rule = String::from("|---|---|---|---|---|---|---|---|---|---|");
    for level in TRIALS_TO_LEVELS_MM {
        table += &format!(" trials to {level} mm |");
        rule += "---|";
    }
    if let Some(event) = event {
        table += &format!(" trials to recover after {event} |");
        rule += "---|";
    }
    table += &format!("\n{rule}\n");
    let cell = |values: Vec<f64>, digits: usize| {
        if values.is_empty() {
            return "-".to_string();
        }
        let (mean, sd) = mean_sd(&values);
        format!("{mean:.digits$} ± {sd:.digits$}")
    };
    for (label, group) in by_label(runs) {
        let mut row = format!("| {label} | {} |", group.len());
        for step in 0..5 {
            let values = group
                .iter()
                .filter_map(|r| r.summary.mean_distance_mm[step])
                .collect();
            row += &format!(" {} |", cell(values, 4));
        }
        let of = |f: fn(&CellResult) -> f64| group.iter().map(|r| f(r)).collect::<Vec<_>>();
        row += &format!(" {} |", cell(of(|r| r.summary.trials_per_second), 0));
        row += &format!(
            " {} |",
            cell(of(|r| r.summary.peak_rss_kb as f64 / 1024.0), 1)
        );
        row += &format!(" {} |", cell(of(|r| r.summary.nodes as f64), 0));
        for level in TRIALS_TO_LEVELS_MM {
            row += &per_seed(&group, |t| t.first_within(level, TRIALS_TO_WINDOW));
        }
        if let Some(event) = event {
            row += &per_seed(&group, |t| t.recovered_after(event.trial()));
        }
        table += &row;
        table += "\n";
    }
    table
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
    let mut table = String::from("| cell | setting | seed | 1 step (mm) | 2 steps | 3 steps | 4 steps | 5 steps | trials/s | nodes |\n");
    table += "|---|---|---|---|---|---|---|---|---|---|\n";
    for run in runs {
        let s = &run.summary;
        let steps: Vec<String> = s
            .mean_distance_mm
            .iter()
            .map(|d| d.map_or("-".into(), |d| format!("{d:.4}")))
            .collect();
        table += &format!(
            "| {} | {} | {} | {} | {:.0} | {} |\n",
            run.index,
            run.cell.label,
            run.cell.seed,
            steps.join(" | "),
            s.trials_per_second,
            s.nodes,
        );
    }
    table
}

/// Each label's distance after feedback step `step` (1..5), smoothed over the last 50
/// trials and averaged over its seeds.
pub fn step_curves(runs: &[CellResult], step: usize) -> Result<Vec<Curve>, PlotError> {
    by_label(runs)
        .into_iter()
        .map(|(label, group)| {
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
            let points = sums
                .into_iter()
                .map(|(t, (s, n))| (t as f64, s / n as f64))
                .collect();
            Ok(Curve {
                label: label.to_string(),
                points,
            })
        })
        .collect()
}
