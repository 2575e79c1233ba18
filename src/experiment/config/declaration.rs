//! What the declaration of a config entry says about it, as data: the table behind
//! `eyehand config defaults`, docs/CONFIG.md and the check of each value on its own.

use super::values::ConfigValue;
use super::{ConfigErrorKind, Rule, Scope, ValueError};

/// One config entry's declaration.
#[derive(Debug, Clone, PartialEq)]
pub struct Declaration {
    /// The entry's name, as a config file writes it.
    pub name: &'static str,
    /// The kind of value it takes, in words ("integer", "real", "a,b,c", …).
    pub kind: &'static str,
    /// Its unit ("" for none).
    pub unit: &'static str,
    /// What it applies to.
    pub scope: Scope,
    /// One line saying what it does.
    pub doc: String,
    /// The rule its value must meet on its own.
    pub rule: Rule,
    /// Its default as a config file writes it; `None` for a repeated entry (none by
    /// default).
    pub default: Option<String>,
}

/// The entries eyehand accepts but does not implement ([`Scope::Unused`]).
pub fn unused_entries() -> Vec<&'static str> {
    super::declarations()
        .into_iter()
        .filter(|d| d.scope == Scope::Unused)
        .map(|d| d.name)
        .collect()
}

/// Doc-comment lines joined into one line.
pub(super) fn one_line(doc: &str) -> String {
    doc.split_whitespace().collect::<Vec<_>>().join(" ")
}

/// `value` of entry `name` (in `unit`) against its `rule`.
pub(super) fn meets_rule<T: ConfigValue>(
    name: &'static str,
    value: &T,
    rule: Rule,
    unit: &str,
) -> Result<(), ConfigErrorKind> {
    let Some(number) = value.number() else {
        return Ok(());
    };
    match rule.text(unit) {
        Some(text) if !rule.holds(number) => Err(ConfigErrorKind::OutOfRange {
            name,
            value: value.render(),
            rule: text,
        }),
        _ => Ok(()),
    }
}

/// Entry `name`'s text that did not parse as its kind (`problem`): a whole number its type
/// cannot hold (a negative count, too many digits) is said against the entry's own `rule`
/// (in `unit`) where it has one.
pub(super) fn bad_value(
    name: &'static str,
    problem: ValueError,
    rule: Rule,
    unit: &str,
) -> ConfigErrorKind {
    match (problem, rule.text(unit)) {
        (ValueError::IntegerOutOfRange { text, .. }, Some(rule)) => ConfigErrorKind::OutOfRange {
            name,
            value: text,
            rule,
        },
        (problem, _) => ConfigErrorKind::BadValue { name, problem },
    }
}
