//! The simulator's world as the camera's scene: what a ray meets and the grey level a
//! picture gives it — the floor in 10 cm tiles of two dark greys, obstacles light grey, the
//! arm's links mid grey (all darker than the white target, and the floor darker than the
//! empty background of `eyehand show`'s images).

use crate::camera::{Scene, SceneHit};
use crate::robot::{RayHit, Surface, WorldView};
use nalgebra::{Point3, Vector3};

/// Side of a floor tile (m).
const TILE: f64 = 0.1;
/// Grey levels of the floor's two kinds of tile.
pub const FLOOR_GREYS: [u8; 2] = [34, 22];
/// Grey level of an obstacle.
pub const OBSTACLE_GREY: u8 = 150;
/// Grey level of the arm's links and base.
pub const ARM_GREY: u8 = 100;

impl Scene for WorldView<'_> {
    fn first_hit(&self, origin: &Point3<f64>, dir: &Vector3<f64>, max: f64) -> Option<SceneHit> {
        self.cast(origin, dir, max).map(|hit| SceneHit {
            distance: hit.distance,
            grey: grey_of(&hit),
        })
    }

    fn may_reach_into(&self, lower: &Point3<f64>, upper: &Point3<f64>) -> bool {
        self.may_enter(lower, upper)
    }
}

/// The grey level of what a ray met.
fn grey_of(hit: &RayHit) -> u8 {
    match hit.surface {
        Surface::Floor => {
            let tile = (hit.point.x / TILE).floor() + (hit.point.y / TILE).floor();
            FLOOR_GREYS[(tile.rem_euclid(2.0) >= 1.0) as usize]
        }
        Surface::Obstacle(_) => OBSTACLE_GREY,
        Surface::Body(_) => ARM_GREY,
    }
}
