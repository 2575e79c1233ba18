//! The parts of the URDF the simulators use: revolute joints and link bodies.

use crate::robot::description::Shape;
use nalgebra::{Isometry3, Matrix3, Unit, Vector3};

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

    /// The angles worth sampling: the limits when they span less than a turn (wherever
    /// they lie: 47°..313° as they are), else one turn, −π..π (a joint without limits too).
    pub fn one_turn(&self) -> (f64, f64) {
        let half = std::f64::consts::PI;
        if self.upper - self.lower < 2.0 * half {
            (self.lower, self.upper)
        } else {
            (-half, half)
        }
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
