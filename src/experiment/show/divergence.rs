//! A replay held against the run it replays: each trial's distance after step 1 must be the
//! one the run wrote into its `1step` file, else the folder's `info` no longer describes
//! that run (an entry was edited) and what would be drawn is another run's trial.

use super::{RecordedRun, ShowError};
use crate::experiment::plot::Series;
use crate::experiment::RunSummary;
use crate::files::{read_text, MAX_RUN_FILE_BYTES};
use std::collections::VecDeque;
use std::path::PathBuf;

/// The most a replayed distance may differ from the one written with six decimals (mm):
/// half the last written digit, and rounding.
const WRITTEN_PRECISION_MM: f64 = 0.5e-6 * 1.01;

/// The run's step-1 distances, trial by trial, to hold a replay against.
#[derive(Debug, Clone)]
pub(super) struct StepOneLog {
    path: PathBuf,
    /// (trial, distance) of the lines not yet checked.
    lines: VecDeque<(f64, f64)>,
}

impl StepOneLog {
    /// Reads `1step` of the run (trial and distance of each trial that took step 1, in trial
    /// order, as [`Series::read`] reads a data file); a missing file or a line that does not
    /// parse is an error.
    pub(super) fn read(run: &RecordedRun) -> Result<StepOneLog, ShowError> {
        let path = run.folder.join("1step");
        let bad = |reason: String| ShowError::BadInfo {
            path: path.clone(),
            reason,
        };
        if !path.is_file() {
            return Err(bad(
                "no such file: the run's step-1 distances are needed".into()
            ));
        }
        let series = Series::read(&path).map_err(|e| bad(e.to_string()))?;
        Ok(StepOneLog {
            lines: series.points.into_iter().collect(),
            path,
        })
    }

    /// Checks replayed trial `trial`, whose distance after step 1 was `replayed` (`None`: it
    /// took no step), against the run's line for it.
    pub(super) fn check(
        &mut self,
        run: &RecordedRun,
        trial: usize,
        replayed: Option<f64>,
    ) -> Result<(), ShowError> {
        let recorded = match self.lines.front() {
            Some(&(t, mm)) if t == trial as f64 => {
                self.lines.pop_front();
                Some(mm)
            }
            _ => None,
        };
        let same = match (recorded, replayed) {
            (Some(a), Some(b)) => (a - b).abs() <= WRITTEN_PRECISION_MM,
            (None, None) => true,
            _ => false,
        };
        if same {
            return Ok(());
        }
        Err(ShowError::Diverged {
            path: self.path.clone(),
            trial,
            recorded,
            replayed,
            entry: mismatched_entry(run),
        })
    }
}

/// The entry of the folder's `info` that its `summary.json` contradicts, if one does: the
/// seed, method, simulator, camera, events or obstacles.
fn mismatched_entry(run: &RecordedRun) -> Option<&'static str> {
    let text = read_text(&run.folder.join("summary.json"), MAX_RUN_FILE_BYTES).ok()?;
    let summary: RunSummary = serde_json::from_str(&text).ok()?;
    let config = &run.setup.config;
    let events: Vec<String> = run.setup.events.iter().map(|e| e.to_string()).collect();
    let obstacles: Vec<[f64; 6]> = config
        .obstacle
        .iter()
        .map(|o| o.centre_and_size())
        .collect();
    [
        ("seed", summary.seed != config.seed),
        ("method", summary.method != config.method.name()),
        ("sim", summary.sim != config.sim.to_string()),
        ("camera", summary.camera != config.camera.to_string()),
        ("event", summary.events != events),
        ("obstacle", summary.obstacles != obstacles),
    ]
    .into_iter()
    .find_map(|(entry, differs)| differs.then_some(entry))
}
