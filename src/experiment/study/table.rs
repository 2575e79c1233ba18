//! A study's results: the markdown tables (compare: mean ± s.d. over seeds per method;
//! sweep: one row per cell) and the 4-step curves, from its finished cells.

use super::plan::{Cell, StudyKind};
use crate::experiment::plot::{moving_average, Curve, PlotError, Series};
use crate::experiment::RunSummary;
use std::collections::BTreeMap;
use std::path::PathBuf;

/// Trials the curves are smoothed over.
const CURVE_SMOOTHING: usize = 50;

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

/// The comparison's markdown table: one row per method, mean ± s.d. over seeds.
pub fn compare_table(runs: &[CellResult]) -> String {
    let mut table = String::from("| method | seeds | 1 step (mm) | 2 steps | 3 steps | 4 steps | 5 steps | trials/s | memory (MB) | nodes |\n");
    table += "|---|---|---|---|---|---|---|---|---|---|\n";
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
        row += &format!(" {} |\n", cell(of(|r| r.summary.nodes as f64), 0));
        table += &row;
    }
    table
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

/// Each label's 4-step distance, smoothed over 50 trials and averaged over its seeds.
pub fn four_step_curves(runs: &[CellResult]) -> Result<Vec<Curve>, PlotError> {
    by_label(runs)
        .into_iter()
        .map(|(label, group)| {
            let mut sums: BTreeMap<u64, (f64, usize)> = BTreeMap::new();
            for run in group {
                let path = run.folder.join("4step");
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
