//! Several runs' distance curves overlaid, one panel per feedback step and one colour per
//! label, with the legend in a cell of its own so it never covers a curve.

use super::canvas::{draw_panel, register_font, Line, Panel, FAMILY, PALETTE};
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

/// Width and height of the curves' image (px): 3 rows of 2 cells.
const CURVES_SIZE: (u32, u32) = (1400, 1500);

/// Draws `title` over one log-axis panel per entry of `panels` (its title and its curves,
/// the same labels in the same order in each) into `out`, the `events` (trial, label)
/// marked in each, and the legend in the cell after the last panel.
pub fn plot_curves(
    out: &Path,
    title: &str,
    y_label: &str,
    panels: &[(String, Vec<Curve>)],
    events: &[(f64, String)],
) -> Result<(), PlotError> {
    let draw_error = |reason: String| PlotError::Draw {
        path: out.to_path_buf(),
        reason,
    };
    register_font().map_err(draw_error)?;
    let root = BitMapBackend::new(out, CURVES_SIZE).into_drawing_area();
    root.fill(&WHITE).map_err(|e| draw_error(e.to_string()))?;
    let root = root
        .titled(title, (FAMILY, 22))
        .map_err(|e| draw_error(e.to_string()))?;
    // Room for the legend after the panels.
    let cells = root.split_evenly(((panels.len() + 1).div_ceil(2), 2));
    for (area, (name, curves)) in cells.iter().zip(panels) {
        let panel = Panel {
            title: name,
            y_label,
            lines: curves
                .iter()
                .enumerate()
                .map(|(i, c)| Line {
                    points: &c.points,
                    colour: PALETTE[i % PALETTE.len()],
                })
                .collect(),
            log_y: true,
            events,
        };
        draw_panel(area, &panel).map_err(draw_error)?;
    }
    if let (Some(area), Some((_, curves))) = (cells.get(panels.len()), panels.first()) {
        draw_legend(area, curves).map_err(draw_error)?;
    }
    root.present().map_err(|e| draw_error(e.to_string()))
}

/// The labels of `curves` in their colours, one a line.
fn draw_legend<DB: DrawingBackend>(
    area: &DrawingArea<DB, plotters::coord::Shift>,
    curves: &[Curve],
) -> Result<(), String> {
    let e = |e: DrawingAreaErrorKind<DB::ErrorType>| e.to_string();
    area.draw(&Text::new("legend", (40, 40), (FAMILY, 18).into_font()))
        .map_err(e)?;
    for (i, curve) in curves.iter().enumerate() {
        let y = 80 + 28 * i as i32;
        let colour = PALETTE[i % PALETTE.len()];
        area.draw(&PathElement::new(
            [(40, y), (80, y)],
            colour.stroke_width(3),
        ))
        .map_err(e)?;
        area.draw(&Text::new(
            curve.label.as_str(),
            (92, y - 8),
            (FAMILY, 16).into_font(),
        ))
        .map_err(e)?;
    }
    Ok(())
}
