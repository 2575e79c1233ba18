//! The `kohonen` learner: a 7×7×7×7×7 self-organising map over the 5-D input space whose
//! neurons each hold a local linear map (an output and a Jacobian), trained the
//! Ritter–Martinetz–Schulten way with a shrinking neighbourhood. The winner's linear map
//! answers; the control loop's first step is the gross move and the next ones fine moves.

mod lattice;
mod learner;

pub use lattice::{Lattice, Neighbourhood};
pub(crate) use learner::KOHONEN_FACTS;
pub use learner::{KohonenLearner, KohonenSettings};
