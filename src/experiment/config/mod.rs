//! The config file (the study's appendix A.2 format): `name value` lines, `#` comments and
//! blank lines, in any order. A file carries only what it changes: an entry it does not
//! give keeps its declared default (`entries.rs`), or its method's own
//! (`method_defaults.rs`). An unknown name, a name given twice (but
//! the repeated `obstacle`), a value of the wrong kind (a real number for an integer), a
//! value out of its sane range or against another entry, or one that would need more
//! memory than the machine has stops with `file:line: reason`.

#[macro_use]
mod entries_macro;
mod declaration;
mod defaults_text;
mod entries;
mod error;
mod memory_estimate;
mod method_defaults;
mod package_paths;
mod rule;
mod scope;
mod source;
mod urdf_file;
mod validate;
mod values;

pub use declaration::{unused_entries, Declaration};
pub use defaults_text::{defaults_text, docs_table};
pub use entries::{declarations, Config, ENTRY_NAMES, REPEATED_ENTRY_NAMES};
pub(crate) use error::{shown, SHOWN_CHARS};
pub use error::{ConfigError, ConfigErrorKind, ValueError};
use method_defaults::method_default;
pub use package_paths::PackagePaths;
pub use rule::Rule;
pub use scope::Scope;
pub use source::{Source, Sources};
pub use urdf_file::UrdfFile;
pub use values::{CameraKind, CameraMount, ObstacleBox, ReachSetting, SimKind};

use std::fmt;
use std::path::Path;

/// The name a config made of the declared defaults alone is reported under.
pub const DEFAULT_CONFIG_NAME: &str = "defaults";

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

/// The declared name `name` is, if it is an entry's.
pub(crate) fn entry_name(name: &str) -> Option<&'static str> {
    ENTRY_NAMES
        .iter()
        .chain(REPEATED_ENTRY_NAMES)
        .copied()
        .find(|n| *n == name)
}

impl Config {
    /// Reads and checks a config file.
    pub fn from_file(path: &Path) -> Result<Config, ConfigError> {
        Config::read_file(path).map(|(config, _)| config)
    }

    /// Reads and checks a config file (a regular file of at most
    /// [`MAX_CONFIG_BYTES`](crate::files::MAX_CONFIG_BYTES)), with where each value
    /// came from.
    pub fn read_file(path: &Path) -> Result<(Config, Sources), ConfigError> {
        let name = path.display().to_string();
        let unreadable = |reason: String| ConfigError {
            file: name.clone(),
            line: None,
            kind: ConfigErrorKind::Unreadable { reason },
        };
        let text = crate::files::read_text(path, crate::files::MAX_CONFIG_BYTES)
            .map_err(|e| unreadable(e.to_string()))?;
        Config::read(&text, &name)
    }

    /// Parses config text (a leading UTF-8 byte-order mark is skipped) and checks the
    /// whole config; `file` names it in errors.
    pub fn parse(text: &str, file: &str) -> Result<Config, ConfigError> {
        Config::read(text, file).map(|(config, _)| config)
    }

    /// [`parse`](Config::parse), with where each value came from: a line of `file`, or
    /// (not recorded) the default of the method or the entry.
    pub fn read(text: &str, file: &str) -> Result<(Config, Sources), ConfigError> {
        let error = |line, kind| ConfigError {
            file: file.to_string(),
            line: Some(line),
            kind,
        };
        let text = text.strip_prefix('\u{feff}').unwrap_or(text);
        let mut config = Config::defaults();
        let mut sources = Sources::default();
        for (index, raw_line) in text.lines().enumerate() {
            let line = index + 1;
            let content = raw_line.split('#').next().unwrap_or("").trim();
            if content.is_empty() {
                continue;
            }
            let mut words = content.split_whitespace();
            let (Some(name), Some(value), None) = (words.next(), words.next(), words.next()) else {
                let found = content.to_string();
                return Err(error(line, ConfigErrorKind::NotNameValue { found }));
            };
            let name = entry_name(name).ok_or_else(|| {
                let name = name.to_string();
                error(line, ConfigErrorKind::UnknownEntry { name })
            })?;
            if let Some(first_line) = sources.line_of(name) {
                if !REPEATED_ENTRY_NAMES.contains(&name) {
                    return Err(error(line, ConfigErrorKind::Repeated { name, first_line }));
                }
            }
            config
                .assign(name, value)
                .map_err(|kind| error(line, kind))?;
            let file = file.to_string();
            sources.record(name, Source::Line { file, line });
        }
        if let Some(folder) = Path::new(file).parent() {
            config.package_paths.relative_to(folder);
            config.urdf.relative_to(folder);
        }
        config
            .take_method_defaults(&sources)
            .map_err(|kind| ConfigError {
                file: file.to_string(),
                line: None,
                kind,
            })?;
        config.check().map_err(|kind| {
            let (line, kind) = located(kind, &sources);
            ConfigError {
                file: file.to_string(),
                line,
                kind,
            }
        })?;
        Ok((config, sources))
    }

    /// Sets one entry from its text, as a config line would, and checks the whole config.
    /// To set several entries that depend on each other, [`assign`](Config::assign) each and
    /// [`check`](Config::check) once.
    pub fn set(&mut self, name: &str, raw: &str) -> Result<(), ConfigErrorKind> {
        self.assign(name, raw)?;
        self.check()
    }

    /// The config of the declared defaults (lin5, the kinematic simulator, the OSCAR-6).
    pub fn default_config() -> Config {
        Config::defaults()
    }

    /// The config text: every entry as `name value`, one a line.
    pub fn to_text(&self) -> String {
        self.entries()
            .iter()
            .map(|(n, v)| format!("{n} {v}\n"))
            .collect()
    }

    /// The config text with where each value came from after it, as a comment (`default`,
    /// `ffn's default`, `file:line`, `--set`, a flag), and `unused` beside the entries
    /// eyehand does not implement: the `info` file's config section and `check-config
    /// --explain`.
    pub fn explained_text(&self, sources: &Sources) -> String {
        let defaults = self.method_default_entries();
        let unused = unused_entries();
        let width = self.entries().iter().map(|(n, v)| n.len() + v.len()).max();
        let width = width.unwrap_or(0) + 1;
        let mut repeated_seen = Vec::new();
        let mut text = String::new();
        for (name, value) in self.entries() {
            let source = if REPEATED_ENTRY_NAMES.contains(&name) {
                let index = repeated_seen.iter().filter(|n| **n == name).count();
                repeated_seen.push(name);
                sources.all_of(name).nth(index).cloned()
            } else {
                sources.of(name).cloned()
            };
            let source = source.unwrap_or_else(|| self.unrecorded(&defaults, name, &value));
            let pad = width - name.len() - value.len();
            let note = if unused.contains(&name) {
                ", unused"
            } else {
                ""
            };
            text += &format!("{name} {value}{:pad$}# {source}{note}\n", "");
        }
        text
    }

    /// Where the value of entry `name` came from: as `sources` recorded it, else its
    /// method's default or its own when it holds it, else the program that built the
    /// config.
    pub fn source_of(&self, name: &str, sources: &Sources) -> Source {
        sources.of(name).cloned().unwrap_or_else(|| {
            let value = self.entries().into_iter().find(|(n, _)| *n == name);
            let value = value.map(|(_, v)| v).unwrap_or_default();
            self.unrecorded(&self.method_default_entries(), name, &value)
        })
    }

    /// Every entry at the default of this config's method ([`Config::defaults_for`]), as
    /// [`entries`](Config::entries) writes them; the entries' own defaults should a method's
    /// not assign (which `tests/method_registry.rs` rules out).
    fn method_default_entries(&self) -> Vec<(&'static str, String)> {
        Config::defaults_for(self.method)
            .unwrap_or_else(|_| Config::defaults())
            .entries()
    }

    /// The source of entry `name`'s `value` when no file, `--set` or flag gave it: its
    /// method's default or its own when it equals it (`defaults`, from
    /// [`method_default_entries`](Config::method_default_entries)), else the program.
    fn unrecorded(&self, defaults: &[(&'static str, String)], name: &str, value: &str) -> Source {
        let at_default = defaults.iter().any(|(n, v)| *n == name && v == value);
        match (at_default, method_default(self.method, name)) {
            (true, Some(_)) => Source::MethodDefault(self.method),
            (true, None) => Source::Default,
            (false, _) => Source::Program,
        }
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

    /// The camera's frame rate a run uses: `camera_fps`, or, when that is 0 and
    /// `learn_during_moves` asks for frames during moves, 30 frames/s.
    pub fn camera_frame_rate(&self) -> f64 {
        if self.camera_fps == 0.0 && self.learn_during_moves == 1 {
            MOVE_FRAMES_FPS
        } else {
            self.camera_fps
        }
    }
}

/// The frame rate (frames/s) of the frames taken during moves when `learn_during_moves` is 1
/// and `camera_fps` gives none: a common camera's 30.
const MOVE_FRAMES_FPS: f64 = 30.0;

/// The line of the file to blame for `kind`: its entry's; for an entry the file does not
/// hold, broken against another entry the file holds, that entry's line, the value said to
/// be the default.
fn located(kind: ConfigErrorKind, sources: &Sources) -> (Option<usize>, ConfigErrorKind) {
    let Some(entry) = kind.entry() else {
        return (None, kind);
    };
    if let Some(line) = sources.line_of(entry) {
        return (Some(line), kind);
    }
    match kind {
        ConfigErrorKind::OutOfRange { name, value, rule } => {
            let line = rule
                .split(|c: char| !(c.is_alphanumeric() || c == '_'))
                .filter(|word| *word != name && ENTRY_NAMES.contains(word))
                .find_map(|other| sources.line_of(other));
            let value = format!("{value}, its default");
            (line, ConfigErrorKind::OutOfRange { name, value, rule })
        }
        kind => (None, kind),
    }
}

impl fmt::Display for Config {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.to_text())
    }
}
