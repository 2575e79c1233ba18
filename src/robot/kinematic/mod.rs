//! The kinematic simulator and the motion it shares with the dynamic one: the trapezoidal
//! move profile with its joint-limit stop, its pace under the joints' velocity limits, and
//! the set-point of continuous servoing.

pub(crate) mod motion;
pub(crate) mod pace;
mod sim;
mod tracking;

pub use motion::{limit_stop_fraction, TrapezoidProfile};
pub use sim::KinematicSim;
pub use tracking::SetPointTracker;
