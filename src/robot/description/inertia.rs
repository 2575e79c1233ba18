//! A link's mass properties, and how the mass properties of rigidly joined links add up
//! (the parallel-axis theorem).

use nalgebra::{Isometry3, Matrix3, Point3};

/// Mass, centre of mass and inertia tensor of a body, in one frame's coordinates.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Inertial {
    /// Mass (kg); 0 for a massless (dummy) link.
    pub mass: f64,
    /// Centre of mass in the frame (m).
    pub com: Point3<f64>,
    /// Inertia tensor about the centre of mass, along the frame's axes (kg·m²): symmetric,
    /// off-diagonal terms kept.
    pub inertia: Matrix3<f64>,
}

impl Inertial {
    /// A body with no mass.
    pub const MASSLESS: Inertial = Inertial {
        mass: 0.0,
        com: Point3::new(0.0, 0.0, 0.0),
        inertia: Matrix3::new(0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0),
    };

    /// The same body seen from a frame in which this body's frame has pose `pose`.
    pub fn transformed(&self, pose: &Isometry3<f64>) -> Inertial {
        let rotation = pose.rotation.to_rotation_matrix();
        let r = rotation.matrix();
        Inertial {
            mass: self.mass,
            com: pose * self.com,
            inertia: r * self.inertia * r.transpose(),
        }
    }

    /// Two bodies in the same frame joined rigidly into one.
    pub fn combined(&self, other: &Inertial) -> Inertial {
        if other.mass == 0.0 {
            return *self;
        }
        if self.mass == 0.0 {
            return *other;
        }
        let mass = self.mass + other.mass;
        let com =
            Point3::from((self.com.coords * self.mass + other.com.coords * other.mass) / mass);
        Inertial {
            mass,
            com,
            inertia: self.inertia_about(&com) + other.inertia_about(&com),
        }
    }

    /// The inertia tensor about `point` (parallel-axis theorem), along the frame's axes.
    pub fn inertia_about(&self, point: &Point3<f64>) -> Matrix3<f64> {
        let d = self.com - point;
        self.inertia + (Matrix3::identity() * d.norm_squared() - d * d.transpose()) * self.mass
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::{Translation3, UnitQuaternion, Vector3};

    fn rod(mass: f64, com: Point3<f64>) -> Inertial {
        Inertial {
            mass,
            com,
            inertia: Matrix3::from_diagonal(&Vector3::new(0.01, 0.02, 0.03)),
        }
    }

    #[test]
    fn two_point_masses_have_the_dumbbell_inertia() {
        let point = |x: f64| Inertial {
            mass: 2.0,
            com: Point3::new(x, 0.0, 0.0),
            inertia: Matrix3::zeros(),
        };
        let both = point(-0.5).combined(&point(0.5));
        assert_eq!(both.mass, 4.0);
        assert!(both.com.coords.norm() < 1e-15);
        // 2 kg at 0.5 m on each side: 1 kg·m² about y and z, nothing about x.
        let expected = Matrix3::from_diagonal(&Vector3::new(0.0, 1.0, 1.0));
        assert!((both.inertia - expected).norm() < 1e-12, "{}", both.inertia);
    }

    #[test]
    fn an_offset_body_gains_off_diagonal_terms() {
        let a = rod(1.0, Point3::new(0.0, 0.0, 0.0));
        let b = rod(1.0, Point3::new(1.0, 1.0, 0.0));
        let both = a.combined(&b);
        // Each body sits at (±0.5, ±0.5, 0) from the joint centre: I_xy = −Σ m x y = −0.5.
        assert!(
            (both.inertia[(0, 1)] + 0.5).abs() < 1e-12,
            "{}",
            both.inertia
        );
        assert_eq!(both.inertia, both.inertia.transpose());
    }

    #[test]
    fn a_massless_body_changes_nothing() {
        let a = rod(3.0, Point3::new(0.1, 0.2, 0.3));
        assert_eq!(a.combined(&Inertial::MASSLESS), a);
        assert_eq!(
            Inertial::MASSLESS.combined(&Inertial::MASSLESS),
            Inertial::MASSLESS
        );
    }

    #[test]
    fn a_turn_rotates_the_tensor_and_moves_the_com() {
        let a = rod(1.0, Point3::new(1.0, 0.0, 0.0));
        let quarter = Isometry3::from_parts(
            Translation3::new(0.0, 0.0, 1.0),
            UnitQuaternion::from_axis_angle(&Vector3::z_axis(), std::f64::consts::FRAC_PI_2),
        );
        let b = a.transformed(&quarter);
        assert!((b.com - Point3::new(0.0, 1.0, 1.0)).norm() < 1e-12);
        let expected = Matrix3::from_diagonal(&Vector3::new(0.02, 0.01, 0.03));
        assert!((b.inertia - expected).norm() < 1e-12, "{}", b.inertia);
    }
}
