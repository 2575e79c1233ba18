//! The `projection` camera: the exact analytic perspective image of the sphere.
//!
//! A sphere of radius r whose centre lies at distance d from the camera, at angle θ off the
//! optical axis, is seen inside a cone of half-angle α (sin α = r/d); the image plane at
//! focal length f cuts that cone in an ellipse. With k = cos²θ − sin²α its centre lies
//! f·sinθ·cosθ / k from the image centre (towards the sphere's direction), its semi-axes
//! are f·sinα·cosα / k (radial) and f·sinα / √k, and its area is π times their product.
//! The reading is the ellipse's centre (what a blob centroid gives) and cz from its area.
//! In a scene it tests the centre ray only: the object is hidden when the ray from the
//! camera centre to the sphere's centre meets something first (see the `scene` module).

use super::model::{CameraModel, NotSeen};
use super::scene::{centre_ray_check, Scene};
use super::Camera;
use nalgebra::{Isometry3, Matrix3, Point3, Vector3};

/// The sphere's exact analytic image.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct ProjectionCamera {
    model: CameraModel,
}

/// The image ellipse of the sphere.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Ellipse {
    centre: (f64, f64),
    half_width: f64,
    half_height: f64,
    area: f64,
}

impl ProjectionCamera {
    /// A projection camera with these intrinsics.
    pub fn new(model: CameraModel) -> ProjectionCamera {
        ProjectionCamera { model }
    }

    /// The image of a sphere centred at `p` (camera frame), wherever it is in front.
    fn ellipse(&self, p: &Vector3<f64>) -> Result<Ellipse, NotSeen> {
        let m = &self.model;
        let distance = p.norm();
        if !(p.z > 0.0 && distance > m.object_radius) {
            return Err(NotSeen::TooClose);
        }
        let sin_a = m.object_radius / distance;
        let cos_a = (1.0 - sin_a * sin_a).sqrt();
        let radial = p.x.hypot(p.y);
        let (sin_t, cos_t) = (radial / distance, p.z / distance);
        let k = cos_t * cos_t - sin_a * sin_a;
        if k <= 0.0 {
            return Err(NotSeen::OutsideFrame);
        }
        let (dir_x, dir_y) = if radial > 0.0 {
            (p.x / radial, p.y / radial)
        } else {
            (1.0, 0.0)
        };
        let centre_distance = m.focal * sin_t * cos_t / k;
        let major = m.focal * sin_a * cos_a / k;
        let minor = m.focal * sin_a / k.sqrt();
        Ok(Ellipse {
            centre: (centre_distance * dir_x, centre_distance * dir_y),
            half_width: (major * major * dir_x * dir_x + minor * minor * dir_y * dir_y).sqrt(),
            half_height: (major * major * dir_y * dir_y + minor * minor * dir_x * dir_x).sqrt(),
            area: std::f64::consts::PI * major * minor,
        })
    }

    /// Where the sphere's centre is in the camera frame, given its reading: the inverse of
    /// [`read_local`](Self::read_local) by Newton steps from the pinhole estimate. `None`
    /// when the reading belongs to no visible sphere.
    pub fn locate(&self, c: &Vector3<f64>) -> Option<Vector3<f64>> {
        let m = &self.model;
        if !(c.iter().all(|v| v.is_finite()) && c.z > -100.0) {
            return None;
        }
        // On the axis √(A_ref/A) = tan α_ref / tan α, which gives the distance.
        let sin_ref = m.object_radius / m.standoff;
        let tan = sin_ref / (1.0 - sin_ref * sin_ref).sqrt() / (1.0 + c.z / 100.0);
        let depth = m.object_radius * (1.0 + tan * tan).sqrt() / tan;
        let mut p = Vector3::new(c.x * depth / m.focal, c.y * depth / m.focal, depth);
        let unbounded = |p: &Vector3<f64>| {
            self.ellipse(p)
                .ok()
                .map(|e| Vector3::new(e.centre.0, e.centre.1, m.cz_from_area(e.area)))
        };
        for _ in 0..30 {
            let residual = unbounded(&p)? - c;
            if residual.norm() < 1e-10 {
                return Some(p);
            }
            let step = 1e-7 * p.norm();
            let base = residual + c;
            let mut jacobian = Matrix3::zeros();
            for i in 0..3 {
                let mut shifted = p;
                shifted[i] += step;
                jacobian.set_column(i, &((unbounded(&shifted)? - base) / step));
            }
            p -= jacobian.lu().solve(&residual)?;
        }
        None
    }
}

impl Camera for ProjectionCamera {
    fn read_local(&self, p: &Vector3<f64>) -> Result<Vector3<f64>, NotSeen> {
        if p.z.is_nan() || p.z < self.model.min_depth {
            return Err(NotSeen::TooClose);
        }
        let ellipse = self.ellipse(p)?;
        let (u, v) = ellipse.centre;
        let inside = u.abs() + ellipse.half_width <= 0.5 * self.model.width
            && v.abs() + ellipse.half_height <= 0.5 * self.model.height;
        if !inside {
            return Err(NotSeen::OutsideFrame);
        }
        Ok(Vector3::new(u, v, self.model.cz_from_area(ellipse.area)))
    }

    fn model(&self) -> &CameraModel {
        &self.model
    }

    fn read_in(
        &self,
        camera_pose: &Isometry3<f64>,
        object: &Point3<f64>,
        scene: &dyn Scene,
    ) -> Result<Vector3<f64>, NotSeen> {
        let reading = self.read(camera_pose, object)?;
        centre_ray_check(scene, camera_pose, object, self.model.object_radius)?;
        Ok(reading)
    }
}
