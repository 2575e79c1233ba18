//! The dynamic simulator: an arm (the OSCAR-6 or any chain) as a Rapier multibody under
//! gravity, moved by servos that follow each move's trapezoidal profile, then settle;
//! stepped by one of two engines: `rk4` integrates its joint-space equations to fourth
//! order tick by tick under eyehand's servo law, `rapier` lets Rapier's multibody
//! integrator step it, each joint driven by a Rapier joint motor.

mod body_parts;
mod builder;
mod colliders;
mod contacts;
mod convert;
mod dry_friction;
mod energy;
mod faults;
mod free;
mod gravity;
mod inertia;
mod integrator;
mod inverse_dynamics;
mod joint_space;
mod joint_state;
mod motors;
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
pub use faults::SpeedFault;
pub use free::{Drive, FreeArm};
pub(super) use seen::compound;
pub use settings::{DynamicSettings, Engine};
pub use sim::{DynamicSim, SimCounters};
