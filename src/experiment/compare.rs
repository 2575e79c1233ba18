//! `eyehand compare`: every method on the same seeds and events, run side by side; a
//! markdown table of mean ± standard deviation over seeds and one PNG overlaying the
//! methods' 4-step curves.

use super::cells::{run_cells, Cell, CellError, CellResult};
use super::plot::{moving_average, plot_curves, Curve, PlotError, Series};
use super::{allocate_run_folder, Event, RunFolderError};
use crate::learn::Method;
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

/// What to compare.
#[derive(Debug, Clone, PartialEq)]
pub struct CompareRequest {
    /// The methods, in table order.
    pub methods: Vec<Method>,
    /// Trials per run.
    pub trials: usize,
    /// Seeds every method runs with.
    pub seeds: Vec<u64>,
    /// Events of every run.
    pub events: Vec<Event>,
    /// The data folder.
    pub data: PathBuf,
    /// Folder of per-method configs (`<method>.conf`); a method without one runs the
    /// default config.
    pub configs: PathBuf,
}

/// Why a comparison failed.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum CompareError {
    /// A run failed.
    #[error(transparent)]
    Cell(#[from] CellError),
    /// No folder for the comparison's files.
    #[error(transparent)]
    Folder(#[from] RunFolderError),
    /// The curves could not be drawn.
    #[error(transparent)]
    Plot(#[from] PlotError),
    /// Writing the table failed.
    #[error("writing the comparison: {0}")]
    Io(#[from] std::io::Error),
}

/// A finished comparison.
#[derive(Debug, Clone)]
pub struct CompareReport {
    /// Where `table.md` and `curves.png` are.
    pub folder: PathBuf,
    /// The markdown table.
    pub table: String,
    /// Every run.
    pub runs: Vec<CellResult>,
}

/// The runs of a comparison: each method × each seed.
pub fn compare_cells(request: &CompareRequest) -> Vec<Cell> {
    let mut cells = Vec::new();
    for method in &request.methods {
        let config = request.configs.join(format!("{method}.conf"));
        let mut flags = Vec::new();
        if config.is_file() {
            flags.extend(["--config".to_string(), config.display().to_string()]);
        }
        flags.extend(["--method".to_string(), method.to_string()]);
        flags.extend(["--trials".to_string(), request.trials.to_string()]);
        for event in &request.events {
            flags.extend(["--event".to_string(), event.to_string()]);
        }
        for &seed in &request.seeds {
            cells.push(Cell {
                label: method.to_string(),
                seed,
                args: Cell::run_args(&flags, seed, &request.data),
            });
        }
    }
    cells
}

/// Runs a comparison with `program` and writes `<data>/compare/<id>/`.
pub fn run_compare(
    program: &Path,
    request: &CompareRequest,
) -> Result<CompareReport, CompareError> {
    let runs = run_cells(program, &compare_cells(request))
        .into_iter()
        .collect::<Result<Vec<_>, _>>()?;
    let folder = allocate_run_folder(&request.data, "compare")?;
    let table = compare_table(&runs);
    std::fs::write(folder.join("table.md"), &table)?;
    let curves = four_step_curves(&runs)?;
    let events: Vec<f64> = request.events.iter().map(|e| e.trial() as f64).collect();
    let title = format!("distance after step 4, mean over seeds {:?}", request.seeds);
    plot_curves(&folder.join("curves.png"), &title, "mm", &curves, &events)?;
    Ok(CompareReport {
        folder,
        table,
        runs,
    })
}

/// Mean and sample standard deviation.
pub(super) fn mean_sd(values: &[f64]) -> (f64, f64) {
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

/// Each label's 4-step distance, smoothed over 50 trials and averaged over its seeds.
fn four_step_curves(runs: &[CellResult]) -> Result<Vec<Curve>, PlotError> {
    by_label(runs)
        .into_iter()
        .map(|(label, group)| {
            let mut sums: BTreeMap<u64, (f64, usize)> = BTreeMap::new();
            for run in group {
                let path = run.folder.join("4step");
                let series =
                    Series::read(&path).map_err(|source| PlotError::Read { path, source })?;
                for (trial, value) in moving_average(&series.points, 50) {
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
