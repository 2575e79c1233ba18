//! `eyehand compare`: every method on the same seeds and events, one cell each, with
//! `<configs>/<method>.conf` where it exists.

use super::plan::{Cell, StudyKind, StudyPlan};
use super::sweep::{check_cell_count, first_repeat};
use super::StudyError;
use crate::experiment::{Event, RunRequest};
use crate::learn::Method;
use std::path::{Path, PathBuf};

/// The per-method config folder used when none is named.
pub const DEFAULT_CONFIGS: &str = "configs";

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
    /// Config entries every run sets (`--set NAME=VALUE`, after its method's config).
    pub sets: Vec<(String, String)>,
    /// Folder of per-method configs (`<method>.conf`; a method without one runs the default
    /// config). `None`: `configs/` if it exists, else the default config for every method.
    pub configs: Option<PathBuf>,
}

/// The comparison's plan: each method × each seed, every cell's config checked first.
pub fn compare_plan(request: &CompareRequest) -> Result<StudyPlan, StudyError> {
    if let Some(method) = first_repeat(&request.methods) {
        return Err(StudyError::Duplicate {
            what: "method".into(),
            value: method.to_string(),
        });
    }
    if let Some(seed) = first_repeat(&request.seeds) {
        return Err(StudyError::Duplicate {
            what: "seed".into(),
            value: seed.to_string(),
        });
    }
    check_cell_count([request.methods.len(), request.seeds.len()])?;
    let configs = match &request.configs {
        Some(path) if !path.is_dir() => {
            return Err(StudyError::MissingConfigs { path: path.clone() })
        }
        Some(path) => Some(path.as_path()),
        None => Some(Path::new(DEFAULT_CONFIGS)).filter(|p| p.is_dir()),
    };
    let mut cells = Vec::new();
    for &method in &request.methods {
        let config = configs
            .map(|folder| folder.join(format!("{method}.conf")))
            .filter(|path| path.is_file());
        for &seed in &request.seeds {
            let request = RunRequest {
                config: config.clone(),
                sets: request.sets.clone(),
                method: Some(method),
                trials: Some(request.trials),
                seed: Some(seed),
                events: request.events.clone(),
                plot: false,
                ..RunRequest::default()
            };
            cells.push(Cell {
                label: method.to_string(),
                seed,
                request,
            });
        }
    }
    let plan = StudyPlan {
        kind: StudyKind::Compare,
        cells,
    };
    plan.check()?;
    Ok(plan)
}
