//! A link of a robot description: its mass properties, geometry and place in the tree.

use super::geometry::GeometryElement;
use super::inertia::Inertial;

/// A link as the URDF gives it, in its own frame (SI units).
#[derive(Debug, Clone, PartialEq)]
pub struct Link {
    /// The link's URDF name.
    pub name: String,
    /// Mass, centre of mass and inertia tensor in the link frame (massless when absent).
    pub inertial: Inertial,
    /// Visual shapes that could be read.
    pub visuals: Vec<GeometryElement>,
    /// Collision shapes; a missing mesh is replaced by a capsule (see the warnings).
    pub collisions: Vec<GeometryElement>,
    /// The joint whose child this link is (`None` for the root).
    pub parent_joint: Option<usize>,
    /// The joints whose parent this link is, in URDF order.
    pub child_joints: Vec<usize>,
}
