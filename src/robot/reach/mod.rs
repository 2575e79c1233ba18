//! The reach space targets are drawn from: the study's half annulus for the OSCAR-6, and
//! the same shape (or, where it does not fit, another) fitted to any other arm.

mod fit;
mod grid;
mod space;

pub use fit::{ReachFit, ReachFitFailure, WristLimit};
pub use space::ReachSpace;
