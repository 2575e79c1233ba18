//! A body's mass, centre of mass and inertia tensor in its link frame: summed over the
//! URDF links merged into one body, stretched with its link, and handed to Rapier by its
//! principal moments and axes (diagonalised here, so a tensor with a repeated moment keeps
//! its axes).

use super::convert::to_vector;
use crate::robot::LinkBody;
use nalgebra::{Isometry3, Matrix3, Rotation3, SymmetricEigen, Unit, UnitQuaternion, Vector3};
use rapier3d_f64::math::Rotation;
use rapier3d_f64::prelude::MassProperties;

/// Mass properties of one rigid body, in its link frame (SI).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct Inertial {
    /// Mass (kg).
    pub(super) mass: f64,
    /// Centre of mass (m).
    pub(super) com: Vector3<f64>,
    /// Inertia tensor about the centre of mass, in link-frame axes (kg·m²).
    pub(super) tensor: Matrix3<f64>,
}

impl Inertial {
    /// The URDF inertial of `link`, in a frame where the link's own frame sits at `at`.
    pub(super) fn of_link(link: &LinkBody, at: &Isometry3<f64>) -> Inertial {
        let frame = at * link.inertial_origin;
        let rotation = frame.rotation.to_rotation_matrix();
        Inertial {
            mass: link.mass,
            com: frame.translation.vector,
            tensor: rotation * link.inertia * rotation.transpose(),
        }
    }

    /// The mass (kg) a body without mass (its URDF links all massless) is given, so that
    /// the multibody's mass matrix stays invertible: a gram.
    pub(super) const MIN_MASS: f64 = 1e-3;
    /// The inertia (kg·m²) it is given about each axis: a gram spread over a 2 cm ball.
    const MIN_MOMENT: f64 = 0.4 * Self::MIN_MASS * 0.02 * 0.02;

    /// This body, or for a body without mass (or with a mass the parts' sum made not a
    /// number) a small ball of [`MIN_MASS`](Self::MIN_MASS) at the frame's origin: Rapier
    /// cannot move a massless link of a multibody.
    pub(super) fn at_least_minimal(self) -> Inertial {
        if self.mass > 0.0 {
            return self;
        }
        Inertial {
            mass: Self::MIN_MASS,
            com: Vector3::zeros(),
            tensor: Matrix3::identity() * Self::MIN_MOMENT,
        }
    }

    /// The parts as one body: masses add, the centre of mass is their weighted mean, the
    /// tensors move to it by the parallel-axis rule.
    pub(super) fn sum(parts: &[Inertial]) -> Inertial {
        let mass: f64 = parts.iter().map(|p| p.mass).sum();
        let com = parts.iter().map(|p| p.com * p.mass).sum::<Vector3<f64>>() / mass;
        let tensor = parts
            .iter()
            .map(|p| {
                let r = p.com - com;
                p.tensor + p.mass * (Matrix3::identity() * r.norm_squared() - r * r.transpose())
            })
            .sum();
        Inertial { mass, com, tensor }
    }

    /// The body after its link grew from `length` to `new_length` (m) along `direction`
    /// (from the link's near joint, its frame origin, to its far joint), as a uniform rod
    /// does: the material is stretched along the link with its density per unit length
    /// kept, so the mass scales by s = `new_length`/`length`, every point's coordinate
    /// along the link by s (the centre of mass with it), and the second moments of mass by
    /// s·A·S·A with A the stretch (s along the link, 1 across it).
    pub(super) fn stretched(
        &self,
        direction: &Unit<Vector3<f64>>,
        length: f64,
        new_length: f64,
    ) -> Inertial {
        let s = new_length / length;
        let d = direction.into_inner();
        let stretch = Matrix3::identity() + (s - 1.0) * d * d.transpose();
        // Second moments ∫ r rᵀ dm about the centre of mass, from the inertia tensor.
        let moments = Matrix3::identity() * (0.5 * self.tensor.trace()) - self.tensor;
        let moments = s * stretch * moments * stretch;
        Inertial {
            mass: s * self.mass,
            com: stretch * self.com,
            tensor: Matrix3::identity() * moments.trace() - moments,
        }
    }

    /// Principal moments (kg·m²) and the rotation whose columns are their axes, a proper
    /// rotation (right-handed).
    pub(super) fn principal(&self) -> (Vector3<f64>, UnitQuaternion<f64>) {
        let eigen = SymmetricEigen::new(self.tensor);
        let mut axes = eigen.eigenvectors;
        if axes.determinant() < 0.0 {
            axes.set_column(2, &-axes.column(2));
        }
        let rotation = Rotation3::from_matrix_unchecked(axes);
        (
            eigen.eigenvalues,
            UnitQuaternion::from_rotation_matrix(&rotation),
        )
    }

    /// As Rapier mass properties, built from the principal frame found here; a principal
    /// moment below [`MIN_MOMENT`](Self::MIN_MOMENT) (a point mass, a thin rod about its
    /// axis) is raised to it, so that no joint turns a body of no inertia.
    pub(super) fn mass_properties(&self) -> MassProperties {
        let (moments, axes) = self.principal();
        let moments = moments.map(|m| m.max(Self::MIN_MOMENT));
        let q = axes.quaternion();
        MassProperties::with_principal_inertia_frame(
            to_vector(&self.com),
            self.mass,
            to_vector(&moments),
            Rotation::from_xyzw(q.i, q.j, q.k, q.w),
        )
    }
}

#[cfg(test)]
mod tests {
    use super::super::builder::Arm;
    use super::*;
    use crate::robot::{ArmModel, DynamicSettings};
    use nalgebra::Matrix3;

    /// The tensor Rapier simulates for body `k`, rebuilt from its principal moments and
    /// axes, with those moments and axes.
    fn simulated(arm: &Arm, k: usize) -> (Matrix3<f64>, Vector3<f64>, Matrix3<f64>) {
        let props = arm.world.bodies[arm.bodies[k]]
            .mass_properties()
            .local_mprops;
        let m = props.principal_inertia();
        let q = props.principal_inertia_local_frame;
        let axes = UnitQuaternion::from_quaternion(nalgebra::Quaternion::new(q.w, q.x, q.y, q.z))
            .to_rotation_matrix()
            .into_inner();
        let moments = Vector3::new(m.x, m.y, m.z);
        (
            axes * Matrix3::from_diagonal(&moments) * axes.transpose(),
            moments,
            axes,
        )
    }

    #[test]
    fn every_link_has_the_principal_moments_and_axes_of_its_urdf_tensor() {
        let model = ArmModel::oscar6();
        let mut arm = Arm::build(&model, &DynamicSettings::default());
        arm.world.step(); // Rapier takes the bodies' mass properties in on its first step.
        let links = model.links();
        // The camera (0.3 kg, 0.00018 kg·m² about every axis, 0.07 m out along the flange)
        // moves to the merged centre of mass by the parallel-axis rule, as does link 6.
        let com: f64 = (0.5 * 0.03 + 0.3 * 0.07) / 0.8;
        let shift = 0.5 * (0.03 - com).powi(2) + 0.3 * (0.07 - com).powi(2);
        let flange = Matrix3::from_diagonal(&Vector3::new(
            0.0004 + 0.00018,
            0.00035 + 0.00018 + shift,
            0.00035 + 0.00018 + shift,
        ));
        for (k, link) in links.iter().enumerate().take(7).skip(1) {
            let urdf = if k == 6 { flange } else { link.inertia };
            let (tensor, moments, axes) = simulated(&arm, k);
            // Rapier keeps the inverse moments and a quaternion: equal to rounding.
            let tol = 1e-12 * urdf.amax();
            assert!(
                (tensor - urdf).amax() < tol,
                "link {k}: simulated {tensor} vs URDF {urdf}"
            );
            for i in 0..3 {
                let axis = axes.column(i);
                assert!(
                    (urdf * axis - axis * moments[i]).amax() < tol,
                    "link {k}: {} is not a principal axis with moment {}",
                    axis.transpose(),
                    moments[i]
                );
            }
        }
        // Link 6's tensor has a repeated moment: the distinct one must lie along the flange.
        let (_, moments, axes) = simulated(&arm, 6);
        let along = (0..3)
            .find(|&i| (moments[i] - flange[(0, 0)]).abs() < 1e-12)
            .expect("the flange moment is among the principal moments");
        assert!((axes.column(along).x.abs() - 1.0).abs() < 1e-12, "{axes}");
    }

    #[test]
    fn a_uniform_rod_stretched_to_twice_its_length() {
        // A thin rod of 2 kg and 1 m along x from the origin: I = m L²/12 across it.
        let rod = Inertial {
            mass: 2.0,
            com: Vector3::new(0.5, 0.0, 0.0),
            tensor: Matrix3::from_diagonal(&Vector3::new(0.0, 2.0 / 12.0, 2.0 / 12.0)),
        };
        let long = rod.stretched(&Vector3::x_axis(), 1.0, 2.0);
        assert!((long.mass - 4.0).abs() < 1e-15);
        assert!((long.com - Vector3::new(1.0, 0.0, 0.0)).norm() < 1e-15);
        let expected = Matrix3::from_diagonal(&Vector3::new(0.0, 16.0 / 12.0, 16.0 / 12.0));
        assert!((long.tensor - expected).amax() < 1e-14, "{}", long.tensor);
        // A solid cylinder's axial moment m r²/2 scales with its mass alone.
        let cylinder = Inertial {
            tensor: Matrix3::from_diagonal(&Vector3::new(0.01, 0.2, 0.2)),
            ..rod
        };
        let long = cylinder.stretched(&Vector3::x_axis(), 1.0, 1.5);
        assert!((long.tensor[(0, 0)] - 0.015).abs() < 1e-15);
        // Across: (m r²/4)·1.5 + (m L²/12)·1.5³ with m r²/4 = 0.005, m L²/12 = 0.195.
        let across = 0.005 * 1.5 + 0.195 * 1.5f64.powi(3);
        assert!((long.tensor[(1, 1)] - across).abs() < 1e-14);
    }
}
