//! The config file (the study's appendix A.2 format): `name value` lines, `#` comments and
//! blank lines, in any order. Every entry must be given exactly once; an unknown name, a
//! name given twice, a missing name, a value of the wrong kind (a real number for an
//! integer) or a value out of range stops with `file:line: reason`.

use std::fmt;
use std::path::Path;

/// The shipped default config (`configs/lin5.conf`), built into the binary.
const DEFAULT_CONFIG: &str = include_str!("../../../configs/lin5.conf");
/// The name the built-in default config is reported under.
pub const DEFAULT_CONFIG_NAME: &str = "configs/lin5.conf";

/// A config error at a line of a config file.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("{file}:{line}: {reason}")]
pub struct ConfigError {
    /// The config file as the user named it.
    pub file: String,
    /// The 1-based line the error is on (for a missing entry: the last line).
    pub line: usize,
    /// What is wrong.
    pub reason: String,
}

#[macro_use]
mod entries_macro;
mod entries;
mod validate;

use entries::Entries;
pub use entries::{Config, ENTRY_NAMES};

impl Config {
    /// Reads and checks a config file.
    pub fn from_file(path: &Path) -> Result<Config, ConfigError> {
        let name = path.display().to_string();
        let text = std::fs::read_to_string(path).map_err(|e| ConfigError {
            file: name.clone(),
            line: 0,
            reason: format!("cannot read: {e}"),
        })?;
        Config::parse(&text, &name)
    }

    /// Parses config text; `file` names it in errors.
    pub fn parse(text: &str, file: &str) -> Result<Config, ConfigError> {
        let error = |line, reason| ConfigError {
            file: file.to_string(),
            line,
            reason,
        };
        let mut entries = Entries::default();
        let mut last_line = 0;
        for (index, raw_line) in text.lines().enumerate() {
            let line = index + 1;
            last_line = line;
            let content = raw_line.split('#').next().unwrap_or("").trim();
            if content.is_empty() {
                continue;
            }
            let mut words = content.split_whitespace();
            let (Some(name), Some(value), None) = (words.next(), words.next(), words.next()) else {
                return Err(error(
                    line,
                    format!("expected `name value`, found `{content}`"),
                ));
            };
            entries
                .put(name, value, line)
                .map_err(|reason| error(line, reason))?;
        }
        let missing = entries.missing();
        if !missing.is_empty() {
            let reason = format!("missing entries: {}", missing.join(", "));
            return Err(error(last_line.max(1), reason));
        }
        let line_of = |name: &str| entries.line_of(name).unwrap_or(0);
        let lines: Vec<(&str, usize)> = ENTRY_NAMES.iter().map(|n| (*n, line_of(n))).collect();
        let config = entries.complete().expect("no entry is missing");
        config.validate().map_err(|(name, reason)| {
            let line = lines
                .iter()
                .find(|(n, _)| *n == name)
                .map_or(0, |(_, l)| *l);
            error(line, reason)
        })?;
        Ok(config)
    }

    /// The shipped default config (`configs/lin5.conf`).
    pub fn default_config() -> Config {
        Config::parse(DEFAULT_CONFIG, DEFAULT_CONFIG_NAME).expect("the shipped config is valid")
    }

    /// The config text: every entry as `name value`, one a line.
    pub fn to_text(&self) -> String {
        self.entries()
            .iter()
            .map(|(n, v)| format!("{n} {v}\n"))
            .collect()
    }

    /// Input boundaries (low, high) of dimension `i` (0–7).
    pub fn boundary(&self, i: usize) -> (f64, f64) {
        let all = [
            (self.boundary_0_low, self.boundary_0_high),
            (self.boundary_1_low, self.boundary_1_high),
            (self.boundary_2_low, self.boundary_2_high),
            (self.boundary_3_low, self.boundary_3_high),
            (self.boundary_4_low, self.boundary_4_high),
            (self.boundary_5_low, self.boundary_5_high),
            (self.boundary_6_low, self.boundary_6_high),
            (self.boundary_7_low, self.boundary_7_high),
        ];
        all[i]
    }
}

impl fmt::Display for Config {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.to_text())
    }
}
