//! `eyehand show`: per shown trial, `RUN_DIR/show/N/` gets `camera_K.png` for every pose
//! (K = 0 the start, K = k after feedback step k), `arm.png` and `trial.json` (the poses as
//! numbers: joints, camera centre, reading, distance to the goal, simulated time).

use super::arm_view::write_arm_image;
use super::camera_image::camera_image_png;
use super::replay::{replay, TrialTrace};
use super::tracer::Look;
use super::{RecordedRun, ShowError, TrialRange};
use crate::camera::CameraModel;
use crate::experiment::setup::{camera_model, move_settings, obstacles};
use crate::experiment::CameraKind;
use crate::robot::KinematicSim;
use crate::units::MM_PER_M;
use nalgebra::{Point3, Vector3};
use serde_json::json;
use std::path::{Path, PathBuf};

/// What `show` wrote.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct ShowReport {
    /// One folder per shown trial.
    pub folders: Vec<PathBuf>,
    /// Camera images written.
    pub camera_images: usize,
}

/// Re-simulates trials `range` of the run in `run_dir` and writes their pictures into
/// `run_dir/show/N/`.
pub fn show_trials(run_dir: &Path, range: TrialRange) -> Result<ShowReport, ShowError> {
    let run = RecordedRun::read(run_dir)?;
    run.check_trials(range.first, range.last)?;
    let scratch = show_folder(run_dir)?;
    let mut report = ShowReport::default();
    let pictures = CameraPictures::of(&run);
    replay(
        &run,
        range.last,
        |t| range.contains(t),
        false,
        &scratch,
        |trace| {
            let folder = scratch.join(trace.trial.to_string());
            create(&folder)?;
            report.camera_images += write_trial(&folder, &trace, &pictures, run_dir)?;
            report.folders.push(folder);
            Ok(())
        },
    )?;
    remove_scratch_patterns(&scratch);
    Ok(report)
}

/// How a run's camera images are drawn: the camera, its rays per image side, and the world
/// of each trial (the arm as it was, the run's floor and obstacles), placed at each look.
#[derive(Debug)]
pub struct CameraPictures<'a> {
    run: &'a RecordedRun,
    camera: CameraModel,
    resolution: usize,
}

impl<'a> CameraPictures<'a> {
    /// The pictures of `run`: its ray-cast camera's resolution, or one ray per pixel.
    pub fn of(run: &'a RecordedRun) -> CameraPictures<'a> {
        let camera = camera_model(&run.setup.config);
        let resolution = match run.setup.config.camera {
            CameraKind::Raycast => run.setup.config.raycast_resolution,
            CameraKind::Projection => camera.width.round() as usize,
        };
        CameraPictures {
            run,
            camera,
            resolution,
        }
    }

    /// The camera image at every look of `trace` with its caption, as PNG bytes.
    pub fn pngs(&self, trace: &TrialTrace) -> Result<Vec<Vec<u8>>, String> {
        let config = &self.run.setup.config;
        let scene = KinematicSim::new(trace.model.clone(), move_settings(config))
            .with_obstacles(obstacles(config));
        let camera = &self.camera;
        trace
            .looks
            .iter()
            .enumerate()
            .map(|(k, look)| {
                let caption = caption(trace.trial, k, look, camera);
                let world = scene.world_at(&look.joints);
                camera_image_png(look, camera, self.resolution, &world, &caption)
            })
            .collect()
    }
}

/// `run_dir/show`, created; a learner that keeps a pattern file keeps it here.
pub(crate) fn show_folder(run_dir: &Path) -> Result<PathBuf, ShowError> {
    let folder = run_dir.join("show");
    create(&folder)?;
    Ok(folder)
}

/// Drops the replay's own pattern file (the run's stays in the run folder).
pub(crate) fn remove_scratch_patterns(scratch: &Path) {
    let _ = std::fs::remove_file(scratch.join("pat_file"));
}

fn create(folder: &Path) -> Result<(), ShowError> {
    std::fs::create_dir_all(folder).map_err(|e| ShowError::Write {
        path: folder.to_path_buf(),
        reason: e.to_string(),
    })
}

/// Writes one trial's files; returns the camera images written.
fn write_trial(
    folder: &Path,
    trace: &TrialTrace,
    pictures: &CameraPictures,
    run_dir: &Path,
) -> Result<usize, ShowError> {
    let failed = |path: PathBuf| move |reason: String| ShowError::Write { path, reason };
    let images = pictures.pngs(trace).map_err(failed(folder.to_path_buf()))?;
    for (k, png) in images.iter().enumerate() {
        let path = folder.join(format!("camera_{k}.png"));
        std::fs::write(&path, png).map_err(|e| failed(path)(e.to_string()))?;
    }
    let path = folder.join("arm.png");
    write_arm_image(&path, trace, &arm_title(run_dir, trace)).map_err(failed(path))?;
    let path = folder.join("trial.json");
    let text = serde_json::to_string_pretty(&trial_json(trace, &pictures.camera))
        .map_err(|e| e.to_string());
    text.and_then(|t| std::fs::write(&path, t + "\n").map_err(|e| e.to_string()))
        .map_err(failed(path))?;
    Ok(images.len())
}

fn goal_of(look: &Look, camera: &CameraModel) -> Point3<f64> {
    camera.goal_point(&look.object)
}

fn camera_centre(look: &Look) -> Point3<f64> {
    look.camera_pose * Point3::origin()
}

fn caption(trial: usize, k: usize, look: &Look, camera: &CameraModel) -> Vec<String> {
    let pose = if k == 0 {
        format!("trial {trial}, start")
    } else {
        format!("trial {trial}, after step {k}")
    };
    let seen = match look.reading {
        Ok(c) => format!("c = ({:.2}, {:.2}, {:.2})  (cx, cy px; cz)", c.x, c.y, c.z),
        Err(why) => format!("not seen: {why}"),
    };
    let at = camera_centre(look).coords * 100.0;
    let distance = (camera_centre(look) - goal_of(look, camera)).norm() * MM_PER_M;
    vec![
        format!("{pose}: {seen}"),
        format!(
            "camera at ({:.1}, {:.1}, {:.1}) cm, {distance:.3} mm from the goal",
            at.x, at.y, at.z
        ),
    ]
}

fn arm_title(run_dir: &Path, trace: &TrialTrace) -> String {
    let distances: Vec<String> = trace
        .outcome
        .distances_mm
        .iter()
        .map(|d| format!("{d:.3}"))
        .collect();
    let end = match trace.outcome.failure {
        Some(failure) => format!(" — failed: {failure:?}"),
        None => String::new(),
    };
    format!(
        "{} trial {}: distance after each step (mm) {}{end}",
        run_dir.display(),
        trace.trial,
        distances.join(", ")
    )
}

fn cm(p: &Point3<f64>) -> [f64; 3] {
    let v = p.coords * 100.0;
    [v.x, v.y, v.z]
}

fn trial_json(trace: &TrialTrace, camera: &CameraModel) -> serde_json::Value {
    let poses: Vec<serde_json::Value> = trace
        .looks
        .iter()
        .enumerate()
        .map(|(k, look)| {
            let reading = look.reading.ok().map(|c: Vector3<f64>| [c.x, c.y, c.z]);
            json!({
                "pose": k,
                "sim_time_s": look.sim_time,
                "joints_deg": look.joints.iter().map(|q| q.to_degrees()).collect::<Vec<_>>(),
                "camera_cm": cm(&camera_centre(look)),
                "reading": reading,
                "not_seen": look.reading.err().map(|why| why.to_string()),
                "distance_mm": (camera_centre(look) - goal_of(look, camera)).norm() * MM_PER_M,
            })
        })
        .collect();
    let first = trace.looks.first();
    json!({
        "trial": trace.trial,
        "object_cm": first.map(|l| cm(&l.object)),
        "goal_cm": first.map(|l| cm(&goal_of(l, camera))),
        "distances_mm": trace.outcome.distances_mm,
        "failure": trace.outcome.failure.map(|f| format!("{f:?}")),
        "events": trace.events.iter().map(ToString::to_string).collect::<Vec<_>>(),
        "poses": poses,
    })
}
