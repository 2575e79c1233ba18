//! The rule a config entry's value must meet on its own (its sane range), declared beside
//! the entry; the rules between entries are in `validate.rs`.

use std::fmt;

/// What a number given to an entry must be. Rules apply to the numeric entries; every
/// other kind is checked as it is parsed (`Any`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Rule {
    /// Any value of the entry's kind.
    Any,
    /// `low ≤ value ≤ high`.
    Within(f64, f64),
    /// `0 < value ≤ high`.
    PositiveUpTo(f64),
    /// `value > 0`.
    Positive,
    /// `value ≥ 0`.
    NonNegative,
    /// `value ≥ low`.
    AtLeast(f64),
    /// `0 < value < 1`.
    OpenUnit,
    /// `0 ≤ value < 1`.
    UnitBelowOne,
}

impl Rule {
    /// Whether `value` meets the rule.
    pub fn holds(self, value: f64) -> bool {
        match self {
            Rule::Any => true,
            Rule::Within(low, high) => (low..=high).contains(&value),
            Rule::PositiveUpTo(high) => value > 0.0 && value <= high,
            Rule::Positive => value > 0.0,
            Rule::NonNegative => value >= 0.0,
            Rule::AtLeast(low) => value >= low,
            Rule::OpenUnit => value > 0.0 && value < 1.0,
            Rule::UnitBelowOne => (0.0..1.0).contains(&value),
        }
    }

    /// The rule in words for an entry measured in `unit` ("must be 1 to 12 cm"); `None` for
    /// [`Rule::Any`].
    pub fn text(self, unit: &str) -> Option<String> {
        let unit = Unit(unit);
        Some(match self {
            Rule::Any => return None,
            Rule::Within(low, high) => format!("must be {low} to {high}{unit}"),
            Rule::PositiveUpTo(high) => format!("must be above 0 and at most {high}{unit}"),
            Rule::Positive => "must be above 0".to_string(),
            Rule::NonNegative => "must not be negative".to_string(),
            Rule::AtLeast(low) => format!("must be at least {low}{unit}"),
            Rule::OpenUnit => "must be above 0 and below 1".to_string(),
            Rule::UnitBelowOne => "must be at least 0 and below 1".to_string(),
        })
    }
}

/// A unit written after a number: `°` close to it, any other after a space.
struct Unit<'a>(&'a str);

impl fmt::Display for Unit<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.0 {
            "" => Ok(()),
            "°" => f.write_str("°"),
            unit => write!(f, " {unit}"),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rules_hold_at_their_edges_and_say_so() {
        assert!(Rule::Within(1.0, 12.0).holds(12.0));
        assert!(!Rule::Within(1.0, 12.0).holds(0.0));
        assert!(!Rule::PositiveUpTo(10.0).holds(0.0));
        assert!(Rule::PositiveUpTo(10.0).holds(10.0));
        assert!(!Rule::OpenUnit.holds(1.0));
        assert!(Rule::UnitBelowOne.holds(0.0));
        assert!(!Rule::AtLeast(1.0).holds(0.5));
        assert_eq!(
            Rule::Within(1e-5, 0.1).text("s").as_deref(),
            Some("must be 0.00001 to 0.1 s")
        );
        assert_eq!(
            Rule::Within(0.0, 10.0).text("°").as_deref(),
            Some("must be 0 to 10°")
        );
        assert_eq!(Rule::Any.text("cm"), None);
    }
}
