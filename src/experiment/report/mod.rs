//! `eyehand report DIR`: one self-contained HTML page for a run folder — its panels as
//! interactive plots with the events marked, the arm in 3-D with its URDF's shapes replaying
//! chosen trials pose by pose beside the camera image, and its summary and `info` as
//! tables — or for a compare/sweep folder (its cells' curves per feedback step and its
//! table).

mod arm_scene;
mod json;
mod page;
mod panels;
mod trials;

pub use arm_scene::ArmScene;
pub use page::{VIEW_ORIGIN, VIEW_SIZE};

use crate::experiment::plot::PlotError;
use crate::experiment::show::{RecordedRun, ShowError};
use crate::experiment::study::{StudyError, StudyFolder};
use crate::files::{read_text, MAX_RUN_FILE_BYTES};
use crate::robot::DescriptionError;
use nalgebra::{Point3, Vector3};
use serde_json::{json, Value};
use std::path::{Path, PathBuf};

/// The file a report is written to, in the folder it reports on.
pub const REPORT_FILE: &str = "report.html";

/// What a report shows.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ReportOptions {
    /// The trials the 3-D view replays; empty: the first, each event's and the last.
    pub trials: Vec<usize>,
    /// Trials the distance curves are smoothed over (a trailing mean).
    pub smooth: usize,
}

impl Default for ReportOptions {
    fn default() -> ReportOptions {
        ReportOptions {
            trials: Vec::new(),
            smooth: 50,
        }
    }
}

/// Why a report could not be written.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum ReportError {
    /// The folder is neither a run's nor a study's.
    #[error(
        "{0} is neither a run folder (no info file) nor a compare or sweep folder (no cells.json)"
    )]
    NotAFolder(PathBuf),
    /// The run could not be replayed (or a trial asked for is not in it).
    #[error(transparent)]
    Show(#[from] ShowError),
    /// A data file could not be read.
    #[error(transparent)]
    Plot(#[from] PlotError),
    /// The study's plan could not be read.
    #[error(transparent)]
    Study(#[from] StudyError),
    /// The run's URDF could not be read again.
    #[error(transparent)]
    Urdf(#[from] DescriptionError),
    /// Writing the page failed.
    #[error("writing {path}: {source}")]
    Write {
        /// The page.
        path: PathBuf,
        /// Why.
        source: std::io::Error,
    },
}

impl ReportError {
    /// True when the error is the input's (exit code 2), not a failure while working.
    pub fn is_bad_input(&self) -> bool {
        !matches!(
            self,
            ReportError::Write { .. } | ReportError::Show(ShowError::Write { .. })
        )
    }
}

/// Writes `dir/report.html` for the run or study in `dir` and returns its path.
pub fn write_report(dir: &Path, options: &ReportOptions) -> Result<PathBuf, ReportError> {
    let (title, data) = if dir.join("info").is_file() {
        run_report(dir, options)?
    } else if dir.join("cells.json").is_file() {
        study_report(dir, options)?
    } else {
        return Err(ReportError::NotAFolder(dir.to_path_buf()));
    };
    let path = dir.join(REPORT_FILE);
    let partial = dir.join(".report.partial.html");
    let write = |path: &Path, e: std::io::Error| ReportError::Write {
        path: path.to_path_buf(),
        source: e,
    };
    std::fs::write(&partial, page::page(&title, &data)).map_err(|e| write(&partial, e))?;
    std::fs::rename(&partial, &path).map_err(|e| write(&path, e))?;
    Ok(path)
}

fn run_report(dir: &Path, options: &ReportOptions) -> Result<(String, Value), ReportError> {
    let run = RecordedRun::read(dir)?;
    let shown = shown_trials(&run, &options.trials)?;
    let scene = ArmScene::of(&run)?;
    let trials = trials::trials_json(&run, &scene, &shown)?;
    let model = &run.setup.model;
    let rest: Vec<[f32; 7]> = scene
        .body_frames(model, &model.rest())
        .iter()
        .map(json::pose_json)
        .collect();
    let mut arm = scene.to_json();
    arm["rest"] = json!(rest);
    let events: Vec<Value> = run
        .setup
        .events
        .iter()
        .map(|e| json!({"trial": e.trial(), "label": e.to_string()}))
        .collect();
    let info = read_text(&dir.join("info"), MAX_RUN_FILE_BYTES).unwrap_or_default();
    let summary: Value = read_text(&dir.join("summary.json"), MAX_RUN_FILE_BYTES)
        .ok()
        .and_then(|text| serde_json::from_str(&text).ok())
        .unwrap_or(Value::Null);
    let title = format!(
        "{}: {} on the {}, {} trials, seed {}",
        dir.display(),
        run.setup.config.method,
        scene.robot,
        run.trials,
        run.setup.config.seed
    );
    let view = view_of(&scene, &run, &trials);
    let data = json!({
        "kind": "run",
        "title": title,
        "panels": panels::run_panels(dir, options.smooth)?,
        "events": events,
        "arm": arm,
        "view": view,
        "trials": trials,
        "summary": summary,
        "info": info,
    });
    Ok((title, data))
}

/// The trials to replay: those asked for (each must be in the run), else the first, each
/// event's and the last; sorted, each once.
fn shown_trials(run: &RecordedRun, asked: &[usize]) -> Result<Vec<usize>, ShowError> {
    let mut trials: Vec<usize> = if asked.is_empty() {
        let events = run.setup.events.iter().map(|e| e.trial());
        [1, run.trials]
            .into_iter()
            .chain(events)
            .filter(|&t| t >= 1 && t <= run.trials)
            .collect()
    } else {
        for &trial in asked {
            run.check_trials(trial, trial)?;
        }
        asked.to_vec()
    };
    trials.sort_unstable();
    trials.dedup();
    Ok(trials)
}

/// Where the 3-D view looks from: at the middle of the arm at rest, the cameras and
/// targets of the shown trials, from the front right and above, far enough to see them all.
fn view_of(scene: &ArmScene, run: &RecordedRun, trials: &[Value]) -> Value {
    let model = &run.setup.model;
    let mut points: Vec<Point3<f64>> = scene
        .body_frames(model, &model.rest())
        .iter()
        .map(|f| f * Point3::origin())
        .collect();
    points.push(model.camera_position(&model.rest()));
    for trial in trials {
        if let Some(object) = trial["object"].as_array() {
            let c: Vec<f64> = object.iter().filter_map(Value::as_f64).collect();
            if let [x, y, z] = c[..] {
                points.push(Point3::new(x, y, z));
            }
        }
    }
    points.push(Point3::origin());
    let (low, high) = points.iter().fold(
        (
            Point3::from([f64::INFINITY; 3]),
            Point3::from([f64::NEG_INFINITY; 3]),
        ),
        |(low, high), p| (low.inf(p), high.sup(p)),
    );
    let target = nalgebra::center(&low, &high);
    let size = (high - low).norm().max(0.3);
    let eye = target + Vector3::new(1.0, -1.5, 0.8).normalize() * size * 1.6;
    json!({"eye": [eye.x, eye.y, eye.z], "target": [target.x, target.y, target.z], "fov": 40.0})
}

fn study_report(dir: &Path, options: &ReportOptions) -> Result<(String, Value), ReportError> {
    let folder = StudyFolder(dir.to_path_buf());
    let plan = folder.plan()?;
    let events: Vec<Value> = plan.cells[0]
        .request
        .events
        .iter()
        .map(|e| json!({"trial": e.trial(), "label": e.to_string()}))
        .collect();
    let cells: Vec<String> = plan
        .cells
        .iter()
        .map(|c| format!("{} seed {}", c.label, c.seed))
        .collect();
    let title = format!(
        "{}: {} of {} cells ({})",
        dir.display(),
        plan.kind.name(),
        plan.cells.len(),
        cells.join(", ")
    );
    let data = json!({
        "kind": "study",
        "title": title,
        "panels": panels::study_panels(&folder, &plan, options.smooth)?,
        "events": events,
        "table": read_text(&dir.join("table.md"), MAX_RUN_FILE_BYTES).ok(),
    });
    Ok((title, data))
}
