//! Config errors as data: where (file, line) and what (a kind with the names and numbers a
//! test or a user needs), so callers match on kinds, not on message text.

use std::fmt;

/// Characters of a value or a line shown in a message before it is cut short.
pub(crate) const SHOWN_CHARS: usize = 60;

/// A config error: the file, the line it is on (none for an unreadable file) and its kind.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub struct ConfigError {
    /// The config file as the user named it.
    pub file: String,
    /// The 1-based line the error is on; `None` when the error is not at a line (the file
    /// cannot be read).
    pub line: Option<usize>,
    /// What is wrong.
    pub kind: ConfigErrorKind,
}

impl fmt::Display for ConfigError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.line {
            Some(line) => write!(f, "{}:{line}: {}", self.file, self.kind),
            None => write!(f, "{}: {}", self.file, self.kind),
        }
    }
}

/// What is wrong with a config file or a config value.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum ConfigErrorKind {
    /// The file cannot be read (missing, a folder, no permission, not UTF-8).
    #[error("cannot read: {reason}")]
    Unreadable {
        /// The operating system's reason.
        reason: String,
    },
    /// A line that is not `name value`.
    #[error("expected `name value`, found `{}`", shown(.found))]
    NotNameValue {
        /// The line's content (without its comment).
        found: String,
    },
    /// A name that is no config entry.
    #[error("unknown entry `{}`", shown(.name))]
    UnknownEntry {
        /// The name given.
        name: String,
    },
    /// An entry given a second time.
    #[error("`{name}` is given twice (first on line {first_line})")]
    Repeated {
        /// The entry.
        name: &'static str,
        /// The line it was first given on.
        first_line: usize,
    },
    /// A value that is not of the entry's kind.
    #[error("{name}: {problem}")]
    BadValue {
        /// The entry.
        name: &'static str,
        /// Why the text is not a value of it.
        problem: ValueError,
    },
    /// A value outside the entry's sane range, or against another entry's value.
    #[error("{name}: {rule} (is {})", shown(.value))]
    OutOfRange {
        /// The entry.
        name: &'static str,
        /// Its value, as a config file would write it.
        value: String,
        /// The rule it breaks, naming any other entry involved.
        rule: String,
    },
    /// A value that would make the run allocate more memory than the machine has.
    #[error(
        "{name} {value} would need {} of memory ({per_unit} bytes each), more than this machine's {}",
        gigabytes(*.needed_bytes),
        gigabytes(*.available_bytes)
    )]
    TooMuchMemory {
        /// The entry.
        name: &'static str,
        /// Its value.
        value: u64,
        /// What one unit of the value costs (bytes): a feedback step, a hidden unit, …
        per_unit: u64,
        /// The estimated need (bytes).
        needed_bytes: f64,
        /// The machine's physical memory (bytes).
        available_bytes: f64,
    },
    /// An event set for a trial the run never reaches.
    #[error(
        "{name}: trial {trial} is after the last trial ({trials}): the event would never happen"
    )]
    EventAfterLastTrial {
        /// The entry or event.
        name: String,
        /// The event's trial.
        trial: usize,
        /// The run's trials.
        trials: usize,
    },
}

/// Why a text is not a value of an entry's kind.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum ValueError {
    /// Not an integer at all.
    #[error("`{}` is not an integer", shown(.0))]
    NotInteger(String),
    /// A real number where an integer is needed.
    #[error("`{}` is a real number, but this entry takes an integer", shown(.0))]
    RealForInteger(String),
    /// An integer the entry's type cannot hold (a negative count, too many digits).
    #[error("`{}` {}", shown(.text), match (.text.starts_with('-'), .min) {
        (true, 0) => "is negative: this entry takes a count (0 or more)".to_string(),
        _ => format!("is not an integer in this entry's range ({min} to {max})"),
    })]
    IntegerOutOfRange {
        /// The text given.
        text: String,
        /// The least value the entry can hold.
        min: i64,
        /// The largest value the entry can hold.
        max: u64,
    },
    /// Not a finite real number (text, NaN or infinite).
    #[error("`{}` is not a finite real number", shown(.0))]
    NotFiniteReal(String),
    /// Not one of the entry's names (method, simulator, …); the message lists them.
    #[error("{0}")]
    UnknownChoice(String),
    /// Not an obstacle box `x,y,z,sx,sy,sz` (cm) with sides above zero.
    #[error("`{}` is not a box x,y,z,sx,sy,sz (cm): {reason}", shown(.text))]
    NotObstacle {
        /// The text given.
        text: String,
        /// What is wrong with it.
        reason: String,
    },
    /// Not the comma-separated list the entry takes; `expected` says what it takes.
    #[error("`{}` is not {expected}", shown(.text))]
    BadList {
        /// The text given.
        text: String,
        /// What the entry takes.
        expected: &'static str,
    },
}

/// `text` with its control characters (a NUL byte, a tab) escaped as `\u{0}`, `\t`, cut to
/// its first characters when it is long, saying how long it was.
pub(crate) fn shown(text: &str) -> String {
    let mut visible = String::with_capacity(text.len());
    for c in text.chars() {
        if c.is_control() {
            visible.extend(c.escape_default());
        } else {
            visible.push(c);
        }
    }
    match visible.char_indices().nth(SHOWN_CHARS) {
        None => visible,
        Some((cut, _)) => format!("{}… ({} characters)", &visible[..cut], text.chars().count()),
    }
}

/// Bytes as GB (10⁹) with a precision that suits the figure.
pub(crate) fn gigabytes(bytes: f64) -> String {
    let gb = bytes / 1e9;
    if gb >= 10.0 {
        format!("{gb:.0} GB")
    } else {
        format!("{gb:.1} GB")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn long_values_are_cut_short_with_their_length() {
        let long = "9".repeat(100_000);
        let text = ValueError::NotInteger(long).to_string();
        assert!(text.len() < 120, "{text}");
        assert!(text.contains("(100000 characters)"), "{text}");
        assert_eq!(shown("1\u{0}2\t"), "1\\u{0}2\\t");
        assert_eq!(shown("short"), "short");
    }

    #[test]
    fn an_unreadable_file_has_no_line() {
        let err = ConfigError {
            file: "x.conf".into(),
            line: None,
            kind: ConfigErrorKind::Unreadable {
                reason: "No such file".into(),
            },
        };
        assert_eq!(err.to_string(), "x.conf: cannot read: No such file");
        assert_eq!(gigabytes(48e9), "48 GB");
        assert_eq!(gigabytes(1.25e9), "1.2 GB");
    }
}
