//! Online learners from the literature that learn the mapping as one model: LWPR, I-SSGP
//! and an online network with replay.

mod issgp;
mod lwpr;
mod mlp;

pub(crate) use issgp::ISSGP_FACTS;
pub use issgp::{Issgp, IssgpSettings};
pub(crate) use lwpr::LWPR_FACTS;
pub use lwpr::{Lwpr, LwprSettings};
pub(crate) use mlp::MLP_FACTS;
pub use mlp::{Mlp, MlpSettings};
