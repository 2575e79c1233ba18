//! The OSCAR-6 arm: its URDF model and forward kinematics, inverse kinematics for the
//! camera position, the reach space, moves, and the simulators behind one trait.

mod clearance;
mod collision;
mod contact_free;
pub mod description;
mod dynamic;
mod error;
mod ik;
mod ik_seeds;
mod joint;
mod joint_vector;
mod kinematic;
mod model;
mod motion;
mod reach;
mod reach_fit;
mod simulator;
mod tracking;
mod urdf;
mod world;

pub use collision::DEFAULT_FLOOR_Z;
pub use contact_free::{ContactRule, Touch, CONTACT_MARGIN};
pub use description::{Chain, DescriptionError, DescriptionOptions, RobotDescription, Shape};
pub use dynamic::{
    Drive, DynamicSettings, DynamicSim, Energy, Engine, FreeArm, SimCounters, SpeedFault,
};
pub use error::RobotError;
pub use joint::{LinkBody, RevoluteJoint};
pub use joint_vector::{Joints, MAX_JOINTS};
pub use kinematic::KinematicSim;
pub use model::{
    ArmModel, ArmPose, ArmSettings, CameraLink, Controlled, Frames, LearnedJoints, Wrist,
};
pub use motion::{limit_stop_fraction, TrapezoidProfile};
pub use reach::ReachSpace;
pub use reach_fit::{ReachFit, ReachFitFailure};
pub use simulator::{MoveReport, MoveSettings, SimWork, Simulator};
pub use tracking::SetPointTracker;
pub use urdf::{load_urdf, parse_urdf, DEFAULT_URDF, DEFAULT_URDF_NAME};
pub use world::{Obstacle, RayHit, Surface, WorldView, SEEN_BODIES};
