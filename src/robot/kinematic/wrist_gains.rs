//! How the joints the wrist solves turn with the learned joints, worked out once per arm:
//! where they follow the learned joints linearly (the OSCAR-6's θ5 against θ2 and θ3, the
//! Panda's joint 6), each one's slopes, which give a move's exact turns.

use crate::robot::{ArmModel, Controlled, Joints, MAX_JOINTS};
use nalgebra::{Isometry3, Matrix3, Vector3};

/// Probes per learned joint across its range ([`RevoluteJoint::one_turn`]): the wrist's
/// slopes are compared on a grid of `PROBES³` poses.
///
/// [`RevoluteJoint::one_turn`]: crate::robot::RevoluteJoint::one_turn
const PROBES: usize = 9;
/// The most a linear wrist's slopes may differ between probes (the rounding of its solve).
const LINEAR_SPREAD: f64 = 1e-12;
/// The grid a linear wrist's slopes are snapped to, where they lie within
/// [`SNAP_TOLERANCE`] of it (the OSCAR-6's 0 and ±1 exactly).
const SNAP: f64 = 1e-9;
/// See [`SNAP`].
const SNAP_TOLERANCE: f64 = 1e-12;
/// How far a linear wrist's turn over a move may differ from its slopes' answer before the
/// move is taken to have wrapped a wrist angle by a whole turn (rad).
const WRAP_TOLERANCE: f64 = 1e-6;

/// Slopes of a chain's joints against the learned joints: `[k][i]` is d(joint k)/d(learned
/// joint i).
type Slopes = [[f64; 3]; MAX_JOINTS];

/// How the joints of an arm's chain turn with its learned joints.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub(crate) struct WristGains {
    /// Each joint's slopes, the same at every pose: present when the wrist follows the
    /// learned joints linearly (1 for a learned joint against itself, 0 for a joint held
    /// at rest).
    slope: Option<Slopes>,
    /// The joints of the chain.
    len: usize,
}

impl WristGains {
    /// The gains of `model` as it is now, from the wrist's slopes on a grid of poses over
    /// the learned joints' ranges.
    pub(crate) fn new(model: &ArmModel) -> WristGains {
        let (mut first, mut spread) = (None::<Slopes>, 0.0f64);
        for_each_probe(model, |slopes| {
            let first = first.get_or_insert(slopes);
            for (row, first_row) in slopes.iter().zip(first.iter()) {
                for (s, f) in row.iter().zip(first_row) {
                    spread = spread.max((s - f).abs());
                }
            }
        });
        let slope = first.filter(|_| spread <= LINEAR_SPREAD).map(|mut slope| {
            slope.iter_mut().flatten().for_each(|s| *s = snapped(*s));
            for (i, &j) in model.learned().iter().enumerate() {
                slope[j] = [0.0; 3];
                slope[j][i] = 1.0;
            }
            slope
        });
        WristGains {
            slope,
            len: model.dof(),
        }
    }

    /// How far (rad) each joint turns in the move by `delta` from the joints `start` to
    /// `end`, exactly: where the wrist follows the learned joints linearly and no wrist
    /// angle was wrapped by a whole turn on the way (its turn from `start` to `end` is what
    /// its slopes give); `None` otherwise.
    pub(crate) fn linear_turns(
        &self,
        delta: &Controlled,
        start: &Joints,
        end: &Joints,
    ) -> Option<Joints> {
        let slope = self.slope.as_ref()?;
        let mut turns = Joints::zeros(self.len);
        for k in 0..self.len {
            let turn = slope[k][0] * delta[0] + slope[k][1] * delta[1] + slope[k][2] * delta[2];
            if (end[k] - start[k] - turn).abs() > WRAP_TOLERANCE {
                return None;
            }
            turns[k] = turn.abs();
        }
        Some(turns)
    }
}

/// `s`, or the multiple of [`SNAP`] it lies within [`SNAP_TOLERANCE`] of.
fn snapped(s: f64) -> f64 {
    let near = (s / SNAP).round() * SNAP;
    if (s - near).abs() <= SNAP_TOLERANCE {
        near
    } else {
        s
    }
}

/// Calls `take` with the wrist's slopes at every probe of the grid where it has a solution
/// and is not singular, each probe's solve starting from the last one found.
fn for_each_probe(model: &ArmModel, mut take: impl FnMut(Slopes)) {
    let ranges = model.learned().map(|j| model.joints()[j].one_turn());
    let at = |(lower, upper): (f64, f64), k: usize| {
        lower + (upper - lower) * (k as f64 + 0.5) / PROBES as f64
    };
    let mut near = model.rest();
    for a in 0..PROBES {
        for b in 0..PROBES {
            for c in 0..PROBES {
                let theta = Controlled::new(at(ranges[0], a), at(ranges[1], b), at(ranges[2], c));
                let pose = model.pose_near(&theta, &near);
                if pose.wrist_found {
                    near = pose.joints;
                    slopes_at(model, &pose.joints).map(&mut take);
                }
            }
        }
    }
}

/// d(joint k)/d(learned joint i) at the pose `q`, whose optical axis points down: the
/// wrist joints turn so that the learned joints' turns tilt the axis not at all (each
/// joint tilts it by the part of its axis across it; least squares where the wrist has
/// more joints than it needs). `None` where the wrist is singular.
fn slopes_at(model: &ArmModel, q: &Joints) -> Option<Slopes> {
    let mut pose = Isometry3::identity();
    let mut axes = [Vector3::zeros(); MAX_JOINTS];
    for (k, joint) in model.joints().iter().enumerate() {
        pose *= joint.transform(q[k]);
        axes[k] = pose.rotation * joint.axis.into_inner();
    }
    let optical = (pose * model.camera_mount()).rotation * Vector3::z();
    let tilting = |k: usize| axes[k] - optical * optical.dot(&axes[k]);
    let (mut solved, mut count) = ([0; 3], 0);
    for k in (0..model.dof()).filter(|&k| model.wrist().sets(k)).take(3) {
        solved[count] = k;
        count += 1;
    }
    let wrist = Matrix3::from_fn(|r, c| {
        if c < count {
            tilting(solved[c])[r]
        } else {
            0.0
        }
    });
    let learned = Matrix3::from_columns(&model.learned().map(tilting));
    let unused = Vector3::from_fn(|i, _| if i < count { 0.0 } else { 1.0 });
    let normal = wrist.transpose() * wrist + Matrix3::from_diagonal(&unused);
    let follow = normal.lu().solve(&(wrist.transpose() * learned))?;
    let mut slopes = [[0.0; 3]; MAX_JOINTS];
    for (s, &k) in solved.iter().enumerate().take(count) {
        slopes[k] = [0, 1, 2].map(|i| -follow[(s, i)]);
    }
    Some(slopes)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_oscar6_wrist_follows_theta2_and_theta3_with_slopes_of_one() {
        let model = ArmModel::oscar6();
        let gains = WristGains::new(&model);
        let slope = gains.slope.expect("linear");
        assert_eq!(slope[4], [0.0, 1.0, -1.0]);
        assert_eq!((slope[3], slope[5]), ([0.0; 3], [0.0; 3]));
        assert_eq!(slope[1], [0.0, 1.0, 0.0]);
        // Along a move, θ5 turns by exactly what its slopes give.
        let delta = Controlled::new(0.3, -0.2, 0.5);
        let from = Controlled::new(0.1, 0.4, -0.6);
        let (start, end) = (model.full_pose(&from), model.full_pose(&(from + delta)));
        let exact = gains.linear_turns(&delta, &start, &end).expect("no wrap");
        assert_eq!(exact.as_slice()[..3], [0.3, 0.2, 0.5]);
        assert!((exact[4] - (end[4] - start[4]).abs()).abs() < 1e-12);
        assert!((exact[4] - 0.7).abs() < 1e-12, "{}", exact[4]);
        // A wrist angle wrapped by a whole turn on the way: not exact.
        let mut wrapped = end;
        wrapped[4] -= std::f64::consts::TAU;
        assert_eq!(gains.linear_turns(&delta, &start, &wrapped), None);
    }
}
