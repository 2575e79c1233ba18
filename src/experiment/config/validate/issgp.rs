//! The rule on the `issgp` length scales, a list of five.

use super::{rule, Check};
use crate::experiment::config::Config;

/// The largest length scale, in boundary ranges (beyond it the kernel is flat).
const MAX_LENGTH_SCALE: f64 = 100.0;

impl Config {
    pub(super) fn check_issgp(&self) -> Check {
        rule(
            self.issgp_length_scales
                .iter()
                .all(|&l| l > 0.0 && l <= MAX_LENGTH_SCALE),
            "issgp_length_scales",
            &self.issgp_length_scales,
            &format!("must each be above 0 and at most {MAX_LENGTH_SCALE}"),
        )
    }
}
