//! The study's Slurm job-array script: task i runs cell i through the binary's absolute
//! path, from the study's folder (`#SBATCH --chdir`), logging to `logs/%A_%a.out`; run by
//! hand it runs the cell given as its argument. Also the line that resubmits some cells.

use super::cells::{shell_quote, CellLauncher};
use super::plan::{StudyFolder, StudyPlan};
use super::StudyError;
use crate::experiment::{Config, SimKind};
use std::path::Path;

/// What the job script asks Slurm for, beyond one CPU per task.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct SlurmOptions {
    /// `--time` (e.g. `1:00:00`); `None`: the partition's default.
    pub time: Option<String>,
    /// `--mem` (e.g. `2G`); `None`: the cells' memory class (see [`memory_class_mb`]).
    pub mem: Option<String>,
    /// `--partition`; `None`: the cluster's default.
    pub partition: Option<String>,
    /// `--account`; `None`: the user's default.
    pub account: Option<String>,
    /// Further `#SBATCH` lines, each as given (`--qos=low` or `#SBATCH --qos=low`).
    pub extra: Vec<String>,
}

impl SlurmOptions {
    /// Refuses values that would break the script (line breaks, empty values).
    pub fn check(&self) -> Result<(), StudyError> {
        let named = [
            ("time", &self.time),
            ("mem", &self.mem),
            ("partition", &self.partition),
            ("account", &self.account),
        ];
        let given = named
            .into_iter()
            .filter_map(|(flag, value)| value.as_ref().map(|v| (flag, v)))
            .chain(self.extra.iter().map(|v| ("extra", v)));
        for (flag, value) in given {
            let word = |c: char| c.is_ascii_alphanumeric() || "_.-".contains(c);
            let reason = if value.trim().is_empty() {
                "is empty"
            } else if value.contains(['\n', '\r']) {
                "holds a line break"
            } else if flag == "mem" && !is_memory(value) {
                "is not a memory size (a whole number, optionally K, M, G or T: 2G, 512M)"
            } else if flag == "time"
                && !value
                    .chars()
                    .all(|c| c.is_ascii_digit() || c == ':' || c == '-')
            {
                "is not a Slurm time (minutes, or [days-]hours:minutes:seconds: 90, 1:30:00)"
            } else if (flag == "partition" || flag == "account") && !value.chars().all(word) {
                "is not a name (letters, digits, _ . -)"
            } else {
                continue;
            };
            return Err(StudyError::SlurmOption {
                flag,
                value: value.clone(),
                reason,
            });
        }
        Ok(())
    }
}

/// True for a Slurm memory size: digits, then at most one of K, M, G, T.
fn is_memory(value: &str) -> bool {
    let digits = value.trim_end_matches(['K', 'M', 'G', 'T', 'k', 'm', 'g', 't']);
    !digits.is_empty()
        && digits.chars().all(|c| c.is_ascii_digit())
        && value.len() - digits.len() <= 1
}

/// A cell's peak memory class (MB): twice the estimate from measured peaks, rounded up to a
/// power of two, at least 256 MB. The estimate is 9 MB, plus the method's stored patterns
/// per trial (its facts' `kb_per_trial`: 2.1 kB for lin5, 2.6 kB for lin8 and nnw, none for
/// the learners that keep no growing store), plus about 20 MB for Rapier's multibody.
pub fn memory_class_mb(config: &Config) -> u64 {
    let per_trial_kb = config.method.facts().kb_per_trial;
    let dynamic_mb = if config.sim == SimKind::Dynamic {
        20.0
    } else {
        0.0
    };
    let estimate_mb = 9.0 + dynamic_mb + per_trial_kb * config.trials as f64 / 1024.0;
    ((2.0 * estimate_mb).ceil() as u64)
        .next_power_of_two()
        .max(256)
}

/// The job script of `plan` in `folder`; `configs` are the cells' resolved configs.
pub fn slurm_script(
    folder: &StudyFolder,
    plan: &StudyPlan,
    configs: &[Config],
    launcher: &CellLauncher,
    options: &SlurmOptions,
) -> String {
    let last = plan.cells.len().saturating_sub(1);
    let mem = options.mem.clone().unwrap_or_else(|| {
        let mb = configs.iter().map(memory_class_mb).max().unwrap_or(256);
        format!("{mb}M")
    });
    let dir = folder.0.display().to_string();
    let mut lines = vec![
        "#!/bin/bash".to_string(),
        format!("#SBATCH --job-name=eyehand-{}", plan.kind.name()),
        format!("#SBATCH --array=0-{last}"),
        "#SBATCH --cpus-per-task=1".into(),
        format!("#SBATCH --chdir={}", sbatch_quote(&dir)),
        format!(
            "#SBATCH --output={}",
            sbatch_quote(&format!("{dir}/logs/%A_%a.out"))
        ),
        format!("#SBATCH --mem={mem}"),
    ];
    let optional = [
        ("time", &options.time),
        ("partition", &options.partition),
        ("account", &options.account),
    ];
    for (flag, value) in optional {
        if let Some(value) = value {
            lines.push(format!("#SBATCH --{flag}={value}"));
        }
    }
    for extra in &options.extra {
        match extra.trim_start().strip_prefix("#SBATCH") {
            Some(rest) => lines.push(format!("#SBATCH {}", rest.trim())),
            None => lines.push(format!("#SBATCH {}", extra.trim())),
        }
    }
    // The script's own path, quoted once for the shell and never inside double quotes: a
    // folder's `$`, backquotes and quotes stay characters.
    let script = shell_quote(&script_path(folder, plan));
    lines.extend([
        "set -euo pipefail".into(),
        format!("script={script}"),
        "cell=\"${SLURM_ARRAY_TASK_ID:-${1:-}}\"".into(),
        "if [ -z \"$cell\" ]; then".into(),
        format!(
            "  printf 'submit all {} cells: sbatch %q\\n' \"$script\" >&2",
            plan.cells.len()
        ),
        format!(
            "  printf 'or run one here:   bash %q CELL   (CELL = 0..{last})\\n' \"$script\" >&2"
        ),
        "  exit 2".into(),
        "fi".into(),
        format!("exec {} \"$cell\"", launcher.command_line(&folder.0)),
    ]);
    lines.join("\n") + "\n"
}

fn script_path(folder: &StudyFolder, plan: &StudyPlan) -> String {
    folder.script(plan.kind).display().to_string()
}

/// Refuses a data folder (absolute) whose studies' paths the job script's `#SBATCH --chdir`
/// and `--output` lines cannot carry: a line break, or `%` (which Slurm reads as a file
/// name pattern there). Anything else is quoted (`sbatch_quote`).
pub fn check_slurm_folder(data: &Path) -> Result<(), StudyError> {
    let text = data.display().to_string();
    match text.chars().find(|c| "\n\r%".contains(*c)) {
        Some(character) => Err(StudyError::SlurmPath {
            path: data.to_path_buf(),
            character,
        }),
        None => Ok(()),
    }
}

/// A value as an `#SBATCH` line carries it: as it is when plain, else in double quotes with
/// `\` and `"` escaped by a backslash (sbatch reads its script's option lines so; a `#`
/// outside quotes would start a comment there).
fn sbatch_quote(value: &str) -> String {
    let plain = value
        .chars()
        .all(|c| c.is_ascii_alphanumeric() || "-_./=:,+@".contains(c));
    if plain {
        value.to_string()
    } else {
        format!("\"{}\"", value.replace('\\', "\\\\").replace('"', "\\\""))
    }
}

/// Writes the study's job script (`<kind>.sbatch`) and returns its path.
pub fn write_slurm_script(
    folder: &StudyFolder,
    plan: &StudyPlan,
    configs: &[Config],
    launcher: &CellLauncher,
    options: &SlurmOptions,
) -> Result<std::path::PathBuf, StudyError> {
    let path = folder.script(plan.kind);
    let script = slurm_script(folder, plan, configs, launcher, options);
    std::fs::write(&path, script).map_err(StudyError::io(&path))?;
    Ok(path)
}

/// `sbatch --array=LIST SCRIPT` for the given cells, runs of indices written as ranges.
pub fn resubmit_line(script: &Path, indices: &[usize]) -> String {
    let mut parts: Vec<String> = Vec::new();
    let mut i = 0;
    while i < indices.len() {
        let start = indices[i];
        while i + 1 < indices.len() && indices[i + 1] == indices[i] + 1 {
            i += 1;
        }
        parts.push(match indices[i] {
            end if end == start => start.to_string(),
            end => format!("{start}-{end}"),
        });
        i += 1;
    }
    format!(
        "sbatch --array={} {}",
        parts.join(","),
        shell_quote(&script.display().to_string())
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::learn::Method;

    #[test]
    fn resubmit_lines_name_exactly_the_given_cells() {
        let script = Path::new("/d/sweep/0/sweep.sbatch");
        assert_eq!(
            resubmit_line(script, &[0, 1, 2, 5, 7, 8]),
            "sbatch --array=0-2,5,7-8 /d/sweep/0/sweep.sbatch"
        );
        assert_eq!(
            resubmit_line(Path::new("/my data/s.sbatch"), &[3]),
            "sbatch --array=3 '/my data/s.sbatch'"
        );
    }

    #[test]
    fn memory_classes_grow_with_the_tree_and_have_a_floor() {
        let mut config = Config::default_config();
        config.trials = 300;
        assert_eq!(memory_class_mb(&config), 256);
        config.trials = 1_000_000;
        assert_eq!(memory_class_mb(&config), 8192);
        config.method = Method::Ik;
        assert_eq!(memory_class_mb(&config), 256);
    }

    #[test]
    fn options_with_line_breaks_are_refused() {
        let bad = SlurmOptions {
            extra: vec!["--qos=low\nrm -rf /".into()],
            ..SlurmOptions::default()
        };
        assert!(matches!(bad.check(), Err(StudyError::SlurmOption { .. })));
        let empty = SlurmOptions {
            time: Some(" ".into()),
            ..SlurmOptions::default()
        };
        assert!(empty.check().is_err());
        assert!(SlurmOptions::default().check().is_ok());
    }
}
