//! `eyehand sweep`: the cross product of config settings and seeds, one run each, side by
//! side; or, with `--slurm`, an sbatch job-array script whose task i runs cell i with the
//! same command line.

use super::cells::{Cell, CellResult};
use super::Config;
use std::path::Path;

/// One `--set name=v1,v2,…` of a sweep.
#[derive(Debug, Clone, PartialEq)]
pub struct Setting {
    /// The config entry.
    pub name: String,
    /// Its values, as written.
    pub values: Vec<String>,
}

impl std::str::FromStr for Setting {
    type Err = String;

    fn from_str(text: &str) -> Result<Self, String> {
        let (name, values) = text
            .split_once('=')
            .ok_or_else(|| format!("`{text}`: expected name=value[,value…]"))?;
        let values: Vec<String> = values.split(',').map(str::to_string).collect();
        if name.is_empty() || values.iter().any(String::is_empty) {
            return Err(format!("`{text}`: expected name=value[,value…]"));
        }
        Ok(Setting {
            name: name.to_string(),
            values,
        })
    }
}

/// Seeds from `1..5` (inclusive) or `1,2,3`.
pub fn parse_seeds(text: &str) -> Result<Vec<u64>, String> {
    let bad = || format!("`{text}`: seeds are FIRST..LAST or a list like 1,2,3");
    if let Some((first, last)) = text.split_once("..") {
        let (first, last): (u64, u64) = (
            first.parse().map_err(|_| bad())?,
            last.parse().map_err(|_| bad())?,
        );
        if first > last {
            return Err(bad());
        }
        return Ok((first..=last).collect());
    }
    text.split(',')
        .map(|s| s.trim().parse().map_err(|_| bad()))
        .collect()
}

/// Every combination of the settings' values (the first setting varies slowest).
pub fn combinations(settings: &[Setting]) -> Vec<Vec<(String, String)>> {
    settings.iter().fold(vec![Vec::new()], |done, setting| {
        done.iter()
            .flat_map(|prefix| {
                setting.values.iter().map(move |value| {
                    let mut next = prefix.clone();
                    next.push((setting.name.clone(), value.clone()));
                    next
                })
            })
            .collect()
    })
}

/// The sweep's cells: every combination × every seed, each checked against the config
/// first so a bad setting fails before any run starts.
pub fn sweep_cells(
    config_path: &Path,
    settings: &[Setting],
    seeds: &[u64],
    data: &Path,
) -> Result<Vec<Cell>, String> {
    let base = Config::from_file(config_path).map_err(|e| e.to_string())?;
    let mut cells = Vec::new();
    for combination in combinations(settings) {
        let mut config = base.clone();
        let mut flags = vec!["--config".to_string(), config_path.display().to_string()];
        for (name, value) in &combination {
            config
                .set(name, value)
                .map_err(|e| format!("--set {name}={value}: {e}"))?;
            flags.extend(["--set".to_string(), format!("{name}={value}")]);
        }
        let label = combination
            .iter()
            .map(|(n, v)| format!("{n}={v}"))
            .collect::<Vec<_>>()
            .join(" ");
        for &seed in seeds {
            cells.push(Cell {
                label: label.clone(),
                seed,
                args: Cell::run_args(&flags, seed, data),
            });
        }
    }
    Ok(cells)
}

/// An sbatch job-array script: array task i runs cell i's command line.
pub fn slurm_script(cells: &[Cell], program: &str) -> String {
    let mut script = String::from("#!/bin/bash\n");
    script += "#SBATCH --job-name=eyehand-sweep\n";
    script += &format!("#SBATCH --array=0-{}\n", cells.len().saturating_sub(1));
    script += "#SBATCH --cpus-per-task=1\n#SBATCH --output=eyehand-sweep-%A_%a.out\n";
    script += "set -euo pipefail\ncase \"$SLURM_ARRAY_TASK_ID\" in\n";
    for (i, cell) in cells.iter().enumerate() {
        script += &format!("  {i}) exec {} ;;\n", cell.command_line(program));
    }
    script += "  *) echo \"no cell $SLURM_ARRAY_TASK_ID\" >&2; exit 2 ;;\nesac\n";
    script
}

/// The sweep's markdown table: one row per cell.
pub fn sweep_table(runs: &[CellResult]) -> String {
    let mut table = String::from("| setting | seed | 1 step (mm) | 2 steps | 3 steps | 4 steps | 5 steps | trials/s | nodes | run |\n");
    table += "|---|---|---|---|---|---|---|---|---|---|\n";
    for run in runs {
        let s = &run.summary;
        let steps: Vec<String> = s
            .mean_distance_mm
            .iter()
            .map(|d| d.map_or("-".into(), |d| format!("{d:.4}")))
            .collect();
        table += &format!(
            "| {} | {} | {} | {:.0} | {} | {} |\n",
            run.cell.label,
            run.cell.seed,
            steps.join(" | "),
            s.trials_per_second,
            s.nodes,
            run.folder.display()
        );
    }
    table
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn settings_and_seeds_parse() {
        let s: Setting = "split_error=1e-4,1e-5".parse().unwrap();
        assert_eq!(s.values, ["1e-4", "1e-5"]);
        assert!("split_error".parse::<Setting>().is_err());
        assert!("split_error=1,".parse::<Setting>().is_err());
        assert_eq!(parse_seeds("1..5").unwrap(), vec![1, 2, 3, 4, 5]);
        assert_eq!(parse_seeds("3,1").unwrap(), vec![3, 1]);
        assert!(parse_seeds("5..1").is_err());
        assert!(parse_seeds("a").is_err());
    }

    #[test]
    fn combinations_are_the_cross_product() {
        let a: Setting = "a=1,2".parse().unwrap();
        let b: Setting = "b=x,y,z".parse().unwrap();
        let all = combinations(&[a, b]);
        assert_eq!(all.len(), 6);
        assert_eq!(
            all[0],
            vec![("a".into(), "1".into()), ("b".into(), "x".into())]
        );
        assert_eq!(
            all[5],
            vec![("a".into(), "2".into()), ("b".into(), "z".into())]
        );
    }
}
