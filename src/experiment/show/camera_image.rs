//! `camera_K.png`: the image the ray-cast camera sees from one pose of a trial. Each pixel
//! of the camera's N×N grid records how much of it the target sphere covers
//! (`RaycastCamera::render`), and that coverage is its grey level: a white sphere on a dark
//! background (nothing else is in the scene yet), its rim in the grey of partly covered
//! pixels. Under the image a caption strip gives the pose and its reading; the image
//! centre is marked by a cyan cross drawn only over the background, so the blob's pixels
//! stay exactly what the camera saw. Where the camera does not see the object (its reading
//! fails), the image is left blank.

use super::watch::Look;
use crate::camera::{CameraModel, RaycastCamera};
use crate::experiment::plot::{register_font, FAMILY};
use plotters::prelude::*;
use std::path::Path;

/// Height of the caption strip under the image (px).
pub const CAPTION_HEIGHT: u32 = 44;
/// Grey level of the empty background.
pub const BACKGROUND_GREY: u8 = 40;
/// Grey level of a pixel the sphere covers wholly; a partly covered pixel lies between
/// this and the background in proportion to its coverage.
pub const OBJECT_GREY: u8 = 255;
/// The colour of the image centre's cross.
pub const CENTRE_MARK: RGBColor = RGBColor(0, 200, 255);
/// Half-length of the centre cross's arms (px).
const CROSS_ARM: i64 = 40;

/// Writes the image seen at `look` to `path`, with `resolution` rays per image side (the
/// ray-cast camera's own, or one ray per pixel) and `caption` under it.
pub fn write_camera_image(
    path: &Path,
    look: &Look,
    camera: &CameraModel,
    resolution: usize,
    caption: &[String],
) -> Result<(), String> {
    let (width, height) = (camera.width.round() as u32, camera.height.round() as u32);
    let object = look.reading.is_ok().then(|| {
        let local = look
            .camera_pose
            .inverse_transform_point(&look.object)
            .coords;
        blob_mask(camera, resolution, &local, width, height)
    });
    register_font()?;
    let root = BitMapBackend::new(path, (width, height + CAPTION_HEIGHT)).into_drawing_area();
    let e = |e: DrawingAreaErrorKind<_>| e.to_string();
    root.fill(&RGBColor(BACKGROUND_GREY, BACKGROUND_GREY, BACKGROUND_GREY))
        .map_err(e)?;
    let grey_at = |x: u32, y: u32| {
        object
            .as_ref()
            .map_or(BACKGROUND_GREY, |m| m[(y * width + x) as usize])
    };
    for y in 0..height {
        for x in 0..width {
            let grey = grey_at(x, y);
            if grey != BACKGROUND_GREY {
                root.draw_pixel((x as i32, y as i32), &RGBColor(grey, grey, grey))
                    .map_err(e)?;
            }
        }
    }
    let (cx, cy) = ((width / 2) as i64, (height / 2) as i64);
    for d in -CROSS_ARM..CROSS_ARM {
        for (x, y) in [
            (cx + d, cy - 1),
            (cx + d, cy),
            (cx - 1, cy + d),
            (cx, cy + d),
        ] {
            if grey_at(x as u32, y as u32) == BACKGROUND_GREY {
                root.draw_pixel((x as i32, y as i32), &CENTRE_MARK)
                    .map_err(e)?;
            }
        }
    }
    let strip = RGBColor(0, 0, 0);
    root.draw(&Rectangle::new(
        [
            (0, height as i32),
            (width as i32, (height + CAPTION_HEIGHT) as i32),
        ],
        strip.filled(),
    ))
    .map_err(e)?;
    for (i, line) in caption.iter().enumerate() {
        let style = (FAMILY, 15).into_font().color(&WHITE);
        root.draw(&Text::new(
            line.as_str(),
            (6, height as i32 + 4 + 19 * i as i32),
            style,
        ))
        .map_err(e)?;
    }
    root.present().map_err(e)
}

/// The grey level of every pixel of a `width`×`height` image in which the camera with a
/// `resolution` grid sees the object centred at `local` (camera frame), row by row: each
/// camera pixel paints the image pixels whose centres fall in it, in the grey of its
/// coverage.
pub(crate) fn blob_mask(
    camera: &CameraModel,
    resolution: usize,
    local: &nalgebra::Vector3<f64>,
    width: u32,
    height: u32,
) -> Vec<u8> {
    let rays = RaycastCamera::new(*camera, resolution);
    let n = rays.resolution() as f64;
    let mut mask = vec![BACKGROUND_GREY; (width * height) as usize];
    let cells = |index: usize, size: u32| {
        let cell = f64::from(size) / n;
        let first = (index as f64 * cell - 0.5).ceil().max(0.0) as u32;
        let end = (((index + 1) as f64 * cell - 0.5).ceil().max(0.0) as u32).min(size);
        first..end
    };
    let span = f64::from(OBJECT_GREY - BACKGROUND_GREY);
    for pixel in rays.render(local) {
        let grey = BACKGROUND_GREY + (span * pixel.coverage).round() as u8;
        for y in cells(pixel.row, height) {
            for x in cells(pixel.column, width) {
                mask[(y * width + x) as usize] = grey;
            }
        }
    }
    mask
}
