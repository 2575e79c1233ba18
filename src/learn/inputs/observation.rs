//! What the controller sees at one pose: joint sensors and the camera reading.

use nalgebra::{SVector, Vector3};

/// The robot's state at one pose of a trial, in the learners' units.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Observation {
    /// Controlled joint angles (θ1, θ2, θ3) in degrees, as the joint sensors read them.
    pub theta_deg: Vector3<f64>,
    /// Camera reading c = (cx, cy, cz): image offsets in pixels and the area measure.
    pub c: Vector3<f64>,
}

impl Observation {
    /// The learner's input at this pose: the reading and (θ2, θ3).
    pub fn query(&self) -> Query {
        Query {
            c: self.c,
            theta2_deg: self.theta_deg.y,
            theta3_deg: self.theta_deg.z,
        }
    }
}

/// A learner's input: `Δθ = N(c, θ2, θ3)`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Query {
    /// Camera reading (cx, cy in pixels, cz the area measure).
    pub c: Vector3<f64>,
    /// Shoulder angle θ2 in degrees.
    pub theta2_deg: f64,
    /// Elbow angle θ3 in degrees.
    pub theta3_deg: f64,
}

impl Query {
    /// The five inputs of the 5-input learners: (θ2, θ3, cx, cy, cz).
    pub fn five_inputs(&self) -> SVector<f64, 5> {
        SVector::<f64, 5>::new(
            self.theta2_deg,
            self.theta3_deg,
            self.c.x,
            self.c.y,
            self.c.z,
        )
    }
}

/// A learner's answer as a move: itself when every component is finite, else no move (a
/// learner's answer must always be finite, [`Learner::propose`](crate::learn::Learner::propose)).
pub(crate) fn finite_or_still(answer: Vector3<f64>) -> Vector3<f64> {
    if answer.iter().all(|v| v.is_finite()) {
        answer
    } else {
        Vector3::zeros()
    }
}
