//! A study's plan and folder: its cells (a label, a seed and a typed [`RunRequest`] each),
//! stored as `cells.json` in `data/<kind>/<id>/`, with cell i's run folder fixed at
//! `cells/<i>/` and its log in `logs/`.

use super::StudyError;
use crate::experiment::{allocate_run_folder, Config, RunRequest};
use crate::files::{read_text, MAX_RUN_FILE_BYTES};
use serde::{Deserialize, Serialize};
use std::path::{Path, PathBuf};

/// The most cells a study may have (a Slurm job array's default limit is 1001 tasks).
pub const MAX_CELLS: usize = 1000;

/// What a study compares, which decides its table.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum StudyKind {
    /// Methods side by side: one row per method, mean ± s.d. over seeds.
    Compare,
    /// Settings crossed: one row per cell.
    Sweep,
}

impl StudyKind {
    /// The folder under the data folder (`compare` or `sweep`).
    pub fn name(self) -> &'static str {
        match self {
            StudyKind::Compare => "compare",
            StudyKind::Sweep => "sweep",
        }
    }
}

/// One run of a study.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Cell {
    /// What the cell varies, for tables (e.g. `lin5` or `split_error=1e-5`).
    pub label: String,
    /// The seed.
    pub seed: u64,
    /// The run.
    pub request: RunRequest,
}

/// A comparison or sweep: its kind and its cells, in index order.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct StudyPlan {
    /// Compare or sweep.
    pub kind: StudyKind,
    /// The cells; cell i runs in `cells/<i>/`.
    pub cells: Vec<Cell>,
}

/// The file a study folder keeps its plan in.
const PLAN_FILE: &str = "cells.json";

impl StudyPlan {
    /// Every cell's config, resolved and validated, so a bad cell fails before any runs.
    pub fn check(&self) -> Result<Vec<Config>, StudyError> {
        self.cells
            .iter()
            .enumerate()
            .map(|(index, cell)| {
                cell.request
                    .config()
                    .map(|(config, _)| config)
                    .map_err(|source| StudyError::Cell {
                        index,
                        label: cell.label.clone(),
                        seed: cell.seed,
                        source: Box::new(source),
                    })
            })
            .collect()
    }

    /// Creates the study's folder (the first free `<data>/<kind>/<id>/`), fixes every cell's
    /// run folder in it, makes every path absolute and writes `cells.json`.
    pub fn create(mut self, data: &Path) -> Result<StudyFolder, StudyError> {
        let data = std::path::absolute(data).map_err(StudyError::io(data))?;
        let folder = StudyFolder(allocate_run_folder(&data, self.kind.name())?);
        for (index, cell) in self.cells.iter_mut().enumerate() {
            cell.request.folder = Some(folder.cell(index));
            cell.request.data = data.clone();
            let request = std::mem::take(&mut cell.request);
            cell.request = request
                .with_absolute_paths()
                .map_err(|source| StudyError::Cell {
                    index,
                    label: cell.label.clone(),
                    seed: cell.seed,
                    source: Box::new(source),
                })?;
        }
        let json = serde_json::to_string_pretty(&self).expect("a plan is plain data");
        let path = folder.0.join(PLAN_FILE);
        std::fs::write(&path, json + "\n").map_err(StudyError::io(path))?;
        let logs = folder.logs();
        std::fs::create_dir_all(&logs).map_err(StudyError::io(logs))?;
        Ok(folder)
    }
}

/// A study's folder and the places of its files.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct StudyFolder(pub PathBuf);

impl StudyFolder {
    /// The study's plan; a plan without cells is no study.
    pub fn plan(&self) -> Result<StudyPlan, StudyError> {
        let path = self.0.join(PLAN_FILE);
        let not_a_study = |reason: String| StudyError::NotAStudy {
            path: self.0.clone(),
            reason,
        };
        let text = read_text(&path, MAX_RUN_FILE_BYTES)
            .map_err(|e| not_a_study(format!("{}: {e}", path.display())))?;
        let plan: StudyPlan =
            serde_json::from_str(&text).map_err(|e| not_a_study(format!("{PLAN_FILE}: {e}")))?;
        if plan.cells.is_empty() {
            return Err(not_a_study(format!("{PLAN_FILE} lists no cells")));
        }
        Ok(plan)
    }

    /// Cell `index`'s run folder.
    pub fn cell(&self, index: usize) -> PathBuf {
        self.0.join("cells").join(index.to_string())
    }

    /// The folder of the cells' logs (Slurm's `%A_%a.out`, local runs' `local_<i>.out`).
    pub fn logs(&self) -> PathBuf {
        self.0.join("logs")
    }

    /// The log a local run of cell `index` writes.
    pub fn local_log(&self, index: usize) -> PathBuf {
        self.logs().join(format!("local_{index}.out"))
    }

    /// The newest log of cell `index`, local or Slurm's.
    pub fn newest_log(&self, index: usize) -> Option<PathBuf> {
        let suffix = format!("_{index}.out");
        std::fs::read_dir(self.logs())
            .ok()?
            .filter_map(Result::ok)
            .filter(|e| e.file_name().to_string_lossy().ends_with(&suffix))
            .max_by_key(|e| e.metadata().and_then(|m| m.modified()).ok())
            .map(|e| e.path())
    }

    /// The sbatch job-array script of a study of `kind`.
    pub fn script(&self, kind: StudyKind) -> PathBuf {
        self.0.join(format!("{}.sbatch", kind.name()))
    }
}
