//! `issgp`: incremental sparse spectrum Gaussian process regression (Gijsberts and
//! Metta, "Real-time model learning using Incremental Sparse Spectrum Gaussian Process
//! Regression", Neural Networks 41, 2013), written here from the paper.
//!
//! It learns from the same adjusted 5-input patterns as `lin5` and `lwpr` (see
//! [`adjusted_pattern`](crate::learn::adjusted_pattern)): (θ2, θ3, cx*, cy*, cz*) → Δθ,
//! each input scaled by the configured boundaries `boundary_0` … `boundary_4`, each output
//! divided by `norm_out` degrees. A query's input is its reading and pose.
//!
//! - A squared-exponential kernel with a length scale per input (`issgp_length_scales`, as
//!   fractions of the inputs' boundary ranges) and amplitude σf (`issgp_signal`) is
//!   approximated by D random Fourier features (`issgp_features`, [`features`]).
//! - On them, Bayesian linear regression with noise σn (`issgp_noise`); its precision
//!   matrix, shared by the three outputs, is kept as a Cholesky factor updated by one
//!   rank-one update per pattern: O(D²) work and constant memory whatever the number of
//!   patterns ([`posterior`]). As D grows the answer tends to that of the exact GP.
//! - Forgetting (`issgp_forgetting` λ < 1) weighs the past down by λ per pattern, the prior
//!   included, so 1/(1 − λ) patterns should be many more than D.
//!
//! **Change detection** (`merge_strategy change_detection`) feeds the watch one value per
//! trial, as `lwpr` does ([`TrialMiss`](crate::learn::change)): the trial's summed miss
//! relative to its summed move, by the model that drove the trial. An alarm makes the
//! current answer the prior's mean and sets the precision back to the prior's: every
//! pattern before it stops counting as evidence, so the patterns after it correct the old
//! mapping at the rate a fresh learner learns, from the old mapping instead of from zero.
//! Starting from zero was rejected for the same reason as in `lwpr`: a turned camera or a
//! longer link leaves the mapping close to the old one, which is a better prior than none.
//! The patterns between the estimated change and the alarm are forgotten with the rest
//! (A does not keep them apart).

mod cholesky;
mod features;
mod learner;
mod posterior;
mod settings;

pub use learner::Issgp;
pub use settings::IssgpSettings;
pub(crate) use settings::ISSGP_FACTS;

#[cfg(test)]
mod tests;
