//! What the arm may touch and what a camera sees: the arm's collision shapes as it is now,
//! the floor stop both simulators share, the self-collision and obstacle stop, and the
//! world of floor, obstacles and arm bodies that rays meet.

mod capsule;
pub(crate) mod clearance;
pub(crate) mod collision;
pub(crate) mod contact_free;
pub(crate) mod contact_march;
pub(crate) mod floor;
mod part;
pub(crate) mod reaches;
pub(crate) mod world;

pub use contact_free::{ContactRule, Touch, CONTACT_MARGIN};
pub use floor::DEFAULT_FLOOR_Z;
pub use world::{Obstacle, RayHit, Surface, WorldView, SEEN_BODIES};
