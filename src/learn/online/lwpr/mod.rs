//! `lwpr`: Locally Weighted Projection Regression (Vijayakumar, D'Souza and Schaal,
//! "Incremental Online Learning in High Dimensions", Neural Computation 17(12), 2005),
//! written here from the paper as the peer learner a roboticist would pick today, and
//! computing as Klanke and Vijayakumar's reference library (v1.2.6) does: on a recorded
//! pattern stream of this task the two agree to rounding (`reference_replay`). The one
//! deliberate difference: while no trusted field covers a query, the answer comes from the
//! untrusted fields (the library answers zero, and a zero move would give a run no pattern
//! to learn from).
//!
//! It learns from the same adjusted 5-input patterns as `lin5` (see
//! [`adjusted_pattern`](crate::learn::adjusted_pattern)): (θ2, θ3, cx*, cy*, cz*) → Δθ,
//! each input normalised to [0, 1] by the configured boundaries `boundary_0` … `boundary_4`,
//! each output divided by `norm_out` degrees. A query's input is its reading and pose.
//!
//! - A receptive field is a Gaussian kernel w = exp(−½·(x − c)ᵀD(x − c)) around its centre
//!   c, with its own metric D = MᵀM ([`metric`]), adapted by one gradient step per pattern
//!   on the field's penalised leave-one-out cost.
//! - Its local model is incremental PLS ([`projection`]) on the field's weighted, mean-free
//!   data; projections are added while the last one still halves the error.
//! - A pattern trains every field it activates above 0.001; a field is made at a pattern
//!   that activates none above `w_gen`; of two fields both activated above `w_prune`, the
//!   narrower is dropped ([`output_model`]). The answer is the activation-weighted mean of
//!   the fields' answers.
//! - Forgetting: each field's λ starts at `init_lambda` and anneals towards `final_lambda`
//!   by `tau_lambda` per update. That is LWPR's own answer to a changed robot.
//!
//! **One model per output, not a shared one.** Each of Δθ1, Δθ2, Δθ3 has its own fields,
//! as in the paper's derivation (univariate PLS) and the reference library. The three
//! outputs bend differently over the inputs — Δθ1 turns with the image offsets and scales
//! with the arm's reach, Δθ2 and Δθ3 depend on the elbow's geometry through θ2 and θ3 — so
//! each gets its own field widths, projection directions and number of projections. A
//! shared model would need one metric to serve three curvatures and a multi-output PLS;
//! its price would be a third of the work per pattern.
//!
//! **Change detection** (`merge_strategy change_detection`) feeds the same per-trial watch
//! as the nested learners ([`ChangeWatch`](crate::learn::change)), but with one value per
//! trial: the log of the trial's summed miss before training relative to its summed move.
//! The nested learners give it each pattern's relative miss; LWPR's answers carry an
//! absolute error floor of a few hundredths of a degree, so the many small moves between a
//! trial's late poses miss by about their own size whatever the robot does, and their
//! values drown the rise a change causes in the large moves (a 30° camera turn raised
//! the per-pattern mean by a third of its spread and no alarm came). An alarm sets every field's λ back to `init_lambda`: the fields forget
//! fast again and the annealing starts over. Dropping the stale fields instead was
//! rejected: a turned camera or a stretched link changes the mapping everywhere, so every
//! field is stale and dropping them is learning from scratch, while the fields' layout
//! (centres and widths, which follow the inputs' distribution and the mapping's
//! curvature) is still about right after such a smooth change; only the local regressions
//! are wrong, and those are what λ discounts.

mod field;
mod learner;
mod metric;
mod output_model;
mod projection;
mod settings;

pub use learner::Lwpr;
pub use settings::LwprSettings;
pub(crate) use settings::LWPR_FACTS;

#[cfg(test)]
mod reference_replay;
#[cfg(test)]
mod tests;
