//! The camera's intrinsics, the target object and the meaning of a reading.

use nalgebra::{Point3, Vector3};

/// Why the object is not seen.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, thiserror::Error)]
pub enum NotSeen {
    /// The object's centre is behind or less than the minimum depth in front of the camera.
    #[error("the object is behind the camera or too close to it")]
    TooClose,
    /// The object's image is cut by the frame's border or lies outside it.
    #[error("the object's image is not wholly inside the frame")]
    OutsideFrame,
    /// Something in the scene (an obstacle, the arm, the floor) hides the object.
    #[error("the object is hidden behind something in the scene")]
    Hidden,
}

/// A pinhole camera looking along its frame's +z axis at a sphere (SI units, pixels).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CameraModel {
    /// Image width (px); default 512.
    pub width: f64,
    /// Image height (px); default 512.
    pub height: f64,
    /// Focal length (px); default 256 (a 90° field of view).
    pub focal: f64,
    /// Radius of the target sphere (m); default 0.02.
    pub object_radius: f64,
    /// Height of the camera above the sphere's centre at the target (m); default 0.20, the
    /// study's (a run's is its config's `standoff`).
    pub standoff: f64,
    /// The sphere's centre must be at least this far in front of the camera (m); default 0.05.
    pub min_depth: f64,
}

impl Default for CameraModel {
    fn default() -> Self {
        CameraModel {
            width: 512.0,
            height: 512.0,
            focal: 256.0,
            object_radius: 0.02,
            standoff: 0.20,
            min_depth: 0.05,
        }
    }
}

impl CameraModel {
    /// The blob area (px²) of the sphere seen on axis from the standoff distance.
    pub fn reference_area(&self) -> f64 {
        let sin = self.object_radius / self.standoff;
        let tan = sin / (1.0 - sin * sin).sqrt();
        std::f64::consts::PI * self.focal * self.focal * tan * tan
    }

    /// cz for a blob of `area` px²: 100·(√(A_ref/A) − 1), zero at the reference size.
    pub fn cz_from_area(&self, area: f64) -> f64 {
        100.0 * ((self.reference_area() / area).sqrt() - 1.0)
    }

    /// The blob area (px²) that gives `cz`.
    pub fn area_from_cz(&self, cz: f64) -> f64 {
        self.reference_area() / (1.0 + cz / 100.0).powi(2)
    }

    /// False when a camera at `centre` looking straight down cannot see the object at
    /// `object`, however it is turned about its optical axis (world, m): the object is too
    /// close below it, or its centre's image falls outside the circle through the frame's
    /// corners (a visible sphere's image holds its centre's, and lies inside the frame).
    /// A few pixels of slack allow for an optical axis a little off vertical; true does
    /// not mean seen.
    pub fn may_see_from_above(&self, centre: &Point3<f64>, object: &Point3<f64>) -> bool {
        const SLACK_PX: f64 = 16.0;
        const SLACK_M: f64 = 1e-6;
        let depth = centre.z - object.z;
        let off_axis = (centre.x - object.x).hypot(centre.y - object.y);
        let corner = 0.5 * self.width.hypot(self.height) + SLACK_PX;
        depth >= self.min_depth - SLACK_M && self.focal * off_axis <= corner * depth
    }

    /// Where the camera centre must be to be at the target: straight above the object's
    /// centre by the standoff (world, m).
    pub fn goal_point(&self, object: &Point3<f64>) -> Point3<f64> {
        object + Vector3::z() * self.standoff
    }

    /// The object's centre for a camera centre at the target `goal`: straight below it by
    /// the standoff (world, m); [`goal_point`](Self::goal_point) undone.
    pub fn object_at_goal(&self, goal: &Point3<f64>) -> Point3<f64> {
        goal - Vector3::z() * self.standoff
    }

    /// How far (m) the object's bottom hangs below the camera centre at the target: the
    /// standoff and the object's radius.
    pub fn object_bottom_below(&self) -> f64 {
        self.standoff + self.object_radius
    }
}
