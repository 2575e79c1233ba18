//! `mlp`: a small multilayer perceptron learned online from a replay buffer — what a
//! deep-learning user would write first for this task.
//!
//! It learns from the same adjusted 5-input patterns as `lin5` and `lwpr` (see
//! [`adjusted_pattern`](crate::learn::adjusted_pattern)): (θ2, θ3, cx*, cy*, cz*) → Δθ,
//! each input scaled onto [−1, 1] by the configured boundaries `boundary_0` …
//! `boundary_4`, each output divided by `norm_out` degrees.
//!
//! - The net ([`network`]): two layers of `mlp_hidden` tanh units and three linear
//!   outputs, the hidden layers Glorot-initialised from the run's seed, the output layer
//!   zero (the untrained net proposes no move).
//! - Every pattern of a trial goes into a buffer of the `mlp_buffer` most recent ones
//!   ([`replay`]); after the trial, `mlp_steps_per_trial` Adam steps ([`adam`], step size
//!   `mlp_rate`) each on the mean squared error of `mlp_batch` patterns drawn uniformly
//!   from the buffer. The buffer's bound is its forgetting: a pattern older than
//!   `mlp_buffer` patterns no longer trains the net.
//!
//! **Change detection** (`merge_strategy change_detection`) is the single-model learners'
//! shared watch ([`WatchedLearner`](crate::learn::change::WatchedLearner)). Under
//! `change_recovery forget` an alarm drops every buffered pattern of the trials before the
//! estimated change, so the steps that follow train on
//! the changed mapping alone; the weights and Adam's moments are kept, as the old mapping
//! is the best start the net has. Until the first pattern after the alarm there is nothing
//! to train on and the net answers as before. Under `change_recovery correct` the net's
//! weights and Adam's state at the start of each of the last 200 trials are kept
//! ([`checkpoints`]), and an alarm sets them back to those before the trial the change is
//! dated to, and drops the buffered patterns since: what the net learned of the changed
//! readings before the alarm does not stay in the net the correction carries them back to.

mod adam;
mod checkpoints;
mod learner;
mod network;
mod replay_buffer;
mod settings;

pub use learner::Mlp;
pub use settings::MlpSettings;
pub(crate) use settings::MLP_FACTS;

#[cfg(test)]
mod tests;
