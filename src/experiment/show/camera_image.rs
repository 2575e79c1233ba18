//! `camera_K.png`: the image the ray-cast camera sees from one pose of a trial. Each pixel
//! of the camera's N×N grid shows the scene its centre ray meets (`RaycastCamera::
//! render_scene`: the floor in dark tiles, obstacles light grey, the arm mid grey, empty
//! space the background grey) and over it the part of the target sphere nothing hides
//! (`RaycastCamera::render_in`): white in proportion to the pixel's coverage, its rim in
//! the grey of partly covered pixels. Under the image a caption strip gives the pose and its
//! reading; the image centre is marked by a cyan cross drawn only where the sphere is not,
//! so the blob's pixels stay exactly what the camera saw. Where the camera does not see the
//! object (its reading fails), the image shows the scene alone.

use super::arm_view::Area;
use super::tracer::Look;
use crate::camera::{CameraModel, PixelCoverage, RaycastCamera, Scene};
use crate::experiment::plot::{register_font, FAMILY};
use plotters::prelude::*;
use std::path::Path;

/// Height of the caption strip under the image (px).
pub const CAPTION_HEIGHT: u32 = 44;
/// Grey level of the empty background (where a ray meets nothing); the floor's tiles are
/// darker.
pub const BACKGROUND_GREY: u8 = 40;
/// Grey level of a pixel the sphere covers wholly; a partly covered pixel lies between
/// this and the background in proportion to its coverage.
pub const OBJECT_GREY: u8 = 255;
/// The colour of the image centre's cross.
pub const CENTRE_MARK: RGBColor = RGBColor(0, 200, 255);
/// Half-length of the centre cross's arms (px).
const CROSS_ARM: i64 = 40;

/// Writes the image seen at `look` in `scene` to `path`, with `resolution` rays per image
/// side (the ray-cast camera's own, or one ray per pixel) and `caption` under it.
pub fn write_camera_image(
    path: &Path,
    look: &Look,
    camera: &CameraModel,
    resolution: usize,
    scene: &dyn Scene,
    caption: &[String],
) -> Result<(), String> {
    let png = camera_image_png(look, camera, resolution, scene, caption)?;
    std::fs::write(path, png).map_err(|e| e.to_string())
}

/// The image [`write_camera_image`] writes, as the bytes of a PNG file.
pub fn camera_image_png(
    look: &Look,
    camera: &CameraModel,
    resolution: usize,
    scene: &dyn Scene,
    caption: &[String],
) -> Result<Vec<u8>, String> {
    register_font()?;
    let size = camera_image_size(camera);
    let mut rgb = vec![0; (size.0 * size.1 * 3) as usize];
    let root = BitMapBackend::with_buffer(&mut rgb, size).into_drawing_area();
    draw_camera_image(&root, look, camera, resolution, scene, caption)?;
    root.present().map_err(|e| e.to_string())?;
    drop(root);
    encode_png(&rgb, size).map_err(|e| e.to_string())
}

/// An 8-bit RGB image of `size` (px) as the bytes of a PNG file.
fn encode_png(rgb: &[u8], size: (u32, u32)) -> Result<Vec<u8>, png::EncodingError> {
    let mut bytes = Vec::new();
    let mut encoder = png::Encoder::new(&mut bytes, size.0, size.1);
    encoder.set_color(png::ColorType::Rgb);
    encoder.set_depth(png::BitDepth::Eight);
    encoder.set_compression(png::Compression::Best);
    encoder.set_adaptive_filter(png::AdaptiveFilterType::Adaptive);
    let mut writer = encoder.write_header()?;
    writer.write_image_data(rgb)?;
    writer.finish()?;
    Ok(bytes)
}

/// The size (px) of a camera image with its caption strip.
pub(super) fn camera_image_size(camera: &CameraModel) -> (u32, u32) {
    let (width, height) = (camera.width.round() as u32, camera.height.round() as u32);
    (width, height + CAPTION_HEIGHT)
}

/// The grey levels (row by row) of a `size` image of what the camera with a `resolution`
/// grid sees at `look` in `scene`: the scene alone, and the scene with the target sphere
/// where it is seen.
pub fn camera_greys(
    look: &Look,
    camera: &CameraModel,
    resolution: usize,
    scene: &dyn Scene,
    (width, height): (u32, u32),
) -> (Vec<u8>, Vec<u8>) {
    let rays = RaycastCamera::new(*camera, resolution);
    let n = rays.resolution();
    let mut background = vec![BACKGROUND_GREY; (width * height) as usize];
    for (k, grey) in rays
        .render_scene(&look.camera_pose, scene)
        .iter()
        .enumerate()
    {
        if let Some(grey) = *grey {
            paint(&mut background, n, (k % n, k / n), (width, height), |_| {
                grey
            });
        }
    }
    let mut image = background.clone();
    if look.reading.is_ok() {
        let blob = rays.render_in(&look.camera_pose, &look.object, scene);
        paint_blob(&mut image, n, &blob, (width, height));
    }
    (background, image)
}

/// Draws the image seen at `look` with `caption` under it on `root` (of
/// [`camera_image_size`]).
pub(super) fn draw_camera_image(
    root: &Area<'_>,
    look: &Look,
    camera: &CameraModel,
    resolution: usize,
    scene: &dyn Scene,
    caption: &[String],
) -> Result<(), String> {
    let (width, height) = (camera.width.round() as u32, camera.height.round() as u32);
    let (background, image) = camera_greys(look, camera, resolution, scene, (width, height));
    let e = |e: DrawingAreaErrorKind<_>| e.to_string();
    root.fill(&RGBColor(BACKGROUND_GREY, BACKGROUND_GREY, BACKGROUND_GREY))
        .map_err(e)?;
    let grey_at = |x: u32, y: u32| image[(y * width + x) as usize];
    let sphere_at = |x: u32, y: u32| {
        let k = (y * width + x) as usize;
        image[k] != background[k]
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
            if !sphere_at(x as u32, y as u32) {
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
    Ok(())
}

/// The grey level of every pixel of a `width`×`height` image in which the camera with a
/// `resolution` grid sees the object centred at `local` (camera frame) and nothing else,
/// row by row: each camera pixel paints the image pixels whose centres fall in it, in the
/// grey of its coverage (the Rerun recording's camera image).
#[cfg(feature = "rerun")]
pub(crate) fn blob_mask(
    camera: &CameraModel,
    resolution: usize,
    local: &nalgebra::Vector3<f64>,
    width: u32,
    height: u32,
) -> Vec<u8> {
    let rays = RaycastCamera::new(*camera, resolution);
    let mut mask = vec![BACKGROUND_GREY; (width * height) as usize];
    paint_blob(
        &mut mask,
        rays.resolution(),
        &rays.render(local),
        (width, height),
    );
    mask
}

/// Paints the sphere's `pixels` (an `n`×`n` grid) over `image`: each lightens what is under
/// it towards white in proportion to its coverage.
fn paint_blob(image: &mut [u8], n: usize, pixels: &[PixelCoverage], size: (u32, u32)) {
    for pixel in pixels {
        paint(image, n, (pixel.column, pixel.row), size, |under| {
            let span = f64::from(OBJECT_GREY - under);
            under + (span * pixel.coverage).round() as u8
        });
    }
}

/// Sets the image pixels whose centres fall in camera pixel (`column`, `row`) of an `n`×`n`
/// grid to `grey` of what they were.
fn paint(
    image: &mut [u8],
    n: usize,
    (column, row): (usize, usize),
    (width, height): (u32, u32),
    grey: impl Fn(u8) -> u8,
) {
    let cells = |index: usize, size: u32| {
        let cell = f64::from(size) / n as f64;
        let first = (index as f64 * cell - 0.5).ceil().max(0.0) as u32;
        let end = (((index + 1) as f64 * cell - 0.5).ceil().max(0.0) as u32).min(size);
        first..end
    };
    for y in cells(row, height) {
        for x in cells(column, width) {
            let at = (y * width + x) as usize;
            image[at] = grey(image[at]);
        }
    }
}
