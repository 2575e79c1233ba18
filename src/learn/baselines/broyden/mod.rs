//! `broyden`: uncalibrated visual servoing, the controller an engineer would pick instead of
//! learning the eye-hand mapping. It learns no global map: it keeps one 3×3 image Jacobian
//! J ≈ ∂c/∂θ of the three learned joints (reading units per degree), estimates it online
//! from the moves it makes and steps toward c = 0 with it.
//!
//! - **The step** is a damped least-squares solve, Δθ = −(JᵀJ + μ²I)⁻¹Jᵀc, with μ² the
//!   `broyden_damping` share of JᵀJ's mean diagonal, scaled down so that no joint turns
//!   more than `broyden_max_step` degrees.
//! - **The update** after each move (Δθ, Δc) is Broyden's rank-one secant update,
//!   J ← J + α(Δc − JΔθ)Δθᵀ / ΔθᵀΔθ, as in Jägersand, Fuentes and Nelson, "Experimental
//!   evaluation of uncalibrated visual servoing for precision manipulation" (ICRA 1997),
//!   α = `broyden_rate` (`broyden_update broyden`), or the recursive least-squares
//!   estimate with forgetting λ of Hosoda and Asada, "Versatile visual servoing without
//!   knowledge of true Jacobian" (IROS 1994), in the form of Piepmeier, McMurray and
//!   Lipkin, "Uncalibrated eye-in-hand visual servoing" (IJRR 2004):
//!   J ← J + (Δc − JΔθ)ΔθᵀP / (λ + ΔθᵀPΔθ), P ← (P − PΔθΔθᵀP / (λ + ΔθᵀPΔθ)) / λ
//!   (`broyden_update rls`, λ = `broyden_forgetting`). The target stands still, so
//!   Piepmeier's term for a moving target is zero. P is kept no larger (by its trace) than
//!   after the first probes, so directions a trial never moves in do not wind it up.
//! - **The start**: before any Jacobian is known the first trial turns each joint by
//!   `broyden_probe` degrees in turn; the three moves and what they did to the reading
//!   give J = ΔC·ΔΘ⁻¹ (and P = (ΔΘΔΘᵀ)⁻¹).
//! - **Memory**: J is carried from one trial to the next; it is the method's only
//!   "learning". Each move's Δθ1 is the one proposed (a query carries no θ1), Δθ2 and
//!   Δθ3 are read from the next query; the trial's last move is taken from its path.
//!
//! A change of the robot needs no detector: the next moves' updates follow it.

mod jacobian;
mod learner;
mod settings;

pub use jacobian::ImageJacobian;
pub use learner::Broyden;
pub(crate) use settings::BROYDEN_FACTS;
pub use settings::{BroydenSettings, BroydenUpdate};
