//! The Rerun side of a recording: entity paths, timelines and archetypes.
//!
//! Entities (world frame: x forward, y left, z up, metres):
//! - `world/arm/link_1` … `link_6`: a capsule from the link's joint to the next joint (or
//!   the camera centre), with the link frame's transform; `world/arm/base` the column's foot.
//! - `world/arm/camera`: the camera frame's transform and a pinhole (x along the image's
//!   columns, y along its rows, z the optical axis); `world/arm/camera/image` the ray-cast
//!   camera's grey image at every pose.
//! - `world/target` the sphere, `world/goal` the point the run's standoff above it,
//!   `world/camera_path` the camera centre's path so far in the trial.
//! - `plots/distance_mm`: the distance to the goal after each feedback step.
//!
//! Timelines: `sim_time` (simulated seconds, running on across the recorded trials) and
//! `trial`. The arm is logged at every physics tick on the dynamic simulator and at every
//! pose on the kinematic one.

use super::RecordReport;
use crate::camera::{CameraModel, RaycastCamera};
use crate::experiment::setup::camera_model;
use crate::experiment::show::{
    blob_mask, remove_scratch_patterns, replay, show_folder, Look, RecordedRun, ShowError,
    TrialRange, TrialTrace, BACKGROUND_GREY,
};
use crate::experiment::CameraKind;
use crate::robot::{ArmModel, Frames, Joints};
use nalgebra::{Isometry3, Point3, Vector3};
use rerun::{
    Capsules3D, Ellipsoids3D, Image, LineStrips3D, Pinhole, Points3D, RecordingStream, Scalars,
    Transform3D, ViewCoordinates,
};
use std::path::Path;

/// Capsule radius of the links (m).
const LINK_RADIUS: f32 = 0.03;
/// Pause on `sim_time` between two recorded trials (s), where the arm is placed anew.
const TRIAL_GAP: f64 = 0.5;

/// Re-simulates trials `range` of the run in `run_dir` and logs them to `out`.
pub(super) fn record(
    run_dir: &Path,
    range: TrialRange,
    out: &Path,
) -> Result<RecordReport, ShowError> {
    let run = RecordedRun::read(run_dir)?;
    run.check_trials(range.first, range.last)?;
    let failed = |reason: String| ShowError::Write {
        path: out.to_path_buf(),
        reason,
    };
    let stream = rerun::RecordingStreamBuilder::new("eyehand")
        .save(out)
        .map_err(|e| failed(e.to_string()))?;
    let camera = camera_model(&run.setup.config);
    let resolution = match run.setup.config.camera {
        CameraKind::Raycast => run.setup.config.raycast_resolution,
        CameraKind::Projection => (camera.width / 2.0).round() as usize,
    };
    let mut log = TrialLogger {
        stream,
        camera,
        resolution: RaycastCamera::new(camera, resolution).resolution(),
        clock: 0.0,
        report: RecordReport::default(),
    };
    log.world().map_err(|e| failed(e.to_string()))?;
    let scratch = show_folder(run_dir)?;
    replay(
        &run,
        range.last,
        |t| range.contains(t),
        true,
        &scratch,
        |trace| log.trial(&trace).map_err(|e| failed(e.to_string())),
    )?;
    remove_scratch_patterns(&scratch);
    log.stream
        .flush_blocking()
        .map_err(|e| failed(e.to_string()))?;
    Ok(log.report)
}

type Logged = Result<(), rerun::RecordingStreamError>;

/// Logs trials one after another on one stream.
struct TrialLogger {
    stream: RecordingStream,
    camera: CameraModel,
    /// Rays (pixels) per side of the logged images.
    resolution: usize,
    clock: f64,
    report: RecordReport,
}

fn f32x3(v: &Vector3<f64>) -> [f32; 3] {
    [v.x as f32, v.y as f32, v.z as f32]
}

fn transform(pose: &Isometry3<f64>) -> Transform3D {
    let q = pose.rotation.quaternion();
    Transform3D::from_translation_rotation(
        f32x3(&pose.translation.vector),
        rerun::Quaternion::from_xyzw([q.i as f32, q.j as f32, q.k as f32, q.w as f32]),
    )
}

/// The link frames and the camera frame of `joints`.
fn frames(model: &ArmModel, joints: &Joints) -> (Frames, Isometry3<f64>) {
    let links = model.link_frames(joints);
    (links, links.last() * model.camera_mount())
}

impl TrialLogger {
    /// What holds for the whole recording: the world's axes.
    fn world(&self) -> Logged {
        self.stream
            .log_static("world", &ViewCoordinates::RIGHT_HAND_Z_UP())
    }

    fn at(&self, sim_time: f64) {
        self.stream
            .set_duration_secs("sim_time", self.clock + sim_time);
    }

    fn trial(&mut self, trace: &TrialTrace) -> Logged {
        let Some(first) = trace.looks.first() else {
            return Ok(());
        };
        self.stream.set_time_sequence("trial", trace.trial as i64);
        self.at(0.0);
        self.shapes(&trace.model)?;
        let radius = self.camera.object_radius as f32;
        self.stream.log(
            "world/target",
            &Ellipsoids3D::from_centers_and_radii([f32x3(&first.object.coords)], [radius])
                .with_colors([rerun::Color::from_rgb(220, 30, 30)]),
        )?;
        let goal = self.camera.goal_point(&first.object);
        self.stream
            .log("world/goal", &Points3D::new([f32x3(&goal.coords)]))?;
        let mut path = Vec::new();
        let mut ticks = trace.ticks.iter().peekable();
        for (k, look) in trace.looks.iter().enumerate() {
            if k > 0 && trace.ticks.is_empty() {
                self.arm(&trace.model, &look.joints, look.sim_time)?;
            }
            while let Some((time, joints)) = ticks.next_if(|(t, _)| *t <= look.sim_time + 1e-9) {
                self.arm(&trace.model, joints, *time)?;
            }
            if k == 0 {
                self.arm(&trace.model, &look.joints, 0.0)?;
            }
            self.at(look.sim_time);
            let centre = look.camera_pose * Point3::origin();
            path.push(f32x3(&centre.coords));
            self.stream
                .log("world/camera_path", &LineStrips3D::new([path.clone()]))?;
            self.image(look)?;
            if k > 0 && look.reading.is_ok() {
                let distance = (centre - goal).norm() * crate::units::MM_PER_M;
                self.stream
                    .log("plots/distance_mm", &Scalars::single(distance))?;
            }
        }
        let end = trace.looks.last().map_or(0.0, |l| l.sim_time);
        self.clock += end + TRIAL_GAP;
        self.report.trials += 1;
        Ok(())
    }

    /// The links' capsules in their own frames and the camera's pinhole, as the robot is
    /// during this trial (a stretched link is longer).
    fn shapes(&self, model: &ArmModel) -> Logged {
        let joints = model.joints();
        let base = joints[0].origin.translation.vector;
        self.stream
            .log("world/arm/base", &capsule(&Vector3::zeros(), &base))?;
        for k in 0..joints.len() {
            let next = if k + 1 < joints.len() {
                joints[k + 1].origin.translation.vector
            } else {
                model.camera_mount().translation.vector
            };
            self.stream.log(
                format!("world/arm/link_{}", k + 1),
                &capsule(&Vector3::zeros(), &next),
            )?;
        }
        let n = self.resolution as f32;
        let scale = n / self.camera.width as f32;
        self.stream.log(
            "world/arm/camera",
            &Pinhole::from_focal_length_and_resolution(
                [self.camera.focal as f32 * scale; 2],
                [n, n],
            )
            .with_image_plane_distance(0.1),
        )
    }

    /// The arm at `joints`, at `sim_time` into the trial.
    fn arm(&mut self, model: &ArmModel, joints: &Joints, sim_time: f64) -> Logged {
        self.at(sim_time);
        let (links, camera) = frames(model, joints);
        for (k, frame) in links.iter().enumerate() {
            self.stream
                .log(format!("world/arm/link_{}", k + 1), &transform(frame))?;
        }
        self.stream.log("world/arm/camera", &transform(&camera))?;
        self.report.arm_transforms += 1;
        Ok(())
    }

    /// The camera's image at a pose: the object's rays in grey levels, blank when unseen.
    fn image(&mut self, look: &Look) -> Logged {
        let n = self.resolution as u32;
        let pixels = if look.reading.is_ok() {
            let local = look
                .camera_pose
                .inverse_transform_point(&look.object)
                .coords;
            blob_mask(&self.camera, n as usize, &local, n, n)
        } else {
            vec![BACKGROUND_GREY; (n * n) as usize]
        };
        self.stream
            .log("world/arm/camera/image", &Image::from_l8(pixels, [n, n]))?;
        self.report.images += 1;
        Ok(())
    }
}

/// A capsule from `from` to `to` in its entity's frame.
fn capsule(from: &Vector3<f64>, to: &Vector3<f64>) -> Capsules3D {
    let along = to - from;
    let length = along.norm();
    let turn =
        nalgebra::UnitQuaternion::rotation_between(&Vector3::z(), &along).unwrap_or_else(|| {
            nalgebra::UnitQuaternion::from_axis_angle(&Vector3::x_axis(), std::f64::consts::PI)
        });
    let q = turn.quaternion();
    Capsules3D::from_lengths_and_radii([length as f32], [LINK_RADIUS])
        .with_translations([f32x3(from)])
        .with_quaternions([rerun::Quaternion::from_xyzw([
            q.i as f32, q.j as f32, q.k as f32, q.w as f32,
        ])])
        .with_colors([rerun::Color::from_rgb(120, 120, 130)])
}
