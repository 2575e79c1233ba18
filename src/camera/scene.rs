//! What besides the target a camera's rays meet: the scene around it (the floor, obstacles,
//! the arm's own links), and the visibility rules both cameras share.
//!
//! The rule: a ray sees the target where it meets the sphere before anything else. The
//! `raycast` camera measures only the visible part of the blob — a target partly hidden
//! gives the shifted centroid and smaller area a real blob detector would report, a wholly
//! hidden one is not seen ([`NotSeen::Hidden`]). The `projection` camera, the study's
//! analytic image, tests one ray: it does not see the target when the ray from the camera
//! centre to the sphere's centre meets something before the sphere, and otherwise reports
//! the whole ellipse. Both first bound the view — the box around the camera centre and the
//! sphere — and take their scene-free path, bit for bit, when nothing of the scene enters
//! it.

use super::model::NotSeen;
use nalgebra::{Isometry3, Point3, Vector3};

/// Something a camera ray met.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SceneHit {
    /// Distance along the ray, in lengths of its direction vector.
    pub distance: f64,
    /// The grey level (0–255) a picture of the scene gives the point met.
    pub grey: u8,
}

/// The scene a camera looks into (world frame, m).
pub trait Scene {
    /// The first thing the ray from `origin` along `dir` meets within `max` lengths of
    /// `dir`, if any.
    fn first_hit(&self, origin: &Point3<f64>, dir: &Vector3<f64>, max: f64) -> Option<SceneHit>;

    /// False when nothing of the scene reaches into the box from `lower` to `upper`; true
    /// may be said of a box that nothing enters.
    fn may_reach_into(&self, lower: &Point3<f64>, upper: &Point3<f64>) -> bool;
}

/// A scene with nothing in it but the target.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct EmptyScene;

impl Scene for EmptyScene {
    fn first_hit(&self, _: &Point3<f64>, _: &Vector3<f64>, _: f64) -> Option<SceneHit> {
        None
    }

    fn may_reach_into(&self, _: &Point3<f64>, _: &Point3<f64>) -> bool {
        false
    }
}

/// True when something of `scene` may stand between the camera at `camera_pose` and the
/// sphere of `radius` centred at `object`: it reaches into their bounding box.
pub(super) fn view_may_be_blocked(
    scene: &dyn Scene,
    camera_pose: &Isometry3<f64>,
    object: &Point3<f64>,
    radius: f64,
) -> bool {
    let apex = Point3::from(camera_pose.translation.vector);
    let reach = Vector3::repeat(radius);
    let lower = apex.inf(&(object - reach));
    let upper = apex.sup(&(object + reach));
    scene.may_reach_into(&lower, &upper)
}

/// [`NotSeen::Hidden`] when the ray from the camera centre to the sphere's centre meets
/// something of `scene` before the sphere's near surface.
pub(super) fn centre_ray_check(
    scene: &dyn Scene,
    camera_pose: &Isometry3<f64>,
    object: &Point3<f64>,
    radius: f64,
) -> Result<(), NotSeen> {
    if !view_may_be_blocked(scene, camera_pose, object, radius) {
        return Ok(());
    }
    let apex = Point3::from(camera_pose.translation.vector);
    let towards = object - apex;
    let near_surface = 1.0 - radius / towards.norm();
    match scene.first_hit(&apex, &towards, near_surface) {
        Some(_) => Err(NotSeen::Hidden),
        None => Ok(()),
    }
}
