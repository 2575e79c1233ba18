//! A joint of a robot description: its kind, frame, axis, limits and dynamics.

use nalgebra::{Isometry3, Translation3, Unit, UnitQuaternion, Vector3};

/// The joint kinds read from a URDF.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum JointKind {
    /// No motion: the child is rigidly attached.
    Fixed,
    /// A turn about the axis within limits.
    Revolute,
    /// A turn about the axis without limits.
    Continuous,
    /// A slide along the axis within limits.
    Prismatic,
}

impl JointKind {
    /// True for every kind but `Fixed`.
    pub fn moves(self) -> bool {
        self != JointKind::Fixed
    }
}

/// A joint's limits as the URDF gives them.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct JointLimits {
    /// Lower position (rad or m); −∞ for a continuous joint or a URDF 1.2 joint without one.
    pub lower: f64,
    /// Upper position (rad or m); +∞ likewise. Limits may be asymmetric.
    pub upper: f64,
    /// Maximum effort (N·m or N); `None` where the URDF gives none, 0 or ∞.
    pub effort: Option<f64>,
    /// Maximum speed (rad/s or m/s); `None` where the URDF gives none, 0 or ∞.
    pub velocity: Option<f64>,
}

impl JointLimits {
    /// True when `position` lies inside the limits.
    pub fn admits(&self, position: f64) -> bool {
        position >= self.lower && position <= self.upper
    }

    /// The position nearest to zero inside the limits: where a joint is held by default.
    pub fn default_position(&self) -> f64 {
        0.0_f64.clamp(self.lower, self.upper)
    }
}

/// Viscous damping and dry friction of a joint (the URDF's `<dynamics>`, 0 when absent).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct JointDynamics {
    /// Damping (N·m·s/rad or N·s/m).
    pub damping: f64,
    /// Static friction (N·m or N).
    pub friction: f64,
}

/// A joint that follows another (the URDF's `<mimic>`): its position is the leader's times
/// `multiplier` plus `offset`.
#[derive(Debug, Clone, PartialEq)]
pub struct Mimic {
    /// The leader joint's name.
    pub joint: String,
    /// The factor on the leader's position (1 when the URDF gives none).
    pub multiplier: f64,
    /// The offset added (rad or m; 0 when the URDF gives none).
    pub offset: f64,
}

/// A joint between two links of the description.
#[derive(Debug, Clone, PartialEq)]
pub struct Joint {
    /// The joint's URDF name.
    pub name: String,
    /// What motion it allows.
    pub kind: JointKind,
    /// Index of the parent link in the description.
    pub parent: usize,
    /// Index of the child link in the description.
    pub child: usize,
    /// Pose of the joint frame (= the child link's frame at position 0) in the parent link.
    pub origin: Isometry3<f64>,
    /// Unit axis in the joint frame (x for fixed joints, where it means nothing).
    pub axis: Unit<Vector3<f64>>,
    /// Position, effort and speed limits.
    pub limits: JointLimits,
    /// Damping and friction.
    pub dynamics: JointDynamics,
    /// The joint it follows, if it mimics one.
    pub mimic: Option<Mimic>,
}

impl Joint {
    /// The child link's pose in the parent link at joint position `position` (rad or m).
    pub fn transform(&self, position: f64) -> Isometry3<f64> {
        self.origin * motion(self.kind, &self.axis, position)
    }
}

/// The motion a joint of `kind` about or along `axis` makes at `position`.
pub(super) fn motion(kind: JointKind, axis: &Unit<Vector3<f64>>, position: f64) -> Isometry3<f64> {
    match kind {
        JointKind::Fixed => Isometry3::identity(),
        JointKind::Revolute | JointKind::Continuous => Isometry3::from_parts(
            Translation3::identity(),
            UnitQuaternion::from_axis_angle(axis, position),
        ),
        JointKind::Prismatic => Isometry3::from_parts(
            Translation3::from(axis.into_inner() * position),
            UnitQuaternion::identity(),
        ),
    }
}
