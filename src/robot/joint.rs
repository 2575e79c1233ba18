//! The parts of the URDF the simulators use: revolute joints and link bodies.

use super::description::TriangleMesh;
use nalgebra::{Isometry3, Matrix3, Point3, Unit, Vector3};
use std::sync::Arc;

/// A revolute joint of the arm, as its URDF element gives it (SI units).
#[derive(Debug, Clone, PartialEq)]
pub struct RevoluteJoint {
    /// The joint's URDF name.
    pub name: String,
    /// Pose of the joint frame in the parent link's frame (the URDF `<origin>`).
    pub origin: Isometry3<f64>,
    /// Unit rotation axis in the joint frame.
    pub axis: Unit<Vector3<f64>>,
    /// Lower limit (rad).
    pub lower: f64,
    /// Upper limit (rad).
    pub upper: f64,
    /// Maximum effort (N·m).
    pub effort: f64,
    /// Maximum speed (rad/s).
    pub velocity: f64,
    /// Viscous damping (N·m·s/rad), the URDF `<dynamics damping>`; 0 when absent.
    pub damping: f64,
    /// Dry (Coulomb) friction (N·m), the URDF `<dynamics friction>`; 0 when absent: the
    /// dynamic simulator's joint resists turning with up to this torque.
    pub friction: f64,
}

impl RevoluteJoint {
    /// True when `angle` lies inside the limits.
    pub fn admits(&self, angle: f64) -> bool {
        angle >= self.lower && angle <= self.upper
    }

    /// The limits cut to one turn either way (−π..π for a joint with wider or no limits):
    /// the angles worth sampling.
    pub fn one_turn(&self) -> (f64, f64) {
        let half = std::f64::consts::PI;
        (self.lower.max(-half), self.upper.min(half))
    }

    /// The middle of the limits (0 for a joint without limits).
    pub fn middle(&self) -> f64 {
        let middle = 0.5 * (self.lower + self.upper);
        if middle.is_finite() {
            middle
        } else {
            0.0
        }
    }

    /// The joint frame's pose in the parent link's frame at `angle`.
    pub fn transform(&self, angle: f64) -> Isometry3<f64> {
        self.origin * nalgebra::UnitQuaternion::from_axis_angle(&self.axis, angle)
    }
}

/// A link's inertial and collision data, for the dynamic simulator.
#[derive(Debug, Clone, PartialEq)]
pub struct LinkBody {
    /// The link's URDF name.
    pub name: String,
    /// Mass (kg).
    pub mass: f64,
    /// Centre of mass and inertia frame in the link frame.
    pub inertial_origin: Isometry3<f64>,
    /// Inertia tensor (kg·m²) in the inertial frame.
    pub inertia: Matrix3<f64>,
    /// Collision shapes with their poses in the link frame.
    pub collisions: Vec<(Isometry3<f64>, Shape)>,
}

/// A collision shape of a link: the URDF's primitives, or a collision mesh with its convex
/// hull.
#[derive(Debug, Clone, PartialEq)]
pub enum Shape {
    /// A box with these full side lengths (m).
    Cuboid(Vector3<f64>),
    /// A cylinder along the local z axis.
    Cylinder {
        /// Radius (m).
        radius: f64,
        /// Length (m).
        length: f64,
    },
    /// A capsule along the local z axis.
    Capsule {
        /// Radius (m).
        radius: f64,
        /// Length of the cylindrical part (m).
        length: f64,
    },
    /// A ball.
    Sphere {
        /// Radius (m).
        radius: f64,
    },
    /// A collision mesh: the ray-cast camera sees its triangles, the physics' contacts its
    /// convex hull, the floor and contact rules the hull's bounding box.
    Hull {
        /// The mesh's own triangles in the element's frame (m).
        triangles: Arc<TriangleMesh>,
        /// Their hull, a closed convex mesh in the element's frame (m).
        mesh: Arc<TriangleMesh>,
        /// The centre of its bounding box in the element's frame (m).
        centre: Vector3<f64>,
        /// The bounding box's side lengths (m).
        size: Vector3<f64>,
    },
}

impl Shape {
    /// The collision mesh `triangles` with its convex hull `mesh` (closed, convex, in the
    /// element's frame) and the hull's bounding box.
    pub fn hull(triangles: Arc<TriangleMesh>, mesh: Arc<TriangleMesh>) -> Shape {
        let (low, high) = mesh.vertices.iter().fold(
            (
                Point3::from([f64::INFINITY; 3]),
                Point3::from([f64::NEG_INFINITY; 3]),
            ),
            |(low, high), p| (low.inf(p), high.sup(p)),
        );
        Shape::Hull {
            centre: nalgebra::center(&low, &high).coords,
            size: high - low,
            triangles,
            mesh,
        }
    }
}
