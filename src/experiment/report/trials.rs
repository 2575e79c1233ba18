//! The trials the report replays: each re-simulated from the run folder as `show` does, and
//! every pose of it written down for the page — the body frames of the arm, the camera
//! frame, the joints, the reading, the distance to the goal and the camera image.

use super::arm_scene::ArmScene;
use super::json::{png_data_url, pose_json};
use crate::camera::CameraModel;
use crate::experiment::setup::camera_model;
use crate::experiment::show::{
    remove_scratch_patterns, replay, show_folder, CameraPictures, RecordedRun, ShowError,
    TrialTrace,
};
use crate::units::MM_PER_M;
use nalgebra::Point3;
use serde_json::{json, Value};

/// Replays the run up to the last of `trials` (sorted, in the run) and returns each of
/// them as the page reads it.
pub(super) fn trials_json(
    run: &RecordedRun,
    scene: &ArmScene,
    trials: &[usize],
) -> Result<Vec<Value>, ShowError> {
    let Some(&last) = trials.last() else {
        return Ok(Vec::new());
    };
    let scratch = show_folder(&run.folder)?;
    let pictures = CameraPictures::of(run);
    let camera = camera_model(&run.setup.config);
    let mut written = Vec::with_capacity(trials.len());
    let result = replay(
        run,
        last,
        |t| trials.binary_search(&t).is_ok(),
        false,
        &scratch,
        |trace| {
            let images = pictures.pngs(&trace).map_err(|reason| ShowError::Write {
                path: run.folder.join("report.html"),
                reason,
            })?;
            written.push(trial_json(&trace, scene, &camera, &images));
            Ok(())
        },
    );
    remove_scratch_patterns(&scratch);
    result.map(|()| written)
}

/// One trial: its target, goal, distances, failure and every pose.
fn trial_json(
    trace: &TrialTrace,
    scene: &ArmScene,
    camera: &CameraModel,
    images: &[Vec<u8>],
) -> Value {
    let object = trace.looks.first().map(|look| look.object);
    let goal = object.map(|o| camera.goal_point(&o));
    let poses: Vec<Value> = trace
        .looks
        .iter()
        .zip(images)
        .map(|(look, image)| {
            let bodies: Vec<[f32; 7]> = scene
                .body_frames(&trace.model, &look.joints)
                .iter()
                .map(pose_json)
                .collect();
            let centre = look.camera_pose * Point3::origin();
            let distance = goal.map(|g| (centre - g).norm() * MM_PER_M);
            let joints: Vec<f64> = look.joints.iter().map(|q| q.to_degrees()).collect();
            json!({
                "bodies": bodies,
                "camera": pose_json(&look.camera_pose),
                "joints_deg": joints,
                "reading": look.reading.ok().map(|c| [c.x, c.y, c.z]),
                "not_seen": look.reading.err().map(|why| why.to_string()),
                "distance_mm": distance,
                "sim_time_s": look.sim_time,
                "image": png_data_url(image),
            })
        })
        .collect();
    let point = |p: Option<Point3<f64>>| p.map(|p| [p.x, p.y, p.z]);
    json!({
        "trial": trace.trial,
        "object": point(object),
        "goal": point(goal),
        "distances_mm": trace.outcome.distances_mm,
        "failure": trace.outcome.failure.map(|f| format!("{f:?}")),
        "events": trace.events.iter().map(ToString::to_string).collect::<Vec<_>>(),
        "poses": poses,
    })
}
