//! Learning patterns from pairs of poses of a trial, in both forms the nested learners use.
//!
//! For poses j < k of one trial the move Δθ = θᵏ − θʲ is known exactly, and so is what the
//! camera saw before (cʲ) and after (cᵏ) it. Two patterns follow:
//! - the **adjusted** form (lin5): input (θ2ʲ, θ3ʲ, c*) with c* = cʲ − R(Δθ1)·cᵏ for the image
//!   offsets and cz* = czʲ − czᵏ. R turns image k's axes into image j's: the optical axis is
//!   vertical, so a base yaw of Δθ1 turns the image by −Δθ1 about the optical axis. The
//!   pattern is exact when cᵏ = 0 and a first-order estimate near it.
//! - the **unadjusted** form (lin8): input (θ2ʲ, θ3ʲ, cʲ, d = cᵏ), exact for every pair.
//!
//! The target of both is Δθ in degrees.

use super::Observation;
use nalgebra::{SVector, Vector3};

/// A learning pattern with `N` inputs and the joint move Δθ (degrees) as target.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Pattern<const N: usize> {
    /// The learner's input vector.
    pub input: SVector<f64, N>,
    /// The joint move (Δθ1, Δθ2, Δθ3) in degrees.
    pub target: Vector3<f64>,
}

/// The adjusted 5-input pattern: (θ2, θ3, cx*, cy*, cz*) → Δθ.
pub type Pattern5 = Pattern<5>;
/// The unadjusted 8-input pattern: (θ2, θ3, cx, cy, cz, dx, dy, dz) → Δθ.
pub type Pattern8 = Pattern<8>;

/// Which pose pairs of a trial's path are learning patterns: those whose move is an actual
/// move. The one home of the `minimal_joint_move` entry; every learner that learns from
/// pose pairs holds one.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PatternSettings {
    /// A pose pair is a pattern only if some joint moved at least this much (degrees);
    /// 0.01 by default.
    pub minimal_joint_move: f64,
}

impl Default for PatternSettings {
    fn default() -> Self {
        PatternSettings {
            minimal_joint_move: 0.01,
        }
    }
}

impl PatternSettings {
    /// The pose pairs of `path` that are learning patterns ([`pose_pairs`]).
    pub fn pairs<'a>(
        &self,
        path: &'a [Observation],
    ) -> impl Iterator<Item = (&'a Observation, &'a Observation)> {
        pose_pairs(path, self.minimal_joint_move)
    }
}

/// Every pair (j, k), j < k, of a trial's poses whose move is an actual move: at least one
/// joint moved by `minimal_joint_move_deg` or more.
pub fn pose_pairs(
    path: &[Observation],
    minimal_joint_move_deg: f64,
) -> impl Iterator<Item = (&Observation, &Observation)> {
    path.iter().enumerate().flat_map(move |(j, from)| {
        path[j + 1..]
            .iter()
            .filter(move |to| (to.theta_deg - from.theta_deg).amax() >= minimal_joint_move_deg)
            .map(move |to| (from, to))
    })
}

/// The adjusted (lin5) pattern of the move from `from` to `to`.
pub fn adjusted_pattern(from: &Observation, to: &Observation) -> Pattern5 {
    let delta = to.theta_deg - from.theta_deg;
    let (sin, cos) = (-delta.x.to_radians()).sin_cos();
    let (kx, ky) = (to.c.x, to.c.y);
    let seen_from_j = (kx * cos - ky * sin, kx * sin + ky * cos);
    Pattern {
        input: SVector::<f64, 5>::new(
            from.theta_deg.y,
            from.theta_deg.z,
            from.c.x - seen_from_j.0,
            from.c.y - seen_from_j.1,
            from.c.z - to.c.z,
        ),
        target: delta,
    }
}

/// The adjusted input `input` (θ2, θ3, cx*, cy*, cz*) with the target centred: the same
/// pose, no offset. The eye-hand mapping's answer there is no move.
pub fn centred(input: &SVector<f64, 5>) -> SVector<f64, 5> {
    SVector::<f64, 5>::new(input[0], input[1], 0.0, 0.0, 0.0)
}

/// The unadjusted (lin8) pattern of the move from `from` to `to`.
pub fn unadjusted_pattern(from: &Observation, to: &Observation) -> Pattern8 {
    Pattern {
        input: SVector::<f64, 8>::from_column_slice(&[
            from.theta_deg.y,
            from.theta_deg.z,
            from.c.x,
            from.c.y,
            from.c.z,
            to.c.x,
            to.c.y,
            to.c.z,
        ]),
        target: to.theta_deg - from.theta_deg,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn obs(theta: [f64; 3], c: [f64; 3]) -> Observation {
        Observation {
            theta_deg: Vector3::from(theta),
            c: Vector3::from(c),
        }
    }

    #[test]
    fn a_path_of_n_poses_gives_every_pair_once() {
        let path: Vec<_> = (0..5)
            .map(|i| obs([i as f64, 0.0, 0.0], [0.0; 3]))
            .collect();
        let pairs: Vec<_> = pose_pairs(&path, 0.01).collect();
        assert_eq!(pairs.len(), 10);
        assert!(pairs.iter().all(|(a, b)| a.theta_deg.x < b.theta_deg.x));
    }

    #[test]
    fn pairs_that_barely_moved_give_no_pattern() {
        let path = [
            obs([0.0, 0.0, 0.0], [0.0; 3]),
            obs([0.005, -0.005, 0.0], [0.0; 3]),
        ];
        assert_eq!(pose_pairs(&path, 0.01).count(), 0);
        assert_eq!(pose_pairs(&path, 0.001).count(), 1);
    }

    #[test]
    fn adjusted_pattern_is_the_plain_move_when_the_target_was_hit() {
        let p = adjusted_pattern(
            &obs([1.0, 20.0, 90.0], [30.0, -4.0, 12.0]),
            &obs([3.0, 21.0, 88.0], [0.0; 3]),
        );
        assert_eq!(
            p.input,
            SVector::<f64, 5>::new(20.0, 90.0, 30.0, -4.0, 12.0)
        );
        assert_eq!(p.target, Vector3::new(2.0, 1.0, -2.0));
    }

    #[test]
    fn adjusted_pattern_turns_the_residual_by_the_base_yaw() {
        // A 90° base yaw turns image k by −90° relative to image j: (10, 0) in k is (0, −10) in j.
        let p = adjusted_pattern(
            &obs([0.0, 0.0, 0.0], [0.0; 3]),
            &obs([90.0, 0.0, 0.0], [10.0, 0.0, 5.0]),
        );
        assert!((p.input[2] - 0.0).abs() < 1e-12);
        assert!((p.input[3] - 10.0).abs() < 1e-12);
        assert_eq!(p.input[4], -5.0);
    }

    #[test]
    fn unadjusted_pattern_carries_both_readings() {
        let p = unadjusted_pattern(
            &obs([0.0, 10.0, 80.0], [1.0, 2.0, 3.0]),
            &obs([1.0, 11.0, 79.0], [4.0, 5.0, 6.0]),
        );
        assert_eq!(
            p.input.as_slice(),
            &[10.0, 80.0, 1.0, 2.0, 3.0, 4.0, 5.0, 6.0]
        );
        assert_eq!(p.target, Vector3::new(1.0, 1.0, -1.0));
    }
}
