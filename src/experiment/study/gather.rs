//! Gathering a study: `table.md` and `curves.png` from the cells that finished (their
//! `summary.json`, written last by a run, is the done marker), the cells that did not with
//! the last lines of their logs, and the `sbatch` line that reruns only those.

use super::plan::{StudyFolder, StudyPlan};
use super::slurm::resubmit_line;
use super::table::{four_step_curves, study_table, CellResult};
use super::StudyError;
use crate::experiment::plot::plot_curves;
use crate::experiment::{Event, FourStepTrace};
use crate::files::{read_bytes, read_text, MAX_RUN_FILE_BYTES};
use std::path::PathBuf;

/// Log lines shown for a cell that did not finish.
const LOG_TAIL_LINES: usize = 5;

/// A cell without a readable `summary.json`.
#[derive(Debug, Clone, PartialEq)]
pub struct Unfinished {
    /// The cell's index.
    pub index: usize,
    /// What it varies.
    pub label: String,
    /// Its seed.
    pub seed: u64,
    /// Why it counts as unfinished.
    pub reason: String,
    /// Its newest log, if any.
    pub log: Option<PathBuf>,
    /// The log's last lines.
    pub log_tail: Vec<String>,
}

/// What gathering a study found.
#[derive(Debug, Clone)]
pub struct GatherReport {
    /// The study's folder.
    pub folder: PathBuf,
    /// The table written to `table.md`.
    pub table: String,
    /// The finished cells, in cell order.
    pub finished: Vec<CellResult>,
    /// The cells that did not finish, in cell order.
    pub unfinished: Vec<Unfinished>,
    /// `sbatch --array=… SCRIPT` rerunning exactly the unfinished cells (`None` if all done).
    pub resubmit: Option<String>,
}

/// Reads every cell of the study in `folder`, writes `table.md` and (when any cell
/// finished) `curves.png`, and reports the cells that did not finish.
pub fn gather(folder: &StudyFolder) -> Result<GatherReport, StudyError> {
    let plan = folder.plan()?;
    let mut finished = Vec::new();
    let mut unfinished = Vec::new();
    for (index, cell) in plan.cells.iter().enumerate() {
        let run_folder = folder.cell(index);
        let result = read_summary(&run_folder)
            .and_then(|summary| cell_of(summary, cell))
            .and_then(|summary| Ok((summary, read_trace(&run_folder)?)));
        match result {
            Ok((summary, trace)) => finished.push(CellResult {
                index,
                cell: cell.clone(),
                folder: run_folder,
                summary,
                trace,
            }),
            Err(reason) => {
                let log = folder.newest_log(index);
                let log_tail = log.as_deref().map(last_lines).unwrap_or_default();
                unfinished.push(Unfinished {
                    index,
                    label: cell.label.clone(),
                    seed: cell.seed,
                    reason,
                    log,
                    log_tail,
                });
            }
        }
    }
    let table = study_table(plan.kind, &finished);
    let table_path = folder.0.join("table.md");
    std::fs::write(&table_path, &table).map_err(StudyError::io(table_path))?;
    if !finished.is_empty() {
        draw_curves(folder, &plan, &finished)?;
    }
    let indices: Vec<usize> = unfinished.iter().map(|u| u.index).collect();
    let resubmit =
        (!indices.is_empty()).then(|| resubmit_line(&folder.script(plan.kind), &indices));
    Ok(GatherReport {
        folder: folder.0.clone(),
        table,
        finished,
        unfinished,
        resubmit,
    })
}

/// A cell's summary, or why there is none.
pub(super) fn read_summary(
    run_folder: &std::path::Path,
) -> Result<crate::experiment::RunSummary, String> {
    let path = run_folder.join("summary.json");
    let text = read_text(&path, MAX_RUN_FILE_BYTES).map_err(|e| {
        let e = std::io::Error::from(e);
        if e.kind() == std::io::ErrorKind::NotFound {
            if run_folder.is_dir() {
                "started, no summary.json (running, failed or cancelled)".to_string()
            } else {
                "not started".to_string()
            }
        } else {
            format!("{}: {e}", path.display())
        }
    })?;
    let summary: crate::experiment::RunSummary =
        serde_json::from_str(&text).map_err(|e| format!("{}: {e}", path.display()))?;
    if summary.interrupted {
        return Err(format!(
            "interrupted after trial {} of its summary",
            summary.trials
        ));
    }
    Ok(summary)
}

/// A finished cell's 4-step distances, or why they cannot be read.
fn read_trace(run_folder: &std::path::Path) -> Result<FourStepTrace, String> {
    FourStepTrace::read(run_folder)
        .map_err(|e| format!("{}: {e}", run_folder.join("4step").display()))
}

/// `summary` when it is the run of `cell` (its method and seed), else why it is not: a
/// folder holding another study's cells would be gathered under the wrong labels.
fn cell_of(
    summary: crate::experiment::RunSummary,
    cell: &super::plan::Cell,
) -> Result<crate::experiment::RunSummary, String> {
    let method = cell.request.method.map(|m| m.name());
    if summary.seed != cell.seed || method.is_some_and(|m| m != summary.method) {
        return Err(format!(
            "its summary.json is another run's (method {}, seed {}; the cell runs {}seed {}): the folder holds another study's cells",
            summary.method,
            summary.seed,
            method.map_or(String::new(), |m| format!("method {m}, ")),
            cell.seed
        ));
    }
    Ok(summary)
}

/// The last lines of a log (empty if unreadable).
fn last_lines(path: &std::path::Path) -> Vec<String> {
    let text = read_bytes(path, MAX_RUN_FILE_BYTES).unwrap_or_default();
    let text = String::from_utf8_lossy(&text);
    let lines: Vec<&str> = text.lines().collect();
    lines[lines.len().saturating_sub(LOG_TAIL_LINES)..]
        .iter()
        .map(|l| l.to_string())
        .collect()
}

fn draw_curves(
    folder: &StudyFolder,
    plan: &StudyPlan,
    finished: &[CellResult],
) -> Result<(), StudyError> {
    let curves = four_step_curves(finished)?;
    let mut seeds: Vec<u64> = plan.cells.iter().map(|c| c.seed).collect();
    seeds.sort_unstable();
    seeds.dedup();
    let events: Vec<f64> = plan
        .cells
        .first()
        .map(|c| {
            c.request
                .events
                .iter()
                .map(|e| Event::trial(e) as f64)
                .collect()
        })
        .unwrap_or_default();
    let title = format!("distance after step 4, mean over seeds {seeds:?}");
    plot_curves(&folder.0.join("curves.png"), &title, "mm", &curves, &events)?;
    Ok(())
}
