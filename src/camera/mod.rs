//! The camera in the end-effector: a pinhole looking down at a sphere, and the reading
//! c = (cx, cy, cz) the learners see, and the scene around the target that can hide it.

mod model;
mod occlusion;
mod projection;
mod raycast;
mod scene;

pub use model::{CameraModel, NotSeen};
pub use projection::ProjectionCamera;
pub use raycast::{PixelCoverage, RaycastCamera};
pub use scene::{EmptyScene, Scene, SceneHit};

use nalgebra::{Isometry3, Point3, Vector3};

/// Something that produces the camera reading for a camera pose and an object position.
pub trait Camera: std::fmt::Debug {
    /// The reading c = (cx, cy in pixels, cz the area measure) of a sphere whose centre is
    /// at `p` in the camera frame (z along the optical axis), or why it is not seen.
    fn read_local(&self, p: &Vector3<f64>) -> Result<Vector3<f64>, NotSeen>;

    /// The camera's intrinsics and object.
    fn model(&self) -> &CameraModel;

    /// The reading of the object whose centre is at `object` (world, m), seen from
    /// `camera_pose`, or why it is not seen.
    fn read(
        &self,
        camera_pose: &Isometry3<f64>,
        object: &Point3<f64>,
    ) -> Result<Vector3<f64>, NotSeen> {
        self.read_local(&camera_pose.inverse_transform_point(object).coords)
    }

    /// The reading of the object at `object` seen from `camera_pose` with `scene` around
    /// it, or why it is not seen: what the scene hides is not seen, by each camera's rule
    /// (see the `scene` module).
    fn read_in(
        &self,
        camera_pose: &Isometry3<f64>,
        object: &Point3<f64>,
        scene: &dyn Scene,
    ) -> Result<Vector3<f64>, NotSeen>;
}
