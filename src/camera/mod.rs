//! The camera in the end-effector: a pinhole looking down at a sphere, and the reading
//! c = (cx, cy, cz) the learners see.

mod model;
mod projection;
mod raycast;

pub use model::{CameraModel, NotSeen};
pub use projection::ProjectionCamera;
pub use raycast::RaycastCamera;

use nalgebra::{Isometry3, Point3, Vector3};

/// Something that produces the camera reading for a camera pose and an object position.
pub trait Camera: std::fmt::Debug {
    /// The reading c = (cx, cy in pixels, cz the area measure) of the object whose centre
    /// is at `object` (world, m), seen from `camera_pose`, or why it is not seen.
    fn read(
        &self,
        camera_pose: &Isometry3<f64>,
        object: &Point3<f64>,
    ) -> Result<Vector3<f64>, NotSeen>;

    /// The camera's intrinsics and object.
    fn model(&self) -> &CameraModel;
}
