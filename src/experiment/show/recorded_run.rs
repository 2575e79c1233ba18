//! What a run folder says about how to rebuild the run: its `info` file holds the URDF, the
//! events in the order they were applied and every config value (seed included), and its
//! `nodes` file one line per finished trial.

use super::ShowError;
use crate::experiment::{Config, RunSetup, Sources};
use crate::files::{read_text, MAX_RUN_FILE_BYTES};
use crate::robot::DEFAULT_URDF_NAME;
use std::path::{Path, PathBuf};

/// A finished (or interrupted) run, as its folder records it.
#[derive(Debug, Clone)]
pub struct RecordedRun {
    /// The run folder.
    pub folder: PathBuf,
    /// The run put together again from its `info`: every config value it used, the robot
    /// as loaded at its start, its reach space and the events it applied, in order.
    pub setup: RunSetup,
    /// Trials the run finished.
    pub trials: usize,
}

impl RecordedRun {
    /// Reads a run folder; a folder without `info`, an `info` that does not parse or a URDF
    /// that is gone is an error.
    pub fn read(folder: &Path) -> Result<RecordedRun, ShowError> {
        let info_path = folder.join("info");
        let info =
            read_text(&info_path, MAX_RUN_FILE_BYTES).map_err(|source| ShowError::NotARun {
                folder: folder.to_path_buf(),
                source,
            })?;
        let bad = |reason: String| ShowError::BadInfo {
            path: info_path.clone(),
            reason,
        };
        let (header, rest) = info
            .split_once("\n# config\n")
            .ok_or_else(|| bad("no `# config` section".into()))?;
        let config_text = rest.split("\n# result\n").next().unwrap_or(rest);
        let config = Config::parse(config_text, &info_path.display().to_string())?;
        let mut urdf = None;
        let mut events = Vec::new();
        for line in header.lines() {
            if let Some(path) = line.strip_prefix("urdf ") {
                urdf = Some(path.trim().to_string());
            } else if let Some(event) = line.strip_prefix("event ") {
                events.push(
                    event
                        .parse()
                        .map_err(|e: crate::experiment::EventError| bad(e.to_string()))?,
                );
            }
        }
        let urdf = match urdf.as_deref() {
            None => return Err(bad("no `urdf` line".into())),
            Some(DEFAULT_URDF_NAME) => None,
            Some(path) => Some(PathBuf::from(path)),
        };
        let setup = RunSetup::new(config, urdf.as_deref(), events, &Sources::default())?;
        let nodes_path = folder.join("nodes");
        let nodes = read_text(&nodes_path, MAX_RUN_FILE_BYTES).map_err(|source| {
            ShowError::NoTrialList {
                path: nodes_path.clone(),
                source,
            }
        })?;
        Ok(RecordedRun {
            folder: folder.to_path_buf(),
            setup,
            trials: nodes.lines().count(),
        })
    }

    /// Checks that the run has every trial of `first..=last`.
    pub fn check_trials(&self, first: usize, last: usize) -> Result<(), ShowError> {
        for trial in [first, last] {
            if trial == 0 || trial > self.trials {
                return Err(ShowError::NoSuchTrial {
                    trial,
                    trials: self.trials,
                });
            }
        }
        Ok(())
    }
}
