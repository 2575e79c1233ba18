//! The lines on how the tree is built up that `verbose_output` asks for, every
//! `depth_info` trials: above the progress bar when the run has one (stderr is a terminal
//! and the run is not `--quiet`), otherwise into the run folder's `tree_lines` file, so a
//! run whose output goes to a log or a pipe does not flood it.

use super::progress_bar::RunProgress;
use crate::learn::LearnerStats;
use std::fs::File;
use std::io::{self, BufWriter, Write};
use std::path::{Path, PathBuf};

/// The file the lines go to when there is no terminal.
pub const TREE_LINES_FILE: &str = "tree_lines";

/// Where a run's tree lines go.
#[derive(Debug)]
pub(super) struct TreeLines {
    /// Printed above the progress bar, or written to `path`.
    to_terminal: bool,
    path: PathBuf,
    /// Made with the first line.
    file: Option<BufWriter<File>>,
}

impl TreeLines {
    /// Lines for the run in `folder`; `to_terminal`: the run shows a progress bar.
    pub(super) fn new(folder: &Path, to_terminal: bool) -> TreeLines {
        TreeLines {
            to_terminal,
            path: folder.join(TREE_LINES_FILE),
            file: None,
        }
    }

    /// The line of `trial` with the learner's `stats`.
    pub(super) fn write(
        &mut self,
        trial: usize,
        stats: &LearnerStats,
        progress: &RunProgress,
    ) -> io::Result<()> {
        let line = tree_line(trial, stats);
        if self.to_terminal {
            progress.println(&line);
            return Ok(());
        }
        let file = match &mut self.file {
            Some(file) => file,
            None => self.file.insert(BufWriter::new(File::create(&self.path)?)),
        };
        writeln!(file, "{line}")
    }

    /// Writes out what is buffered.
    pub(super) fn flush(&mut self) -> io::Result<()> {
        self.file.as_mut().map_or(Ok(()), Write::flush)
    }
}

/// One line on how the tree is built up.
fn tree_line(trial: usize, stats: &LearnerStats) -> String {
    let mut line = format!(
        "trial {trial}: {} nodes, {} bins, {} patterns |",
        stats.nodes, stats.bins, stats.patterns
    );
    for (depth, level) in stats.levels.iter().enumerate().filter(|(_, l)| l.nodes > 0) {
        let error = level.error.map_or("-".to_string(), |e| format!("{e:.2e}"));
        line += &format!(" d{depth}: {} nodes, error {error};", level.nodes);
    }
    line
}
