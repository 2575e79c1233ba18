//! The dynamic simulator: an arm (the OSCAR-6 or any chain) as a Rapier multibody under
//! gravity, its joint-space equations integrated to fourth order tick by tick, moved by
//! servos that follow each move's trapezoidal profile, then settle.

mod body_parts;
mod builder;
mod colliders;
mod contacts;
mod convert;
mod energy;
mod free;
mod gravity;
mod inertia;
mod integrator;
mod inverse_dynamics;
mod joint_space;
mod joint_state;
mod placement;
mod seen;
mod servo;
mod servo_law;
mod settings;
mod settle;
mod sim;

pub(super) use colliders::parts;
pub(super) use convert::{to_pose, to_vector};
pub use energy::Energy;
pub use free::{Drive, FreeArm};
pub(super) use seen::compound;
pub use settings::DynamicSettings;
pub use sim::{DynamicSim, SimCounters};
