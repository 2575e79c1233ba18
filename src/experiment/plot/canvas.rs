//! Shared drawing: the font, and one line panel (title, axes, smoothed series, labelled
//! event marks). Every point is drawn inside its panel and every tick label differs from its
//! neighbours.

use plotters::coord::Shift;
use plotters::prelude::*;
use std::sync::OnceLock;

/// The font every label is drawn with (shipped in assets/fonts, DejaVu Sans).
const FONT: &[u8] = include_bytes!("../../../assets/fonts/DejaVuSans.ttf");
/// The family name the font is registered under.
pub(crate) const FAMILY: &str = "sans-serif";

/// Registers the shipped font once per process.
pub(crate) fn register_font() -> Result<(), String> {
    static REGISTERED: OnceLock<bool> = OnceLock::new();
    let ok = *REGISTERED
        .get_or_init(|| plotters::style::register_font(FAMILY, FontStyle::Normal, FONT).is_ok());
    if ok {
        Ok(())
    } else {
        Err("the shipped font assets/fonts/DejaVuSans.ttf is not a valid font".into())
    }
}

/// One panel's content.
#[derive(Debug)]
pub(super) struct Panel<'a> {
    /// Title above the panel.
    pub title: &'a str,
    /// Y axis label.
    pub y_label: &'a str,
    /// Lines to draw.
    pub lines: Vec<Line<'a>>,
    /// Log-scaled y axis.
    pub log_y: bool,
    /// Events to mark with a vertical line: trial and label.
    pub events: &'a [(f64, String)],
}

/// One line of a panel.
#[derive(Debug)]
pub(super) struct Line<'a> {
    /// (trial, value) points.
    pub points: &'a [(f64, f64)],
    /// Its colour.
    pub colour: RGBColor,
}

type Area<'a> = DrawingArea<BitMapBackend<'a>, Shift>;

/// A panel's x range and y range. A log axis spans whole decades from the smallest
/// positive value's to the largest's, so every panel has labels across its data; when some
/// value is 0 (or below), the range reaches one decade lower, and that bottom is the
/// floor the zeros are drawn on.
pub(super) fn bounds(lines: &[Line<'_>], log_y: bool) -> ((f64, f64), (f64, f64)) {
    let points = lines.iter().flat_map(|l| l.points.iter());
    let (mut x, mut y) = ((f64::MAX, f64::MIN), (f64::MAX, f64::MIN));
    let mut not_positive = false;
    for &(px, py) in points {
        x = (x.0.min(px), x.1.max(px));
        if log_y && py <= 0.0 {
            not_positive = true;
            continue;
        }
        y = (y.0.min(py), y.1.max(py));
    }
    if x.0 > x.1 {
        return ((0.0, 1.0), if log_y { (1e-3, 1.0) } else { (0.0, 1.0) });
    }
    let x = if x.1 > x.0 { x } else { (x.0 - 0.5, x.1 + 0.5) };
    let y = if log_y {
        if y.0 > y.1 {
            (0.1, 1.0)
        } else {
            let decade = |v: f64, round: fn(f64) -> f64| 10f64.powf(round(v.log10()));
            let low = decade(y.0, f64::floor) / if not_positive { 10.0 } else { 1.0 };
            // A hair wider, so the decades at both ends get their labels.
            let high = decade(y.1, f64::ceil).max(low * 10.0);
            (low * (1.0 - 1e-9), high * (1.0 + 1e-9))
        }
    } else {
        let span = y.1 - y.0;
        let pad = if span > 0.0 {
            0.05 * span
        } else {
            (0.05 * y.1.abs()).max(1.0)
        };
        let low = if y.0 >= 0.0 {
            (y.0 - pad).max(0.0)
        } else {
            y.0 - pad
        };
        (low, y.1 + pad)
    };
    (x, y)
}

/// Draws one panel into `area`.
pub(super) fn draw_panel(area: &Area<'_>, panel: &Panel<'_>) -> Result<(), String> {
    let ((x0, x1), (y0, y1)) = bounds(&panel.lines, panel.log_y);
    let zeros = panel.log_y
        && panel
            .lines
            .iter()
            .any(|l| l.points.iter().any(|p| p.1 <= 0.0));
    let y_desc = if zeros {
        format!("{} (0 drawn on the bottom line)", panel.y_label)
    } else {
        panel.y_label.to_string()
    };
    let mut builder = ChartBuilder::on(area);
    builder
        .caption(panel.title, (FAMILY, 18))
        .margin(8)
        // Room for the last x label, centred on the axis's end.
        .margin_right(36)
        .x_label_area_size(32)
        .y_label_area_size(62);
    // Every point inside the panel: on a log axis the zeros lie on its bottom, the floor.
    let inside = |&(x, y): &(f64, f64)| (x.clamp(x0, x1), y.clamp(y0, y1));
    let decimals = tick_decimals(y0, y1, Y_LABELS);
    let y_tick = |y: &f64| {
        if panel.log_y {
            compact(*y)
        } else {
            format!("{y:.decimals$}")
        }
    };
    macro_rules! finish {
        ($chart:expr) => {{
            let mut chart = $chart.map_err(|e| e.to_string())?;
            chart
                .configure_mesh()
                .x_desc("trial")
                .max_light_lines(2)
                .y_desc(y_desc.as_str())
                .label_style((FAMILY, 12))
                .y_labels(Y_LABELS)
                .x_label_formatter(&|x| format!("{x:.0}"))
                .y_label_formatter(&y_tick)
                .draw()
                .map_err(|e| e.to_string())?;
            for (k, (trial, label)) in panel.events.iter().enumerate() {
                let trial = trial.clamp(x0, x1);
                chart
                    .draw_series(LineSeries::new(
                        [(trial, y0), (trial, y1)],
                        RED.stroke_width(1),
                    ))
                    .map_err(|e| e.to_string())?;
                let style = (FAMILY, 12).into_font().color(&RED);
                let offset = (4, 4 + 14 * k as i32);
                chart
                    .draw_series(std::iter::once(
                        EmptyElement::at((trial, y1)) + Text::new(label.clone(), offset, style),
                    ))
                    .map_err(|e| e.to_string())?;
            }
            for line in &panel.lines {
                chart
                    .draw_series(LineSeries::new(
                        line.points.iter().map(inside),
                        line.colour.stroke_width(2),
                    ))
                    .map_err(|e| e.to_string())?;
            }
        }};
    }
    if panel.log_y {
        finish!(builder.build_cartesian_2d(x0..x1, (y0..y1).log_scale()));
    } else {
        finish!(builder.build_cartesian_2d(x0..x1, y0..y1));
    }
    Ok(())
}

/// Labels asked for on a y axis.
const Y_LABELS: usize = 12;

/// Decimals that tell apart the labels of a linear axis from `low` to `high` with about
/// `labels` ticks: as many as the tick step needs (a 0.0002 step gets 4, a 100 step none).
pub(super) fn tick_decimals(low: f64, high: f64, labels: usize) -> usize {
    let step = (high - low) / labels.max(1) as f64;
    if !(step.is_finite() && step > 0.0) {
        return 0;
    }
    (-step.log10()).ceil().max(0.0) as usize
}

/// A log axis's label: plain for ordinary magnitudes, `1e-5` style for tiny or huge ones.
fn compact(v: f64) -> String {
    let a = v.abs();
    if a == 0.0 {
        "0".into()
    } else if !(1e-3..1e6).contains(&a) {
        let exponent = a.log10().floor();
        let mantissa = v / 10f64.powf(exponent);
        if (mantissa.abs() - 1.0).abs() < 1e-6 {
            format!("1e{exponent:.0}")
        } else {
            format!("{mantissa:.1}e{exponent:.0}")
        }
    } else {
        let text = format!("{v:.3}");
        text.trim_end_matches('0').trim_end_matches('.').to_string()
    }
}

/// The palette lines are drawn in, one colour per series.
pub(super) const PALETTE: [RGBColor; 10] = [
    RGBColor(31, 119, 180),
    RGBColor(255, 127, 14),
    RGBColor(44, 160, 44),
    RGBColor(148, 103, 189),
    RGBColor(140, 86, 75),
    RGBColor(23, 190, 207),
    RGBColor(227, 119, 194),
    RGBColor(127, 127, 127),
    RGBColor(188, 189, 34),
    RGBColor(214, 39, 40),
];

#[cfg(test)]
mod tests {
    use super::*;

    fn line(points: &[(f64, f64)]) -> Line<'_> {
        Line {
            points,
            colour: BLACK,
        }
    }

    use plotters::coord::ranged1d::Ranged;
    use plotters::coord::types::RangedCoordf64;

    /// The colour of the test's line.
    const INK: RGBColor = RGBColor(200, 0, 100);

    /// Size of the test's image: two panels side by side.
    const SIZE: (u32, u32) = (800, 300);

    /// Draws `points` (and an event halfway) into the left panel of a 2×1 image.
    fn drawn(points: &[(f64, f64)], log_y: bool) -> Vec<u8> {
        register_font().unwrap();
        let mut rgb = vec![255u8; (SIZE.0 * SIZE.1 * 3) as usize];
        {
            let root = BitMapBackend::with_buffer(&mut rgb, SIZE).into_drawing_area();
            let panels = root.split_evenly((1, 2));
            let line = Line {
                points,
                colour: INK,
            };
            let events = [(points[points.len() / 2].0, "rotate:3:90".to_string())];
            let panel = Panel {
                title: "nodes",
                y_label: "nodes",
                lines: vec![line],
                log_y,
                events: &events,
            };
            draw_panel(&panels[0], &panel).unwrap();
            root.present().unwrap();
        }
        rgb
    }

    /// The pixels (x, y) of `rgb` for which `colour` holds.
    fn pixels(rgb: &[u8], colour: impl Fn([u8; 3]) -> bool) -> Vec<(u32, u32)> {
        let (w, h) = SIZE;
        (0..h)
            .flat_map(|y| (0..w).map(move |x| (x, y)))
            .filter(|&(x, y)| {
                let i = ((y * w + x) * 3) as usize;
                colour([rgb[i], rgb[i + 1], rgb[i + 2]])
            })
            .collect()
    }

    /// The line's pixels outside its panel (in the right one).
    fn pixels_outside(points: &[(f64, f64)], log_y: bool) -> usize {
        let ink = |p: [u8; 3]| p == [INK.0, INK.1, INK.2];
        let rgb = drawn(points, log_y);
        pixels(&rgb, ink)
            .iter()
            .filter(|(x, _)| *x >= SIZE.0 / 2)
            .count()
    }

    #[test]
    fn events_are_marked_and_labelled() {
        let points: Vec<(f64, f64)> = (1..=6).map(|t| (f64::from(t), 1.0)).collect();
        let rgb = drawn(&points, false);
        let red = pixels(&rgb, |[r, g, b]| r > 200 && g < 160 && b < 160);
        let mut columns: Vec<u32> = red.iter().map(|(x, _)| *x).collect();
        columns.sort_unstable();
        columns.dedup();
        // The line is one column; its label's letters span dozens more.
        assert!(columns.len() > 30, "red in {} columns", columns.len());
    }

    #[test]
    fn no_curve_point_is_drawn_outside_its_panel() {
        // Steep growth, huge values, zeros on a log axis, a single point.
        let steep: Vec<(f64, f64)> = (1..=500)
            .map(|t| (f64::from(t), f64::from(t).powi(3)))
            .collect();
        assert_eq!(pixels_outside(&steep, false), 0);
        assert_eq!(pixels_outside(&steep, true), 0);
        let zeros = [(1.0, 0.0), (2.0, 5.0), (3.0, 0.0), (4.0, 1e9)];
        assert_eq!(pixels_outside(&zeros, true), 0);
        assert_eq!(pixels_outside(&[(7.0, 3.0)], false), 0);
    }

    #[test]
    fn tick_labels_of_a_linear_axis_are_distinct() {
        // The time used of a short run: 0 to 0.0025 minutes.
        for (low, high) in [
            (0.0, 0.0025),
            (0.0, 1.0),
            (8500.0, 10_000.0),
            (0.0, 70.0),
            (-3e-6, 2e-6),
        ] {
            let decimals = tick_decimals(low, high, Y_LABELS);
            let labels: Vec<String> = RangedCoordf64::from(low..high)
                .key_points(Y_LABELS)
                .iter()
                .map(|y| format!("{y:.decimals$}"))
                .collect();
            let mut distinct = labels.clone();
            distinct.dedup();
            assert_eq!(distinct, labels, "{low}..{high}");
            assert!(labels.len() >= 3, "{labels:?}");
            if high - low >= 12.0 {
                assert!(
                    labels.iter().all(|l| !l.contains('.')),
                    "whole numbers: {labels:?}"
                );
            }
        }
    }

    #[test]
    fn a_log_axis_spans_whole_decades_over_its_data() {
        // A sweep's 4-step curves from 0.2 to 40 mm: labels from 0.1 to 100.
        let points = [(1.0, 40.0), (10_000.0, 0.2)];
        let (x, y) = bounds(&[line(&points)], true);
        assert_eq!(x, (1.0, 10_000.0));
        let near = |a: f64, b: f64| (a / b - 1.0).abs() < 1e-6;
        assert!(near(y.0, 0.1) && y.0 < 0.1, "{y:?}");
        assert!(near(y.1, 100.0) && y.1 > 100.0, "{y:?}");
    }

    #[test]
    fn zeros_lie_on_a_floor_one_decade_below_the_smallest_value() {
        // ik's zeros beside learners at 0.01..30 mm: the floor at 1e-3, not at 1e-6.
        let ik = [(1.0, 0.0), (100.0, 0.0)];
        let learner = [(1.0, 30.0), (100.0, 0.01)];
        let (_, y) = bounds(&[line(&ik), line(&learner)], true);
        let near = |a: f64, b: f64| (a / b - 1.0).abs() < 1e-6;
        assert!(near(y.0, 1e-3) && near(y.1, 100.0), "{y:?}");
        let (_, only_zeros) = bounds(&[line(&ik)], true);
        assert_eq!(only_zeros, (0.1, 1.0));
    }
}
