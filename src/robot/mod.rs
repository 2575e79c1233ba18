//! The OSCAR-6 arm: its URDF model and forward kinematics, inverse kinematics for the
//! camera position, the reach space, moves, and the simulators behind one trait.

mod contact;
pub mod description;
mod dynamic;
mod error;
mod kinematic;
mod model;
mod reach;
mod simulator;

pub use contact::{
    ContactRule, Obstacle, RayHit, Surface, Touch, WorldView, CONTACT_MARGIN, DEFAULT_FLOOR_Z,
    SEEN_BODIES,
};
pub use description::{
    load_urdf, parse_urdf, Chain, DescriptionError, DescriptionOptions, RobotDescription, Shape,
    DEFAULT_URDF, DEFAULT_URDF_NAME,
};
pub use dynamic::{
    Drive, DynamicSettings, DynamicSim, Energy, Engine, FreeArm, SimCounters, SpeedFault,
};
pub use error::RobotError;
pub use kinematic::{limit_stop_fraction, KinematicSim, SetPointTracker, TrapezoidProfile};
pub use model::{
    ArmModel, ArmPose, ArmSettings, BaseLink, Branch, CameraLink, Centre, Controlled, Frames,
    Joints, LearnedJoints, LinkBody, PoseGrid, RevoluteJoint, Wrist, MAX_JOINTS,
};
pub use reach::{ReachFit, ReachFitFailure, ReachSpace, WristLimit};
pub use simulator::{MoveReport, MoveSettings, SimWork, Simulator};
