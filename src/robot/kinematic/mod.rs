//! The kinematic simulator and the motion it shares with the dynamic one: the trapezoidal
//! move profile with its joint-limit stop, its pace under the joints' velocity limits, how
//! fast the wrist turns with the learned joints, and the set-point of continuous servoing.

pub(crate) mod motion;
pub(crate) mod pace;
mod sim;
mod tracking;
pub(crate) mod wrist_gains;

pub use motion::{limit_stop_fraction, TrapezoidProfile};
pub use sim::KinematicSim;
pub use tracking::SetPointTracker;
