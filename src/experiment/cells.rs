//! Cells of a comparison or sweep: one `eyehand run` command line each, run side by side
//! as separate processes (so each has its own memory figures), their summaries read back.

use super::RunSummary;
use rayon::prelude::*;
use std::path::{Path, PathBuf};
use std::process::Command;

/// One run of a comparison or sweep.
#[derive(Debug, Clone, PartialEq)]
pub struct Cell {
    /// What the cell varies, for tables (e.g. `lin5` or `split_error=1e-5`).
    pub label: String,
    /// The seed.
    pub seed: u64,
    /// The arguments after `eyehand`.
    pub args: Vec<String>,
}

/// A finished cell.
#[derive(Debug, Clone, PartialEq)]
pub struct CellResult {
    /// The cell.
    pub cell: Cell,
    /// Its run folder.
    pub folder: PathBuf,
    /// Its summary.
    pub summary: RunSummary,
}

/// Why a cell failed.
#[derive(Debug, thiserror::Error)]
#[error("`eyehand {}` failed: {reason}", .args.join(" "))]
pub struct CellError {
    /// The cell's arguments.
    pub args: Vec<String>,
    /// What went wrong.
    pub reason: String,
}

impl Cell {
    /// The `eyehand run` arguments of a cell writing into `data`, quiet and without a plot.
    pub fn run_args(run_flags: &[String], seed: u64, data: &Path) -> Vec<String> {
        let mut args = vec!["run".to_string()];
        args.extend(run_flags.iter().cloned());
        args.extend([
            "--seed".into(),
            seed.to_string(),
            "--data".into(),
            data.display().to_string(),
        ]);
        args.extend(["--quiet".into(), "--no-plot".into()]);
        args
    }

    /// The cell as one shell command line, each argument quoted where it needs it.
    pub fn command_line(&self, program: &str) -> String {
        std::iter::once(program.to_string())
            .chain(self.args.iter().map(|a| shell_quote(a)))
            .collect::<Vec<_>>()
            .join(" ")
    }
}

/// `arg` quoted for a POSIX shell.
pub fn shell_quote(arg: &str) -> String {
    let plain = !arg.is_empty()
        && arg
            .chars()
            .all(|c| c.is_ascii_alphanumeric() || "-_./=:,+".contains(c));
    if plain {
        arg.to_string()
    } else {
        format!("'{}'", arg.replace('\'', r"'\''"))
    }
}

/// Runs every cell with `program` (the eyehand binary), in parallel across cores.
pub fn run_cells(program: &Path, cells: &[Cell]) -> Vec<Result<CellResult, CellError>> {
    cells
        .par_iter()
        .map(|cell| run_cell(program, cell))
        .collect()
}

fn run_cell(program: &Path, cell: &Cell) -> Result<CellResult, CellError> {
    let fail = |reason: String| CellError {
        args: cell.args.clone(),
        reason,
    };
    let output = Command::new(program)
        .args(&cell.args)
        .output()
        .map_err(|e| fail(e.to_string()))?;
    if !output.status.success() {
        return Err(fail(
            String::from_utf8_lossy(&output.stderr).trim().to_string(),
        ));
    }
    let stdout = String::from_utf8_lossy(&output.stdout);
    let folder = PathBuf::from(stdout.lines().last().unwrap_or_default().trim());
    let json = std::fs::read_to_string(folder.join("summary.json"))
        .map_err(|e| fail(format!("{}: {e}", folder.display())))?;
    let summary = serde_json::from_str(&json).map_err(|e| fail(e.to_string()))?;
    Ok(CellResult {
        cell: cell.clone(),
        folder,
        summary,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn arguments_are_quoted_only_when_needed() {
        assert_eq!(shell_quote("split_error=1e-5"), "split_error=1e-5");
        assert_eq!(shell_quote("/tmp/my data"), "'/tmp/my data'");
        assert_eq!(shell_quote("it's"), r"'it'\''s'");
        assert_eq!(shell_quote(""), "''");
    }
}
