//! A frame in memory, as `render()` of the Python environments draws it: arm.png's side
//! and top views of a trial's poses beside the camera image at its last pose, both drawn as
//! `eyehand show` draws them.

use super::arm_view::{draw_arm_image, ARM_IMAGE_SIZE};
use super::camera_image::{camera_image_size, draw_camera_image};
use super::replay::TrialTrace;
use crate::camera::{CameraModel, Scene};
use crate::experiment::plot::register_font;
use plotters::prelude::*;

/// An RGB image, row by row, three bytes a pixel.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct RgbFrame {
    /// Width (px).
    pub width: u32,
    /// Height (px).
    pub height: u32,
    /// The pixels' red, green and blue.
    pub rgb: Vec<u8>,
}

/// What a frame shows beside the arm: the camera's view of the trial's last pose.
#[derive(Clone, Copy)]
pub struct FrameView<'a> {
    /// The camera's intrinsics.
    pub camera: &'a CameraModel,
    /// Rays per image side (the ray-cast camera's own, or one per pixel).
    pub resolution: usize,
    /// What else the camera sees: the world at the last pose.
    pub scene: &'a dyn Scene,
}

impl std::fmt::Debug for FrameView<'_> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("FrameView")
            .field("camera", self.camera)
            .field("resolution", &self.resolution)
            .finish_non_exhaustive()
    }
}

/// The size (px) of a frame of `camera`'s images.
pub fn frame_size(camera: &CameraModel) -> (u32, u32) {
    let (cam_w, cam_h) = camera_image_size(camera);
    (ARM_IMAGE_SIZE.0 + cam_w, ARM_IMAGE_SIZE.1.max(cam_h))
}

/// Draws `trace` (at least one look) under `title`, and its last look as the camera sees
/// it with `caption` under it, into one frame.
pub fn draw_frame(
    trace: &TrialTrace,
    title: &str,
    view: &FrameView<'_>,
    caption: &[String],
) -> Result<RgbFrame, String> {
    let last = trace.looks.last().ok_or("a frame needs a pose to draw")?;
    register_font()?;
    let (width, height) = frame_size(view.camera);
    let mut rgb = vec![0u8; 3 * width as usize * height as usize];
    {
        let root = BitMapBackend::with_buffer(&mut rgb, (width, height)).into_drawing_area();
        root.fill(&WHITE).map_err(|e| e.to_string())?;
        let (arm, side) = root.split_horizontally(ARM_IMAGE_SIZE.0);
        draw_arm_image(&arm, trace, title)?;
        let (camera, _) = side.split_vertically(camera_image_size(view.camera).1);
        draw_camera_image(
            &camera,
            last,
            view.camera,
            view.resolution,
            view.scene,
            caption,
        )?;
        root.present().map_err(|e| e.to_string())?;
    }
    Ok(RgbFrame { width, height, rgb })
}
