//! Unit conversions between the simulators' SI units and the thesis's user-facing units.
//!
//! Inside the robot and camera models lengths are metres and angles radians (URDF
//! convention); everything a user or a learner reads is in centimetres, degrees and, for
//! distances to the target, millimetres. Angles convert with `f64::to_radians` and
//! `f64::to_degrees`.

/// Metres per centimetre.
pub const M_PER_CM: f64 = 0.01;
/// Millimetres per metre.
pub const MM_PER_M: f64 = 1000.0;
