//! The config file (the study's appendix A.2 format): `name value` lines, `#` comments and
//! blank lines, in any order. Every entry must be given exactly once, but for the repeated
//! ones (`obstacle`), given any number of times; an unknown name, a
//! name given twice, a missing name, a value of the wrong kind (a real number for an
//! integer), a value out of its sane range or against another entry, or one that would
//! need more memory than the machine has stops with `file:line: reason`.

use std::fmt;
use std::path::Path;

/// The shipped default config (`configs/lin5.conf`), built into the binary.
const DEFAULT_CONFIG: &str = include_str!("../../../configs/lin5.conf");
/// The name the built-in default config is reported under.
pub const DEFAULT_CONFIG_NAME: &str = "configs/lin5.conf";

#[macro_use]
mod entries_macro;
mod entries;
mod error;
mod memory;
mod validate;

use entries::Entries;
pub use entries::{Config, ENTRY_NAMES, REPEATED_ENTRY_NAMES};
pub(crate) use error::shown;
pub use error::{ConfigError, ConfigErrorKind, ValueError};

impl ConfigErrorKind {
    /// The entry the error is about, if it is about one.
    pub fn entry(&self) -> Option<&str> {
        match self {
            ConfigErrorKind::Repeated { name, .. }
            | ConfigErrorKind::BadValue { name, .. }
            | ConfigErrorKind::OutOfRange { name, .. }
            | ConfigErrorKind::TooMuchMemory { name, .. } => Some(name),
            ConfigErrorKind::UnknownEntry { name }
            | ConfigErrorKind::EventAfterLastTrial { name, .. } => Some(name),
            _ => None,
        }
    }
}

impl Config {
    /// Reads and checks a config file.
    pub fn from_file(path: &Path) -> Result<Config, ConfigError> {
        let name = path.display().to_string();
        let text = std::fs::read_to_string(path).map_err(|e| ConfigError {
            file: name.clone(),
            line: None,
            kind: ConfigErrorKind::Unreadable {
                reason: e.to_string(),
            },
        })?;
        Config::parse(&text, &name)
    }

    /// Parses config text (a leading UTF-8 byte-order mark is skipped) and checks the
    /// whole config; `file` names it in errors.
    pub fn parse(text: &str, file: &str) -> Result<Config, ConfigError> {
        let error = |line, kind| ConfigError {
            file: file.to_string(),
            line: Some(line),
            kind,
        };
        let text = text.strip_prefix('\u{feff}').unwrap_or(text);
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
                let found = content.to_string();
                return Err(error(line, ConfigErrorKind::NotNameValue { found }));
            };
            entries
                .put(name, value, line)
                .map_err(|kind| error(line, kind))?;
        }
        let names = entries.missing();
        if !names.is_empty() {
            return Err(error(last_line.max(1), ConfigErrorKind::Missing { names }));
        }
        let lines: Vec<(&str, Option<usize>)> = ENTRY_NAMES
            .iter()
            .map(|n| (*n, entries.line_of(n)))
            .collect();
        let mut config = entries.complete().expect("no entry is missing");
        if let Some(folder) = Path::new(file).parent() {
            config.package_paths.relative_to(folder);
        }
        config.check().map_err(|kind| {
            let line = kind
                .entry()
                .and_then(|entry| lines.iter().find(|(n, _)| *n == entry))
                .and_then(|(_, line)| *line);
            ConfigError {
                file: file.to_string(),
                line,
                kind,
            }
        })?;
        Ok(config)
    }

    /// Sets one entry from its text, as a config line would, and checks the whole config.
    /// To set several entries that depend on each other, [`assign`](Config::assign) each and
    /// [`check`](Config::check) once.
    pub fn set(&mut self, name: &str, raw: &str) -> Result<(), ConfigErrorKind> {
        self.assign(name, raw)?;
        self.check()
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
