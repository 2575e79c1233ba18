//! A small dense feed-forward network (one tanh hidden layer) with back-propagation and
//! conjugate-gradient training, shared by the `nnw` and `ffn` learners.

mod batch;
mod batch_passes;
mod cg;
mod dense;
mod scaling;
mod tanh;

pub use batch::BatchLoss;
pub use cg::{minimize, Objective};
pub use dense::DenseNet;
pub use scaling::InputScaling;
pub(crate) use tanh::tanh;
