//! The study's baselines and the references: one feed-forward network for the whole space
//! (ffn), the Kohonen map of local linear maps, the dense network they use, the
//! model-based controller (ik) and the model-free one (broyden, uncalibrated visual
//! servoing).

mod broyden;
mod ffn;
mod ik;
mod kohonen;
pub mod net;

pub(crate) use broyden::BROYDEN_FACTS;
pub use broyden::{Broyden, BroydenSettings, BroydenUpdate, ImageJacobian};
pub(crate) use ffn::FFN_FACTS;
pub use ffn::{FfnLearner, FfnSettings};
pub use ik::IkLearner;
pub(crate) use ik::IK_FACTS;
pub(crate) use kohonen::KOHONEN_FACTS;
pub use kohonen::{KohonenLearner, KohonenSettings, Lattice, Neighbourhood};
