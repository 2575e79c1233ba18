//! Several runs' 4-step distance curves overlaid in one PNG, one colour per label.

use super::canvas::{draw_panel, register_font, Line, Panel, PALETTE};
use super::PlotError;
use plotters::prelude::*;
use std::path::Path;

/// A labelled curve: (trial, value) points.
#[derive(Debug, Clone, PartialEq)]
pub struct Curve {
    /// The legend label.
    pub label: String,
    /// The points.
    pub points: Vec<(f64, f64)>,
}

/// Draws `curves` overlaid on a log axis into `out` (1200×800 px).
pub fn plot_curves(
    out: &Path,
    title: &str,
    y_label: &str,
    curves: &[Curve],
    events: &[f64],
) -> Result<(), PlotError> {
    let draw_error = |reason: String| PlotError::Draw {
        path: out.to_path_buf(),
        reason,
    };
    register_font().map_err(draw_error)?;
    let root = BitMapBackend::new(out, (1200, 800)).into_drawing_area();
    root.fill(&WHITE).map_err(|e| draw_error(e.to_string()))?;
    let panel = Panel {
        title,
        y_label,
        lines: curves
            .iter()
            .enumerate()
            .map(|(i, c)| Line {
                points: &c.points,
                colour: PALETTE[i % PALETTE.len()],
                label: c.label.clone(),
            })
            .collect(),
        log_y: true,
        events,
    };
    draw_panel(&root, &panel).map_err(draw_error)?;
    root.present().map_err(|e| draw_error(e.to_string()))
}
