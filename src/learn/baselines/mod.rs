//! The study's baselines and the reference: one feed-forward network for the whole space
//! (ffn), the Kohonen map of local linear maps, the dense network they use, and the
//! model-based controller (ik).

mod ffn;
mod ik;
mod kohonen;
pub mod net;

pub use ffn::{FfnLearner, FfnSettings};
pub use ik::IkLearner;
pub use kohonen::{KohonenLearner, KohonenSettings, Lattice, Neighbourhood};
