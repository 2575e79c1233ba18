//! The arm's equations of motion in joint space, M(q)·q̈ + b(q, q̇) = τ: the mass matrix
//! from each body's Jacobian (its centre of mass's and its spin's), the bias (gravity,
//! Coriolis and centrifugal torques, and the joints' damping) from the recursive
//! Newton–Euler pass, both from the model's kinematics and the masses as simulated. The
//! dynamic simulator integrates them itself (integrator.rs).

use super::builder::Arm;
use super::placement::Placement;
use crate::robot::{ArmModel, Joints, MAX_JOINTS};
use nalgebra::{SMatrix, Vector3};

/// A joint-space matrix; only its first rows and columns, one per joint, are used.
pub(super) type Square = SMatrix<f64, MAX_JOINTS, MAX_JOINTS>;

/// The arm's equations of motion at one state (angles and speeds).
#[derive(Debug, Clone)]
pub(super) struct JointSpace {
    /// L, lower triangular, with L·Lᵀ = M(q).
    factor: Square,
    /// b(q, q̇): the torques the joints take at zero acceleration (N·m).
    bias: Joints,
}

impl JointSpace {
    /// The joint accelerations (rad/s²) under joint torques `tau` (N·m): M⁻¹·(τ − b).
    pub(super) fn accelerations(&self, tau: &Joints) -> Joints {
        self.solve(*tau - self.bias)
    }

    /// A bound (1/s) on the fastest relaxation the joints' damping D gives the arm: the
    /// largest eigenvalue of M⁻¹·D is at most Σᵢ dᵢ·(M⁻¹)ᵢᵢ.
    pub(super) fn damping_rate(&self, model: &ArmModel) -> f64 {
        let n = self.bias.len();
        let unit = |i: usize| Joints::from_fn(n, |j| if i == j { 1.0 } else { 0.0 });
        model.joints()[..n]
            .iter()
            .enumerate()
            .filter(|(_, joint)| joint.damping > 0.0)
            .map(|(i, joint)| joint.damping * self.solve(unit(i))[i])
            .sum()
    }

    /// How many joints.
    pub(super) fn dof(&self) -> usize {
        self.bias.len()
    }

    /// M⁻¹·`x`, from the factor.
    pub(super) fn solve(&self, mut x: Joints) -> Joints {
        let n = x.len();
        let l = &self.factor;
        for i in 0..n {
            let sum: f64 = (0..i).map(|j| l[(i, j)] * x[j]).sum();
            x[i] = (x[i] - sum) / l[(i, i)];
        }
        for i in (0..n).rev() {
            let sum: f64 = (i + 1..n).map(|j| l[(j, i)] * x[j]).sum();
            x[i] = (x[i] - sum) / l[(i, i)];
        }
        x
    }

    /// The torques M(q)·`a` (N·m) that give the arm accelerations `a` (rad/s²) beyond the
    /// bias.
    pub(super) fn inertial_torques(&self, a: &Joints) -> Joints {
        let n = a.len();
        let l = &self.factor;
        let lt_a = Joints::from_fn(n, |i| (i..n).map(|j| l[(j, i)] * a[j]).sum());
        Joints::from_fn(n, |i| (0..=i).map(|j| l[(i, j)] * lt_a[j]).sum())
    }
}

impl Arm {
    /// The equations of motion of the arm of `model` at angles `q` (rad) and speeds `v`
    /// (rad/s); none when the mass matrix is not positive definite (a mass property not
    /// finite).
    pub(super) fn joint_space(
        &self,
        model: &ArmModel,
        q: &Joints,
        v: &Joints,
    ) -> Option<JointSpace> {
        let placed = self.placement(model, q);
        let bias = placed.driving_torques(model, v, &Joints::zeros(self.dof));
        Some(JointSpace {
            factor: cholesky(mass_matrix(&placed), self.dof)?,
            bias,
        })
    }
}

/// M of the bodies `placed`: Σₖ mₖ·Jᵥₖᵀ·Jᵥₖ + J_ωₖᵀ·Iₖ·J_ωₖ, where column j ≤ k of body
/// k's Jacobians is aⱼ × (cₖ − oⱼ) (its centre of mass's speed) and aⱼ (its spin); the
/// lower triangle only.
fn mass_matrix(placed: &Placement) -> Square {
    let mut m = Square::zeros();
    let mut linear = [Vector3::zeros(); MAX_JOINTS];
    let mut spun = [Vector3::zeros(); MAX_JOINTS];
    for k in 0..placed.dof {
        let (com, tensor, mass) = (placed.coms[k], &placed.tensors[k], placed.masses[k]);
        for j in 0..=k {
            linear[j] = placed.axes[j].cross(&(com - placed.origins[j]));
            spun[j] = tensor * placed.axes[j];
        }
        for i in 0..=k {
            for j in 0..=i {
                m[(i, j)] += mass * linear[i].dot(&linear[j]) + placed.axes[i].dot(&spun[j]);
            }
        }
    }
    m
}

/// The Cholesky factor of the first `n` rows and columns of `m` (its lower triangle read),
/// in place; none when they are not positive definite.
fn cholesky(mut m: Square, n: usize) -> Option<Square> {
    for j in 0..n {
        let diagonal = m[(j, j)] - (0..j).map(|k| m[(j, k)] * m[(j, k)]).sum::<f64>();
        if diagonal.is_nan() || diagonal <= 0.0 {
            return None;
        }
        let root = diagonal.sqrt();
        m[(j, j)] = root;
        for i in j + 1..n {
            let sum: f64 = (0..j).map(|k| m[(i, k)] * m[(j, k)]).sum();
            m[(i, j)] = (m[(i, j)] - sum) / root;
        }
    }
    Some(m)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::robot::DynamicSettings;

    /// The forward dynamics inverts the Newton–Euler pass: the accelerations under the
    /// torques that pass gives for them are those accelerations; and M·a is the torque
    /// of a at rest less the weight's.
    #[test]
    fn forward_dynamics_inverts_the_inverse() {
        let model = ArmModel::oscar6();
        let arm = Arm::build(&model, &DynamicSettings::default());
        let q = Joints::from_slice(&[0.3, 0.6, 1.2, 0.4, 0.5, 0.2]);
        let v = Joints::from_slice(&[0.5, -1.0, 2.0, 0.3, -0.7, 1.1]);
        let a = Joints::from_slice(&[1.0, 2.0, -3.0, 4.0, -0.5, 0.25]);
        let tau = arm.joint_torques(&model, &q, &v, &a);
        let found = arm.joint_space(&model, &q, &v).unwrap().accelerations(&tau);
        assert!((found - a).amax() < 1e-9, "{found:?} against {a:?}");
        let still = Joints::zeros(6);
        let space = arm.joint_space(&model, &q, &still).unwrap();
        let at_rest = arm.joint_torques(&model, &q, &still, &a);
        let weight = arm.joint_torques(&model, &q, &still, &still);
        assert!((space.inertial_torques(&a) - (at_rest - weight)).amax() < 1e-9);
    }

    #[test]
    fn a_matrix_that_is_not_positive_definite_has_no_factor() {
        let mut m = Square::identity();
        m[(1, 1)] = -1.0;
        assert!(cholesky(m, 2).is_none());
        m[(1, 1)] = f64::NAN;
        assert!(cholesky(m, 2).is_none());
        assert!(cholesky(m, 1).is_some());
    }
}
