//! The dynamic simulator: the OSCAR-6 as a Rapier multibody under gravity, moved by
//! position servos that follow each move's trapezoidal profile, then settle.

mod builder;
mod colliders;
mod convert;
mod gravity;
mod inertia;
mod motors;
mod settings;
mod settle;
mod sim;

pub use settings::DynamicSettings;
pub use sim::{DynamicSim, SimCounters};
