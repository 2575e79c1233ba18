//! The report's plots as the page reads them: for a run, one panel per data file (the
//! distances after steps 1–5 raw and smoothed, nodes, bins, memory, patterns and time
//! used) with the run's events; for a study, one panel per feedback step with a curve per
//! finished cell.

use crate::experiment::plot::{moving_average, time_in_unit, PlotError, Series, PANELS};
use crate::experiment::study::StudyFolder;
use crate::experiment::study::StudyPlan;
use serde_json::{json, Value};
use std::collections::BTreeMap;
use std::path::Path;

/// Significant digits the page gets of a value: the plots show four.
const DIGITS: i32 = 5;

/// Curves drawn from at most about this many points per cell in a study's panels.
const STUDY_POINTS: usize = 2000;

fn read(folder: &Path, name: &str) -> Result<Series, PlotError> {
    let path = folder.join(name);
    Series::read(&path).map_err(|source| PlotError::Read { path, source })
}

/// `value` to [`DIGITS`] significant digits (a shorter number in the page's text).
fn rounded(value: f64) -> f64 {
    if value == 0.0 || !value.is_finite() {
        return value;
    }
    let scale = 10f64.powi(DIGITS - 1 - value.abs().log10().floor() as i32);
    (value * scale).round() / scale
}

fn column(points: &[(f64, f64)]) -> Vec<f64> {
    points.iter().map(|&(_, v)| rounded(v)).collect()
}

/// A run's panels, smoothing the distances over the last `smooth` trials.
pub(super) fn run_panels(run_dir: &Path, smooth: usize) -> Result<Vec<Value>, PlotError> {
    let mut panels = Vec::new();
    for step in 1..=5 {
        let series = read(run_dir, &format!("{step}step"))?;
        let trials: Vec<f64> = series.points.iter().map(|p| p.0).collect();
        panels.push(json!({
            "title": PANELS[step - 1],
            "unit": "mm",
            "log": true,
            "x": trials,
            "series": [
                {"label": "per trial", "values": column(&series.points), "faint": true},
                {"label": format!("mean of the last {smooth} trials"),
                 "values": column(&moving_average(&series.points, smooth))},
            ],
        }));
    }
    let nodes = read(run_dir, "nodes")?;
    let (time_unit, time) = time_in_unit(&nodes.minutes);
    let figures = [
        (PANELS[5], "nodes", nodes.points.clone()),
        (PANELS[6], "bins", read(run_dir, "bins")?.points),
        (PANELS[7], "kB", read(run_dir, "mem")?.points),
        (PANELS[8], "patterns", read(run_dir, "patterns")?.points),
        (PANELS[9], time_unit, time),
    ];
    for (title, unit, points) in figures {
        let trials: Vec<f64> = points.iter().map(|p| p.0).collect();
        panels.push(json!({
            "title": title,
            "unit": unit,
            "log": false,
            "x": trials,
            "series": [{"label": unit, "values": column(&points)}],
        }));
    }
    Ok(panels)
}

/// A study's panels: per feedback step the distance of every finished cell (a cell without
/// the step's file is left out), smoothed over the last `smooth` trials.
pub(super) fn study_panels(
    folder: &StudyFolder,
    plan: &StudyPlan,
    smooth: usize,
) -> Result<Vec<Value>, PlotError> {
    let mut panels = Vec::new();
    for step in 1..=5 {
        let mut curves = Vec::new();
        for (index, cell) in plan.cells.iter().enumerate() {
            let run = folder.cell(index);
            if !run.join("summary.json").is_file() {
                continue;
            }
            let series = read(&run, &format!("{step}step"))?;
            let smoothed = moving_average(&series.points, smooth);
            let stride = smoothed.len().div_ceil(STUDY_POINTS).max(1);
            let kept: BTreeMap<u64, f64> = smoothed
                .iter()
                .enumerate()
                .filter(|(i, _)| i % stride == 0 || *i + 1 == smoothed.len())
                .map(|(_, &(t, v))| (t as u64, rounded(v)))
                .collect();
            curves.push((format!("{index}: {} seed {}", cell.label, cell.seed), kept));
        }
        let mut trials: Vec<u64> = curves.iter().flat_map(|(_, c)| c.keys().copied()).collect();
        trials.sort_unstable();
        trials.dedup();
        let series: Vec<Value> = curves
            .iter()
            .map(|(label, curve)| {
                let values: Vec<Option<f64>> =
                    trials.iter().map(|t| curve.get(t).copied()).collect();
                json!({"label": label, "values": values})
            })
            .collect();
        panels.push(json!({
            "title": PANELS[step - 1],
            "unit": "mm",
            "log": true,
            "x": trials,
            "series": series,
        }));
    }
    Ok(panels)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn values_keep_five_significant_digits() {
        assert_eq!(rounded(123.456_789), 123.46);
        assert_eq!(rounded(0.000_012_345_67), 0.000_012_346);
        assert_eq!(rounded(0.0), 0.0);
        assert_eq!(rounded(-98_765.43), -98_765.0);
    }
}
