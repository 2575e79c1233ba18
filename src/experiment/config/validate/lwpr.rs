//! The rule between two `lwpr` entries.

use super::{rule, Check};
use crate::experiment::config::Config;

impl Config {
    pub(super) fn check_lwpr(&self) -> Check {
        rule(
            self.w_prune > self.w_gen && self.w_prune <= 1.0,
            "w_prune",
            &self.w_prune,
            &format!("must be above w_gen ({}) and at most 1", self.w_gen),
        )
    }
}
