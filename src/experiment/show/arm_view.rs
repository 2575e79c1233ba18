//! `arm.png`: the arm in 3-D from the side (x to the right, z up) and from the top (x to
//! the right, y up), at a fixed scale so a pixel says where a point is. Every pose of the
//! trial is overlaid from light (start) to dark (last): the links as capsules between the
//! joint frames' origins, the camera centre and its optical axis; the target sphere, the
//! goal point above it, the base plane and the events in effect are drawn too.

use super::replay::TrialTrace;
use super::tracer::Look;
use crate::experiment::plot::{register_font, FAMILY};
use nalgebra::{Point3, Vector3};
use plotters::coord::Shift;
use plotters::prelude::*;
use std::path::Path;

/// Pixels per metre in both views.
pub const PIXELS_PER_METRE: f64 = 350.0;
/// Width and height of arm.png (px).
pub const ARM_IMAGE_SIZE: (u32, u32) = (1120, 900);
/// The colour of the last pose's camera centre.
pub const LAST_CAMERA_CENTRE: RGBColor = RGBColor(255, 0, 255);
/// Radius of the camera centre's dot (px).
const CAMERA_DOT: i32 = 4;
/// Length of the optical axis drawn from the camera centre (m).
const AXIS_LENGTH: f64 = 0.3;
/// Width of a link's capsule (px).
const LINK_WIDTH: u32 = 9;

/// One of the two views.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ArmView {
    /// Looking along −y: x to the right, z up.
    Side,
    /// Looking down: x to the right, y up.
    Top,
}

impl ArmView {
    /// The view's panel: left and top edge (px), and the world coordinates (m) at them
    /// (x at the left edge, z or y at the top edge), and its size (px).
    fn panel(self) -> ((f64, f64), (f64, f64), (u32, u32)) {
        match self {
            ArmView::Side => ((20.0, 60.0), (-0.35, 1.2), (525, 525)),
            ArmView::Top => ((575.0, 60.0), (-0.35, 1.05), (525, 735)),
        }
    }

    /// The pixel (column, row; before rounding) at which the world point `p` (m) is drawn
    /// in arm.png.
    pub fn pixel(self, p: &Point3<f64>) -> (f64, f64) {
        let ((left, top), (x0, up0), _) = self.panel();
        let up = match self {
            ArmView::Side => p.z,
            ArmView::Top => p.y,
        };
        (
            left + (p.x - x0) * PIXELS_PER_METRE,
            top + (up0 - up) * PIXELS_PER_METRE,
        )
    }

    fn name(self) -> &'static str {
        match self {
            ArmView::Side => "side: x →, z ↑",
            ArmView::Top => "top: x →, y ↑",
        }
    }
}

/// A drawing area of a bitmap, in a file or in memory.
pub(super) type Area<'a> = DrawingArea<BitMapBackend<'a>, Shift>;

/// Draws the trial's poses into `path` under `title`.
pub fn write_arm_image(path: &Path, trace: &TrialTrace, title: &str) -> Result<(), String> {
    register_font()?;
    let root = BitMapBackend::new(path, ARM_IMAGE_SIZE).into_drawing_area();
    draw_arm_image(&root, trace, title)?;
    root.present().map_err(|e| e.to_string())
}

/// Draws the trial's poses under `title` on `root` (of [`ARM_IMAGE_SIZE`]).
pub(super) fn draw_arm_image(
    root: &Area<'_>,
    trace: &TrialTrace,
    title: &str,
) -> Result<(), String> {
    let root = root.clone();
    root.fill(&WHITE).map_err(|e| e.to_string())?;
    text(&root, title, (20, 18), 18)?;
    for view in [ArmView::Side, ArmView::Top] {
        draw_view(&root, view, trace).map_err(|e| e.to_string())?;
    }
    let events = if trace.events.is_empty() {
        "events in effect: none".to_string()
    } else {
        let names: Vec<String> = trace.events.iter().map(ToString::to_string).collect();
        format!("events in effect: {}", names.join(", "))
    };
    let model = &trace.model;
    let changes = format!(
        "camera turned {:.1}°; links 1–3 stretched by {:.1}, {:.1}, {:.1} cm",
        model.camera_turn().to_degrees(),
        model.link_stretch(1) * 100.0,
        model.link_stretch(2) * 100.0,
        model.link_stretch(3) * 100.0
    );
    let legend = "poses light (start) → dark (last); magenta: last camera centre; \
                  blue: optical axis; red: target sphere, ring: goal";
    let bottom = ARM_IMAGE_SIZE.1 as i32;
    text(&root, &events, (20, bottom - 78), 15)?;
    text(&root, &changes, (20, bottom - 54), 15)?;
    text(&root, legend, (20, bottom - 30), 15)
}

fn text(root: &Area<'_>, line: &str, at: (i32, i32), size: u32) -> Result<(), String> {
    let style = (FAMILY, size).into_font().color(&BLACK);
    root.draw(&Text::new(line, at, style))
        .map_err(|e| e.to_string())
}

/// The grey of pose `k` of `n`: light for the first, dark for the last.
fn shade(k: usize, n: usize) -> u8 {
    let t = if n > 1 {
        k as f64 / (n - 1) as f64
    } else {
        1.0
    };
    (205.0 - 175.0 * t).round() as u8
}

fn draw_view<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    view: ArmView,
    trace: &TrialTrace,
) -> Result<(), DrawingAreaErrorKind<DB::ErrorType>> {
    let ((left, top), _, (w, h)) = view.panel();
    let at = |p: &Point3<f64>| {
        let (x, y) = view.pixel(p);
        (x.round() as i32, y.round() as i32)
    };
    let corner = (left as i32, top as i32);
    let far = (corner.0 + w as i32, corner.1 + h as i32);
    root.draw(&Rectangle::new([corner, far], BLACK.stroke_width(1)))?;
    root.draw(&Text::new(
        view.name(),
        (corner.0 + 6, corner.1 + 6),
        (FAMILY, 14).into_font(),
    ))?;
    let ten_cm = (corner.0 + 10, far.1 - 14);
    let bar_end = (ten_cm.0 + (0.1 * PIXELS_PER_METRE) as i32, ten_cm.1);
    root.draw(&PathElement::new([ten_cm, bar_end], BLACK.stroke_width(2)))?;
    root.draw(&Text::new(
        "10 cm",
        (bar_end.0 + 6, bar_end.1 - 7),
        (FAMILY, 13).into_font(),
    ))?;
    if view == ArmView::Side {
        let (a, b) = (Point3::new(-0.35, 0.0, 0.0), Point3::new(1.15, 0.0, 0.0));
        root.draw(&PathElement::new([at(&a), at(&b)], RGBColor(150, 110, 60)))?;
    }
    let base = at(&Point3::origin());
    root.draw(&Rectangle::new(
        [(base.0 - 14, base.1 - 4), (base.0 + 14, base.1 + 4)],
        RGBColor(90, 90, 90).filled(),
    ))?;
    let n = trace.looks.len();
    for (k, look) in trace.looks.iter().enumerate() {
        draw_pose(root, view, trace, look, shade(k, n))?;
    }
    if let Some(look) = trace.looks.first() {
        let object = at(&look.object);
        let radius = (0.02 * PIXELS_PER_METRE).round() as i32;
        root.draw(&Circle::new(object, radius, RGBColor(220, 30, 30).filled()))?;
        let goal = at(&(look.object + Vector3::z() * 0.2));
        root.draw(&Circle::new(goal, 6, RGBColor(220, 30, 30).stroke_width(2)))?;
    }
    if let Some(look) = trace.looks.last() {
        let centre = at(&(look.camera_pose * Point3::origin()));
        root.draw(&Circle::new(
            centre,
            CAMERA_DOT,
            LAST_CAMERA_CENTRE.filled(),
        ))?;
    }
    Ok(())
}

fn draw_pose<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    view: ArmView,
    trace: &TrialTrace,
    look: &Look,
    grey: u8,
) -> Result<(), DrawingAreaErrorKind<DB::ErrorType>> {
    let at = |p: &Point3<f64>| {
        let (x, y) = view.pixel(p);
        (x.round() as i32, y.round() as i32)
    };
    let colour = RGBColor(grey, grey, grey);
    let camera = look.camera_pose * Point3::origin();
    let mut chain = vec![at(&Point3::origin())];
    for frame in trace.model.link_frames(&look.joints).iter() {
        chain.push(at(&(frame * Point3::origin())));
    }
    chain.push(at(&camera));
    chain.dedup();
    // Segment by segment: a thick polyline's joins spike where two points nearly meet.
    for pair in chain.windows(2) {
        root.draw(&PathElement::new(
            [pair[0], pair[1]],
            colour.stroke_width(LINK_WIDTH),
        ))?;
    }
    for joint in &chain {
        root.draw(&Circle::new(*joint, LINK_WIDTH as i32 / 2, colour.filled()))?;
    }
    let axis_end = look.camera_pose * Point3::new(0.0, 0.0, AXIS_LENGTH);
    let blue = RGBColor(grey / 3, grey / 2 + 40, 255);
    root.draw(&PathElement::new(
        [at(&camera), at(&axis_end)],
        blue.stroke_width(2),
    ))?;
    root.draw(&Circle::new(
        at(&camera),
        CAMERA_DOT,
        RGBColor(255, 160, 40).filled(),
    ))
}
