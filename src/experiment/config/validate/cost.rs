//! The rule on entries that are fine alone but slow together: the work one trial's learning
//! takes in `mlp` (Adam steps × batch × the net's weights) and `ffn` (CG iterations × window
//! × the net's weights), estimated before the run and bounded.

use super::{rule, Check};
use crate::experiment::config::Config;
use crate::learn::Method;

/// The most multiply-adds one `mlp` trial's learning may take: about a second on one core.
pub(super) const MAX_MLP_TRIAL_WORK: f64 = 1e9;
/// The most multiply-adds one `ffn` trial's learning may take: about two seconds on one
/// core (its batch loss runs in vector instructions).
pub(super) const MAX_FFN_TRIAL_WORK: f64 = 1e10;

/// Multiply-adds of a pass forward and back through a net of `weights` for one pattern.
const PASSES: f64 = 3.0;
/// Loss and gradient evaluations of one CG iteration (its line search).
const EVALUATIONS_PER_ITERATION: f64 = 3.0;

impl Config {
    /// Multiply-adds of one `mlp` trial's learning: `mlp_steps_per_trial` × `mlp_batch`
    /// patterns through the 5 → H → H → 3 net and back.
    pub fn mlp_trial_work(&self) -> f64 {
        let h = self.mlp_hidden as f64;
        let weights = h * h + 10.0 * h + 3.0;
        self.mlp_steps_per_trial as f64 * self.mlp_batch as f64 * weights * PASSES
    }

    /// Multiply-adds of one `ffn` trial's learning: `ffn_cg_iterations` × the window of
    /// `ffn_window` patterns through the 5 → H → 3 net and back.
    pub fn ffn_trial_work(&self) -> f64 {
        let weights = 9.0 * self.ffn_hidden_units as f64 + 3.0;
        self.ffn_cg_iterations as f64
            * EVALUATIONS_PER_ITERATION
            * self.ffn_window as f64
            * weights
            * PASSES
    }

    pub(super) fn check_cost(&self) -> Check {
        match self.method {
            Method::Mlp => rule(
                self.mlp_trial_work() <= MAX_MLP_TRIAL_WORK,
                "mlp_steps_per_trial",
                &self.mlp_steps_per_trial,
                &format!(
                    "with mlp_batch {} and mlp_hidden {}, each trial's learning would take about {:.1e} multiply-adds, more than {MAX_MLP_TRIAL_WORK:.0e} (about a second); lower one of the three",
                    self.mlp_batch,
                    self.mlp_hidden,
                    self.mlp_trial_work()
                ),
            ),
            Method::Ffn => rule(
                self.ffn_trial_work() <= MAX_FFN_TRIAL_WORK,
                "ffn_cg_iterations",
                &self.ffn_cg_iterations,
                &format!(
                    "with ffn_window {} and ffn_hidden_units {}, each trial's learning would take about {:.1e} multiply-adds, more than {MAX_FFN_TRIAL_WORK:.0e} (about two seconds); lower one of the three",
                    self.ffn_window,
                    self.ffn_hidden_units,
                    self.ffn_trial_work()
                ),
            ),
            _ => Ok(()),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::experiment::ConfigErrorKind;

    #[test]
    fn slow_products_are_refused_and_the_defaults_pass() {
        let mut config = Config::default_config();
        config.method = Method::Mlp;
        assert_eq!(config.check_cost(), Ok(()));
        config.mlp_steps_per_trial = 10_000;
        config.mlp_hidden = 1000;
        config.mlp_batch = 100_000;
        let Err(ConfigErrorKind::OutOfRange { name, rule, .. }) = config.check_cost() else {
            panic!("refused");
        };
        assert_eq!(name, "mlp_steps_per_trial");
        assert!(rule.contains("about 3.0e15 multiply-adds"), "{rule}");
        config.method = Method::Ffn;
        assert_eq!(config.check_cost(), Ok(()));
        config.ffn_cg_iterations = 1000;
        config.ffn_hidden_units = 1000;
        assert!(config.check_cost().is_err());
    }
}
