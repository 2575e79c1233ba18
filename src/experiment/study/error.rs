//! Why a comparison or sweep cannot be planned, run or gathered.

use crate::experiment::plot::PlotError;
use crate::experiment::{RequestError, RunFolderError};
use std::path::PathBuf;

/// Why a study failed; [`StudyError::is_bad_input`] tells the user's mistakes from failures.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum StudyError {
    /// Seeds that are neither `FIRST..LAST` nor a list of numbers.
    #[error("`{text}`: seeds are FIRST..LAST or a list like 1,2,3")]
    BadSeeds {
        /// What was given.
        text: String,
    },
    /// A `--set` that is not `NAME=V1,V2,…`.
    #[error("`{text}`: expected name=value[,value…]")]
    BadSetting {
        /// What was given.
        text: String,
    },
    /// More cells than a study may have.
    #[error("{cells} cells is more than the {max} a study may have (seeds × settings × methods)")]
    TooManyCells {
        /// Cells asked for (saturated at `u64::MAX`).
        cells: u64,
        /// The limit.
        max: usize,
    },
    /// The same seed, method or value twice.
    #[error("{what} `{value}` is given twice")]
    Duplicate {
        /// `seed`, `method` or the entry's name.
        what: String,
        /// The repeated value.
        value: String,
    },
    /// The same setting crossed twice.
    #[error("--set {name} is given more than once")]
    RepeatedSetting {
        /// The entry.
        name: String,
    },
    /// `--set seed=…`: the seeds are given by `--seeds`.
    #[error("--set seed: give the seeds with --seeds (e.g. --seeds 1..4)")]
    SeedSetting,
    /// The per-method config folder does not exist.
    #[error("--configs {}: no such folder", .path.display())]
    MissingConfigs {
        /// The folder.
        path: PathBuf,
    },
    /// A cell's run is invalid (its config, overrides or paths).
    #[error("cell {index} ({label}, seed {seed}): {source}")]
    Cell {
        /// The cell's index.
        index: usize,
        /// What it varies.
        label: String,
        /// Its seed.
        seed: u64,
        /// Why.
        source: Box<RequestError>,
    },
    /// No cell of that index.
    #[error("no cell {index}: the study has cells 0 to {}", .cells.saturating_sub(1))]
    NoSuchCell {
        /// The index asked for.
        index: usize,
        /// How many cells there are.
        cells: usize,
    },
    /// The folder holds no readable study.
    #[error("{}: not a comparison or sweep folder ({reason})", .path.display())]
    NotAStudy {
        /// The folder.
        path: PathBuf,
        /// Why.
        reason: String,
    },
    /// A Slurm option that cannot go into the job script.
    #[error("--slurm-{flag} `{value}`: {reason}")]
    SlurmOption {
        /// The option, without `--slurm-`.
        flag: &'static str,
        /// What was given.
        value: String,
        /// Why it is refused.
        reason: &'static str,
    },
    /// A study folder whose path the job script's `#SBATCH` lines cannot carry.
    #[error(
        "{}: a Slurm job script cannot name this folder in its #SBATCH lines (it holds \
         {character:?}; Slurm reads % as a pattern in file names); give --data a path \
         without % or line breaks, or run the cells here",
        path.display()
    )]
    SlurmPath {
        /// The study's folder.
        path: std::path::PathBuf,
        /// The first character #SBATCH lines cannot carry.
        character: char,
    },
    /// No folder for the study.
    #[error(transparent)]
    Folder(#[from] RunFolderError),
    /// The curves could not be drawn.
    #[error(transparent)]
    Plot(#[from] PlotError),
    /// Reading or writing the study's files, or starting a cell, failed.
    #[error("{}: {source}", .path.display())]
    Io {
        /// The file or program.
        path: PathBuf,
        /// Why.
        source: std::io::Error,
    },
}

impl StudyError {
    /// Whether the user asked for something invalid (exit code 2) rather than the work failing.
    pub fn is_bad_input(&self) -> bool {
        !matches!(
            self,
            StudyError::Folder(_) | StudyError::Plot(_) | StudyError::Io { .. }
        )
    }

    /// An I/O error at `path`.
    pub(crate) fn io(path: impl Into<PathBuf>) -> impl FnOnce(std::io::Error) -> StudyError {
        let path = path.into();
        move |source| StudyError::Io { path, source }
    }
}
