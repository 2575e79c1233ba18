//! Any robot from its URDF (or a xacro file, expanded): links and joints as a tree, meshes
//! read from disk, the serial chain from the root to a camera link, and its forward
//! kinematics.

mod auto_arm;
mod chain;
mod convert;
mod error;
mod geometry;
mod inertia;
mod joint;
mod kinematics;
mod link;
mod mesh;
mod oscar6;
mod ranges;
mod resolve;
mod robot;
mod tree;
mod warning;
mod xacro;

pub use auto_arm::{camera_choice, CameraChoice};
pub use chain::{Chain, ChainBody, ChainJoint, HeldJoint};
pub use error::{DescriptionError, DescriptionErrorKind};
pub use geometry::{GeometryElement, MeshGeometry, Shape};
pub use inertia::Inertial;
pub use joint::{Joint, JointDynamics, JointKind, JointLimits, Mimic};
pub use link::Link;
pub use mesh::{MeshFormat, TriangleMesh};
pub use oscar6::{load_urdf, parse_urdf, DEFAULT_URDF, DEFAULT_URDF_NAME};
pub use ranges::{MAX_LENGTH_M, MAX_MASS_KG, MESH_SCALE, MIN_SIZE_M};
pub use resolve::{mesh_candidates, resolve_mesh};
pub use robot::{DescriptionOptions, RobotDescription};
pub use warning::DescriptionWarning;
