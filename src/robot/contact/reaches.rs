//! How far points of the arm can be from each joint's axis, and so how fast a move can
//! bring them down or together: the bounds the floor and contact rules march by.

use super::collision::Elements;
use crate::robot::{ArmModel, Controlled, Joints, Shape, MAX_JOINTS};
use nalgebra::{Isometry3, Vector3};

/// How far points of the arm can be from the joints' axes (m), for the floor rule's bounds.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Reaches {
    /// `joint[j]`: any point beyond joint j — the later joint origins, the camera mount and
    /// the largest collision element's reach added up. A turn of joint j by δ rad moves no
    /// point of the arm by more than `joint[j]` times δ.
    pub joint: [f64; MAX_JOINTS],
    /// `body[j][k]` (j < k): any point of link k (`bodies[k - 1]`) — the joint origins
    /// from joint j + 1 to joint k - 1 and link k's own farthest element.
    pub body: [[f64; MAX_JOINTS + 1]; MAX_JOINTS],
}

impl Default for Reaches {
    fn default() -> Reaches {
        Reaches {
            joint: [0.0; MAX_JOINTS],
            body: [[0.0; MAX_JOINTS + 1]; MAX_JOINTS],
        }
    }
}

impl Reaches {
    /// How fast (m/s) a point of body `j` (1 for link 1) can come closer to body `i < j`
    /// (0: the base, or anything fixed in the world) with the joints turning at `speeds`
    /// (rad/s): each joint between them, its speed times how far body j reaches from its
    /// axis.
    pub(crate) fn closing_speed(&self, speeds: &Joints, i: usize, j: usize) -> f64 {
        (i..j.min(speeds.len()))
            .map(|k| speeds[k].abs() * self.body[k][j])
            .sum()
    }
}

/// How far any point of the arm, and of each link, can be from each joint's axis (m).
pub(crate) fn reaches(model: &ArmModel, bodies: &[Elements]) -> Reaches {
    let extent = |(pose, shape): &(Isometry3<f64>, Shape)| {
        pose.translation.vector.norm()
            + match *shape {
                Shape::Sphere { radius } => radius,
                Shape::Cuboid(size) => 0.5 * size.norm(),
                Shape::Cylinder { radius, length } | Shape::Capsule { radius, length } => {
                    radius + 0.5 * length
                }
                Shape::Mesh { centre, size, .. } => centre.norm() + 0.5 * size.norm(),
            }
    };
    let shapes = bodies.iter().flatten().map(extent).fold(0.0, f64::max);
    let tail = model.camera_mount().translation.vector.norm() + shapes;
    let origins = model
        .joints()
        .iter()
        .map(|j| j.origin.translation.vector.norm());
    let origins: Vec<f64> = origins.collect();
    let own = |k: usize| bodies[k - 1].iter().map(extent).fold(0.0, f64::max);
    let mut body = [[0.0; MAX_JOINTS + 1]; MAX_JOINTS];
    for k in 1..=bodies.len() {
        for (j, row) in body.iter_mut().enumerate().take(k) {
            row[k] = origins[j + 1..k].iter().sum::<f64>() + own(k);
        }
    }
    Reaches {
        joint: std::array::from_fn(|j| origins.iter().skip(j + 1).sum::<f64>() + tail),
        body,
    }
}

/// A move's line from the arm where it starts, and how far each joint of the chain can turn
/// along it (`WristGains::sweep`): the bounds the floor and contact rules march by.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Sweep {
    /// The learned joints' move (rad).
    pub delta: Controlled,
    /// How fast (rad per whole move by `delta`) each joint can turn anywhere along it: the
    /// learned joints by their share of the move, the wrist's joints as fast as it makes
    /// them, the others not at all.
    pub turns: [f64; MAX_JOINTS],
}

/// How fast (m per unit fraction of a move) any point of the arm can sink with its joints
/// turning at `turns` ([`Sweep::turns`]): each joint's turn times its reach. The first
/// joint's axis is fixed in the world: a turn about it lowers a point by at most its reach
/// times the sine of the axis's angle to the vertical (nothing for a base yaw).
pub(super) fn sinking_speed(model: &ArmModel, reaches: &Reaches, turns: &[f64; MAX_JOINTS]) -> f64 {
    sinking_speeds(turns, first_tilt(model), model.dof(), |joint| {
        reaches.joint[joint]
    })
}

/// The sine of the first joint's axis's angle to the vertical (0 for a base yaw).
pub(super) fn first_tilt(model: &ArmModel) -> f64 {
    let first = &model.joints()[0];
    (first.origin.rotation * first.axis.into_inner())
        .cross(&Vector3::z())
        .norm()
}

/// How fast (m per unit fraction of the move) points as far as `reach(j)` from each of the
/// first `joints` joints' axes can sink when the joints turn by `turns`, the first one's
/// share times `first_tilt` (see [`sinking_speed`]).
pub(super) fn sinking_speeds(
    turns: &[f64; MAX_JOINTS],
    first_tilt: f64,
    joints: usize,
    reach: impl Fn(usize) -> f64,
) -> f64 {
    (0..joints)
        .map(|joint| {
            let tilt = if joint == 0 { first_tilt } else { 1.0 };
            turns[joint] * reach(joint) * tilt
        })
        .sum()
}
