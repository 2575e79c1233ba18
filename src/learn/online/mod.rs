//! Online learners from the literature that learn the mapping as one model: LWPR, I-SSGP
//! and an online network with replay.

mod issgp;
mod lwpr;
mod mlp;

pub use issgp::{Issgp, IssgpSettings};
pub use lwpr::{Lwpr, LwprSettings};
pub use mlp::{Mlp, MlpSettings};
