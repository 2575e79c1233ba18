//! A two-joint wrist near its singularity, where the two joints tilt the optical axis
//! nearly the same way (the xArm7's joints 5 and 6 with joint 6 near 0: joint 5 turns
//! about the optical axis). The full Newton step there turns the first joint by the tilt
//! across the second's divided by the small singular value: an arm a hair off planar (a
//! URDF's rounded `rpy`, 1.5708 for π/2) passing the singularity would whirl that joint
//! round within a few control ticks, or hop between its two solutions. Near it the wrist
//! solves only the tilt it turns well and leaves the tilt across it, when that is within
//! [`LOOSE_RAD`].

use super::TOLERANCE_RAD;
use nalgebra::{Matrix2, Matrix3, Vector2, Vector3};

/// The smallest singular value of a two-joint wrist's tilting (rad of tilt per rad) below
/// which it is near its singularity (the xArm7's joint 6 within 2.9° of 0).
const SINGULAR: f64 = 0.05;
/// The tilt (rad) across its well-turned direction a wrist near its singularity may leave
/// (0.006°: the xArm7's URDF rounds π/2 by 3.7·10⁻⁶ rad at six joints).
const LOOSE_RAD: f64 = 1e-4;

/// What a two-joint wrist near its singularity does next.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) enum NearSingular {
    /// It looks down as well as it can: done.
    Done,
    /// It turns its two joints by this much (rad).
    Step(Vector2<f64>),
}

/// For a two-joint wrist whose joints tilt the optical axis `optical` by the first two
/// columns of `jacobian`, left `error` (rad, a turn across the axis) from looking down:
/// `None` away from its singularity, or where the tilt across its well-turned direction
/// exceeds [`LOOSE_RAD`] (a full Newton step then); else the step along that direction
/// alone, or done when what is left along it is within the wrist's tolerance.
pub(super) fn near_singular(
    jacobian: &Matrix3<f64>,
    optical: &Vector3<f64>,
    error: &Vector3<f64>,
) -> Option<NearSingular> {
    let columns = jacobian.fixed_columns::<2>(0);
    let gram: Matrix2<f64> = columns.transpose() * columns;
    let eigen = gram.symmetric_eigen();
    let (weak, strong) = match eigen.eigenvalues[0] < eigen.eigenvalues[1] {
        true => (0, 1),
        false => (1, 0),
    };
    let sigma = eigen.eigenvalues[strong].sqrt();
    if eigen.eigenvalues[weak] >= SINGULAR * SINGULAR || sigma < SINGULAR {
        return None;
    }
    let turn = eigen.eigenvectors.column(strong).into_owned();
    let along = columns * turn / sigma;
    if optical.cross(&along).dot(error).abs() >= LOOSE_RAD {
        return None;
    }
    let left = along.dot(error);
    if left.abs() < TOLERANCE_RAD {
        return Some(NearSingular::Done);
    }
    Some(NearSingular::Step(turn * (left / sigma)))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The tilting of two joints across an optical axis along z: the second turns about
    /// x, the first about an axis `lean` (rad) off the optical axis towards y.
    fn wrist(lean: f64) -> Matrix3<f64> {
        Matrix3::new(0.0, 1.0, 0.0, lean.sin(), 0.0, 0.0, 0.0, 0.0, 0.0)
    }

    #[test]
    fn away_from_the_singularity_the_full_step_is_taken() {
        let error = Vector3::new(0.01, 1e-6, 0.0);
        assert_eq!(near_singular(&wrist(0.3), &Vector3::z(), &error), None);
    }

    #[test]
    fn near_it_only_the_well_turned_tilt_is_solved() {
        // 1e-6 rad across at a lean of 0.001 rad: the full step would turn the first
        // joint by 1e-3 rad; this one turns the second alone.
        let error = Vector3::new(0.01, 1e-6, 0.0);
        let Some(NearSingular::Step(step)) = near_singular(&wrist(1e-3), &Vector3::z(), &error)
        else {
            panic!("no step near the singularity");
        };
        assert!(
            step[0].abs() < 1e-15 && (step[1] - 0.01).abs() < 1e-15,
            "{step}"
        );
        let left = Vector3::new(1e-13, 1e-6, 0.0);
        let done = near_singular(&wrist(1e-3), &Vector3::z(), &left);
        assert_eq!(done, Some(NearSingular::Done));
    }

    #[test]
    fn a_large_tilt_across_takes_the_full_step() {
        let error = Vector3::new(0.01, 2.0 * LOOSE_RAD, 0.0);
        assert_eq!(near_singular(&wrist(1e-3), &Vector3::z(), &error), None);
    }
}
