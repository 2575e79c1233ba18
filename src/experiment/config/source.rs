//! Where each value of a config came from: its default (the entry's, or its method's), a
//! line of a config file, a `--set` or a flag. `info` and `check-config --explain` print it beside the value.

use crate::learn::Method;
use std::fmt;

/// Where one value came from.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Source {
    /// The entry's declared default.
    Default,
    /// The config's method's own default for an entry it shares with other methods.
    MethodDefault(Method),
    /// A line of a config file.
    Line {
        /// The file as the user named it.
        file: String,
        /// The 1-based line.
        line: usize,
    },
    /// `--set NAME=VALUE` (or a sweep's setting).
    Set,
    /// A command-line flag (`--trials`, `--method`, …).
    Flag(&'static str),
    /// Code that built the config itself (a test, a Python script), not a file or flag.
    Program,
    /// Worked out from the arm, for an entry left at its default on an arm other than
    /// the shipped OSCAR-6 (`reach_space`, `boundary_0_*`, `boundary_1_*`, `standoff`,
    /// `boundary_4_*`).
    Fitted,
}

impl fmt::Display for Source {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Source::Default => f.write_str("default"),
            Source::MethodDefault(method) => write!(f, "{method}'s default"),
            Source::Line { file, line } => write!(f, "{file}:{line}"),
            Source::Set => f.write_str("--set"),
            Source::Flag(flag) => f.write_str(flag),
            Source::Program => f.write_str("set by the program"),
            Source::Fitted => f.write_str("fitted to the arm"),
        }
    }
}

/// The sources of a config's values, in the order they were given: a later one of the same
/// entry overrides an earlier one, but for a repeated entry (`obstacle`), whose values
/// each keep their own.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct Sources {
    given: Vec<(&'static str, Source)>,
}

impl Sources {
    /// Records that `name` was given by `source`.
    pub fn record(&mut self, name: &'static str, source: Source) {
        self.given.push((name, source));
    }

    /// Where the value of entry `name` came from, if it was given.
    pub fn of<'a>(&'a self, name: &'a str) -> Option<&'a Source> {
        self.all_of(name).last()
    }

    /// Where each value of entry `name` came from, in order.
    pub fn all_of<'a>(&'a self, name: &'a str) -> impl Iterator<Item = &'a Source> {
        self.given
            .iter()
            .filter(move |(n, _)| *n == name)
            .map(|(_, source)| source)
    }

    /// The line of a config file that gave `name`, if one did.
    pub fn line_of(&self, name: &str) -> Option<usize> {
        self.all_of(name).find_map(|source| match source {
            Source::Line { line, .. } => Some(*line),
            _ => None,
        })
    }
}
