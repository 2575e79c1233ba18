//! A run folder's `info` file: the header written before the first trial (version, host,
//! config and where each value came from) and the result appended after the last.

use super::run_options::RunOptions;
use crate::experiment::output::summary::RunSummary;
use crate::experiment::RunSetup;
use crate::learn::LearnerStats;
use std::io::{self, Write};
use std::path::Path;

fn host_name() -> String {
    std::fs::read_to_string("/proc/sys/kernel/hostname")
        .map(|h| h.trim().to_string())
        .unwrap_or_else(|_| "unknown".into())
}

/// Writes the `info` file's header: the version, host, config file, URDF, events and
/// the config with where each value came from.
pub(super) fn write_info_header(
    folder: &Path,
    options: &RunOptions,
    setup: &RunSetup,
) -> io::Result<()> {
    let mut info = std::fs::File::create(folder.join("info"))?;
    writeln!(info, "# eyehand {} run", env!("CARGO_PKG_VERSION"))?;
    writeln!(info, "host {}", host_name())?;
    writeln!(info, "config_file {}", options.config_name)?;
    let urdf = setup
        .config
        .urdf
        .path()
        .map_or(crate::robot::DEFAULT_URDF_NAME.to_string(), |p| {
            p.display().to_string()
        });
    writeln!(info, "urdf {urdf}")?;
    for event in &setup.events {
        writeln!(info, "event {event}")?;
    }
    writeln!(info, "\n# config")?;
    info.write_all(setup.config.explained_text(&setup.sources).as_bytes())
}

/// Appends the run's result and its tree per level to the `info` file.
pub(super) fn write_info_tail(
    folder: &Path,
    summary: &RunSummary,
    stats: &LearnerStats,
) -> io::Result<()> {
    let mut info = std::fs::OpenOptions::new()
        .append(true)
        .open(folder.join("info"))?;
    writeln!(info, "\n# result")?;
    writeln!(info, "wall_seconds {:.3}", summary.wall_seconds)?;
    writeln!(
        info,
        "trials_per_hour {:.0}",
        summary.trials_per_second * 3600.0
    )?;
    writeln!(info, "failures {}", summary.failures)?;
    if let Some(not_learned) = &summary.not_learned {
        writeln!(info, "not_learned {}", not_learned.reason)?;
    }
    if summary.interrupted {
        writeln!(info, "interrupted after trial {}", summary.trials)?;
    }
    writeln!(
        info,
        "physics_steps_per_trial {:.1}",
        summary.physics_steps_per_trial
    )?;
    writeln!(
        info,
        "simulated_seconds_per_trial {:.4}",
        summary.simulated_seconds_per_trial
    )?;
    writeln!(info, "settle_timeouts {}", summary.settle_timeouts)?;
    writeln!(info, "stopped_by_contact {}", summary.stopped_by_contact)?;
    writeln!(info, "speed_faults {}", summary.speed_faults)?;
    let figure = |v: Option<f64>| v.map_or("-".to_string(), |v| format!("{v:.4}"));
    writeln!(
        info,
        "final_distance_mm mean {} median {}",
        figure(summary.mean_final_distance_mm),
        figure(summary.median_final_distance_mm)
    )?;
    writeln!(
        info,
        "reached_epsilon {} of {} (mean {} simulated s)",
        summary.reached_epsilon,
        summary.window,
        figure(summary.mean_seconds_to_epsilon)
    )?;
    writeln!(info, "peak_rss_kb {}", summary.peak_rss_kb)?;
    writeln!(info, "\n# tree per level: depth nodes bins patterns error")?;
    for (depth, level) in stats.levels.iter().enumerate() {
        let error = level.error.map_or("-".to_string(), |e| format!("{e:.6e}"));
        writeln!(
            info,
            "{depth} {} {} {} {error}",
            level.nodes, level.bins, level.patterns
        )?;
    }
    Ok(())
}
