//! One PNG per run with the panels of the study's result figures: distance after feedback
//! steps 1..5 (log axis, mm), nodes, bins, memory, patterns and time used, each against
//! trials and smoothed, with the run's events marked. Long runs are drawn from evenly
//! spaced points of their smoothed curves.

use super::canvas::{draw_panel, register_font, Line, Panel, PALETTE};
use super::series::{decimated, event_trials, Series};
use super::PlotError;
use crate::files::{read_text, MAX_RUN_FILE_BYTES};
use plotters::prelude::*;
use std::path::{Path, PathBuf};

/// Width and height of a run's plot (px).
pub const PLOT_SIZE: (u32, u32) = (1400, 1800);
/// A line is drawn from at most about this many points (a panel is 700 px wide), so a
/// million-trial run plots as fast as a short one.
const POINTS_PER_LINE: usize = 4000;
/// Panels of a run's plot, in reading order (5 rows of 2).
pub const PANELS: [&str; 10] = [
    "distance after step 1",
    "distance after step 2",
    "distance after step 3",
    "distance after step 4",
    "distance after step 5",
    "nodes",
    "bins",
    "memory",
    "patterns",
    "time used",
];

/// Draws `<run_dir>/plot.png` from the run's data files, smoothing over `smooth` trials;
/// the image is drawn under a temporary name and renamed, so `plot.png` is whole or absent.
pub fn plot_run(run_dir: &Path, smooth: usize) -> Result<PathBuf, PlotError> {
    let read = |name: &str| {
        let path = run_dir.join(name);
        Series::read(&path).map_err(|source| PlotError::Read { path, source })
    };
    let info = read_text(&run_dir.join("info"), MAX_RUN_FILE_BYTES).unwrap_or_default();
    let events = event_trials(&info);
    let steps: Vec<Series> = (1..=5)
        .map(|s| read(&format!("{s}step")))
        .collect::<Result<_, _>>()?;
    let (nodes, bins, mem, patterns) = (
        read("nodes")?,
        read("bins")?,
        read("mem")?,
        read("patterns")?,
    );
    let thin = |points: &[(f64, f64)]| decimated(points, POINTS_PER_LINE);
    let mut lines: Vec<PanelLine> = steps
        .iter()
        .enumerate()
        .map(|(i, s)| (PANELS[i].to_string(), "mm", thin(&s.smoothed(smooth)), true))
        .collect();
    lines.push((PANELS[5].into(), "nodes", thin(&nodes.points), false));
    lines.push((PANELS[6].into(), "bins", thin(&bins.points), false));
    lines.push((PANELS[7].into(), "kB", thin(&mem.points), false));
    lines.push((PANELS[8].into(), "patterns", thin(&patterns.points), false));
    lines.push((PANELS[9].into(), "minutes", thin(&nodes.minutes), false));

    let out = run_dir.join("plot.png");
    let draw_error = |reason: String| PlotError::Draw {
        path: out.clone(),
        reason,
    };
    register_font().map_err(draw_error)?;
    let drawn = run_dir.join(".plot.partial.png");
    let title = title_of(run_dir, &info, nodes.points.len(), smooth);
    let result = draw_panels(&drawn, &title, &lines, &events)
        .and_then(|()| std::fs::rename(&drawn, &out).map_err(|e| e.to_string()));
    if let Err(reason) = result {
        let _ = std::fs::remove_file(&drawn);
        return Err(draw_error(reason));
    }
    Ok(out)
}

/// The plot's title: the method, simulator and seed the run's `info` records, the trials
/// it holds and the folder.
fn title_of(run_dir: &Path, info: &str, trials: usize, smooth: usize) -> String {
    let entry = |name: &str| {
        info.lines()
            .filter_map(|line| line.strip_prefix(name)?.strip_prefix(' '))
            .map(|rest| rest.split('#').next().unwrap_or("").trim())
            .next_back()
            .unwrap_or("?")
            .to_string()
    };
    format!(
        "{} on the {} simulator, seed {}, {trials} trials: {} (smoothed over {smooth} trials)",
        entry("method"),
        entry("sim"),
        entry("seed"),
        run_dir.display()
    )
}

/// A panel's title, y label, points and whether its y axis is logarithmic.
type PanelLine = (String, &'static str, Vec<(f64, f64)>, bool);

fn draw_panels(out: &Path, title: &str, lines: &[PanelLine], events: &[f64]) -> Result<(), String> {
    let root = BitMapBackend::new(out, PLOT_SIZE).into_drawing_area();
    root.fill(&WHITE).map_err(|e| e.to_string())?;
    let root = root
        .titled(title, (super::canvas::FAMILY, 22))
        .map_err(|e| e.to_string())?;
    for (area, (name, unit, points, log_y)) in root.split_evenly((5, 2)).iter().zip(lines) {
        let panel = Panel {
            title: name,
            y_label: unit,
            lines: vec![Line {
                points,
                colour: PALETTE[0],
                label: name.clone(),
            }],
            log_y: *log_y,
            events,
        };
        draw_panel(area, &panel)?;
    }
    root.present().map_err(|e| e.to_string())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_title_names_the_method_the_simulator_the_seed_and_the_trials() {
        let info = "# eyehand run\nconfig_file defaults\n\n# config\nmethod lin8  # --method\n\
                    sim dynamic  # default\nseed 7  # --seed\n";
        let title = title_of(Path::new("data/lin8/3"), info, 10_000, 50);
        assert_eq!(
            title,
            "lin8 on the dynamic simulator, seed 7, 10000 trials: data/lin8/3 (smoothed over 50 trials)"
        );
    }
}
