//! Unit conversions between the simulators' SI units and the thesis's user-facing units.
//!
//! Inside the robot and camera models lengths are metres and angles radians (URDF
//! convention); everything a user or a learner reads is in centimetres, degrees and, for
//! distances to the target, millimetres.

/// Metres per centimetre.
pub const M_PER_CM: f64 = 0.01;
/// Millimetres per metre.
pub const MM_PER_M: f64 = 1000.0;

/// Degrees to radians.
pub fn rad(deg: f64) -> f64 {
    deg.to_radians()
}

/// Radians to degrees.
pub fn deg(rad: f64) -> f64 {
    rad.to_degrees()
}
