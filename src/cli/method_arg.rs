//! The learning methods as the command line takes them: `--method` and `--methods` list
//! [`Method::ALL`] in their help, so a new method is named there without an edit.

use crate::learn::Method;
use clap::builder::PossibleValue;

impl clap::ValueEnum for Method {
    fn value_variants<'a>() -> &'a [Self] {
        &Method::ALL
    }

    fn to_possible_value(&self) -> Option<PossibleValue> {
        Some(PossibleValue::new(self.name()))
    }
}
