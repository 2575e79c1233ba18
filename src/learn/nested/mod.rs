//! The study's nested learners: the nested tree they share, the perceptron that is lin5's
//! and lin8's node model, and the learners themselves (lin5, lin8, nnw).

mod lin5;
mod lin8;
mod merge_strategy;
mod nnw;
mod perceptron;
pub(crate) mod tree;

pub(crate) use lin5::LIN5_FACTS;
pub use lin5::{Lin5, Lin5Settings};
pub(crate) use lin8::LIN8_FACTS;
pub use lin8::{Lin8, Lin8Settings};
pub use merge_strategy::MergeStrategy;
pub(crate) use nnw::NNW_FACTS;
pub use nnw::{Nnw, NnwSettings};
pub use perceptron::PerceptronSettings;
pub use tree::{NestedLearner, NestedSettings, TreeSettings};
