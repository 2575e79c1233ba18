//! What the arm may touch and what a camera sees: the arm's collision shapes as it is now,
//! the floor stop both simulators share, the self-collision and obstacle stop, and the
//! world of floor, obstacles and arm bodies that rays meet.

pub(crate) mod clearance;
pub(crate) mod collision;
pub(crate) mod contact_free;
pub(crate) mod world;

pub use collision::DEFAULT_FLOOR_Z;
pub use contact_free::{ContactRule, Touch, CONTACT_MARGIN};
pub use world::{Obstacle, RayHit, Surface, WorldView, SEEN_BODIES};
