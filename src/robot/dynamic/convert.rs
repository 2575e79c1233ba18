//! Conversions between the crate's nalgebra types and Rapier's glam types.

use nalgebra::{Isometry3, Quaternion, Translation3, UnitQuaternion, Vector3};
use rapier3d_f64::math::{Pose, Rotation, Vector};

/// A nalgebra isometry as a Rapier pose.
pub(in crate::robot) fn to_pose(iso: &Isometry3<f64>) -> Pose {
    let q = iso.rotation.quaternion();
    Pose::from_parts(
        to_vector(&iso.translation.vector),
        Rotation::from_xyzw(q.i, q.j, q.k, q.w),
    )
}

/// A Rapier pose as a nalgebra isometry.
pub(in crate::robot) fn to_isometry(pose: &Pose) -> Isometry3<f64> {
    let r = pose.rotation;
    Isometry3::from_parts(
        Translation3::from(from_vector(pose.translation)),
        UnitQuaternion::new_normalize(Quaternion::new(r.w, r.x, r.y, r.z)),
    )
}

/// A nalgebra vector as a glam vector.
pub(in crate::robot) fn to_vector(v: &Vector3<f64>) -> Vector {
    Vector::new(v.x, v.y, v.z)
}

/// A glam vector as a nalgebra vector.
pub(super) fn from_vector(v: Vector) -> Vector3<f64> {
    Vector3::new(v.x, v.y, v.z)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn poses_round_trip() {
        let iso = Isometry3::new(Vector3::new(0.1, -0.2, 0.3), Vector3::new(0.4, 0.5, -0.6));
        let back = to_isometry(&to_pose(&iso));
        assert!((back.to_homogeneous() - iso.to_homogeneous()).norm() < 1e-15);
        let p = Vector3::new(1.0, 2.0, 3.0);
        let moved = to_pose(&iso).transform_point(to_vector(&p));
        assert!((from_vector(moved) - (iso * nalgebra::Point3::from(p)).coords).norm() < 1e-15);
    }
}
