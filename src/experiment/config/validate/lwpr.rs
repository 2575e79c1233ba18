//! The sane ranges of the `lwpr` entries.

use super::{positive_up_to, rule, within, Check};
use crate::experiment::Config;

impl Config {
    pub(super) fn check_lwpr(&self) -> Check {
        positive_up_to(
            "init_D",
            self.init_D,
            1e6,
            " (per squared normalised input)",
        )?;
        positive_up_to("init_alpha", self.init_alpha, 1e6, "")?;
        open_unit("w_gen", self.w_gen)?;
        rule(
            self.w_prune > self.w_gen && self.w_prune <= 1.0,
            "w_prune",
            &self.w_prune,
            &format!("must be above w_gen ({}) and at most 1", self.w_gen),
        )?;
        open_unit("init_lambda", self.init_lambda)?;
        rule(
            (0.0..1.0).contains(&self.tau_lambda),
            "tau_lambda",
            &self.tau_lambda,
            "must be at least 0 and below 1",
        )?;
        open_unit("final_lambda", self.final_lambda)?;
        within("diag_only", self.diag_only, 0, 1, "")?;
        within("meta", self.meta, 0, 1, "")?;
        within("meta_rate", self.meta_rate, 0.0, 1e6, "")?;
        within("penalty", self.penalty, 0.0, 1e3, "")?;
        open_unit("add_threshold", self.add_threshold)?;
        positive_up_to("norm_out", self.norm_out, 1e4, "°")
    }
}

/// `value` strictly between 0 and 1.
fn open_unit(name: &'static str, value: f64) -> Check {
    rule(
        value > 0.0 && value < 1.0,
        name,
        &value,
        "must be above 0 and below 1",
    )
}
