//! A typed description of one run — what `eyehand run` parses its flags into and what a
//! comparison or sweep stores for each of its cells — and how it becomes [`RunOptions`]:
//! the config file, then every `--set`, then the flags, then the method's own defaults for
//! what none of them gave, validated once on the final config.

use crate::experiment::{
    entry_name, shown, CameraKind, Config, ConfigError, ConfigErrorKind, Event, RunOptions,
    SimKind, Source, Sources, DEFAULT_CONFIG_NAME,
};
use crate::learn::Method;
use serde::{Deserialize, Serialize};
use std::path::{Path, PathBuf};

/// One run, as asked for: every field is optional on top of the config file.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct RunRequest {
    /// The config file; `None` for the declared defaults.
    pub config: Option<PathBuf>,
    /// `NAME=VALUE` overrides of config entries, each name at most once.
    pub sets: Vec<(String, String)>,
    /// The learning method, overriding the config's `method`.
    #[serde(with = "as_text")]
    pub method: Option<Method>,
    /// The simulator, overriding the config's `sim`.
    #[serde(with = "as_text")]
    pub sim: Option<SimKind>,
    /// The camera, overriding the config's `camera`.
    #[serde(with = "as_text")]
    pub camera: Option<CameraKind>,
    /// Trials, overriding the config's `trials`.
    pub trials: Option<usize>,
    /// The seed, overriding the config's `seed`.
    pub seed: Option<u64>,
    /// The URDF; `None` for the shipped `urdf/oscar6.urdf`.
    pub urdf: Option<PathBuf>,
    /// The data folder; the run takes the first free `<data>/<method>/<id>/`.
    pub data: PathBuf,
    /// A fixed run folder (a sweep's cell) instead of a free id under `data`: emptied first.
    pub folder: Option<PathBuf>,
    /// Events on top of the config's, as `rotate:TRIAL:DEG` / `elongate:TRIAL:LINK:CM`.
    #[serde(with = "as_text")]
    pub events: Vec<Event>,
    /// Show a progress bar.
    pub progress: bool,
    /// Draw `plot.png` at the end.
    pub plot: bool,
}

impl Default for RunRequest {
    /// The default config into `data/`, no overrides, no progress bar, with a plot.
    fn default() -> RunRequest {
        RunRequest {
            config: None,
            sets: Vec::new(),
            method: None,
            sim: None,
            camera: None,
            trials: None,
            seed: None,
            urdf: None,
            data: PathBuf::from("data"),
            folder: None,
            events: Vec::new(),
            progress: false,
            plot: true,
        }
    }
}

/// Why a request cannot become a run.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum RequestError {
    /// The config file is unreadable or invalid.
    #[error(transparent)]
    Config(#[from] ConfigError),
    /// A `--set` names an entry twice.
    #[error("--set {name} is given more than once")]
    RepeatedSet {
        /// The entry.
        name: String,
    },
    /// A `--set` names no entry or gives a value of the wrong kind.
    #[error("--set {shown}: {kind}")]
    Set {
        /// The `NAME=VALUE` as given (cut short if long).
        shown: String,
        /// What is wrong.
        kind: ConfigErrorKind,
    },
    /// The config with every override applied breaks a range or a rule between entries.
    #[error("{config} with the command line's settings: {kind}")]
    Combined {
        /// The config file's name.
        config: String,
        /// What is wrong.
        kind: ConfigErrorKind,
    },
    /// A path could not be made absolute.
    #[error("{}: {reason}", .path.display())]
    Path {
        /// The path.
        path: PathBuf,
        /// Why.
        reason: String,
    },
}

impl RunRequest {
    /// The config with every `--set` and then every flag applied, checked as a whole once
    /// the last is in (so values that depend on each other may be set in any order), and
    /// the name the config is reported under.
    pub fn config(&self) -> Result<(Config, String), RequestError> {
        self.sourced_config()
            .map(|(config, name, _)| (config, name))
    }

    /// [`config`](RunRequest::config), with where each value came from.
    pub fn sourced_config(&self) -> Result<(Config, String, Sources), RequestError> {
        let (mut config, name, mut sources) = match &self.config {
            Some(path) => {
                let (config, sources) = Config::read_file(path)?;
                (config, path.display().to_string(), sources)
            }
            None => (
                Config::default_config(),
                DEFAULT_CONFIG_NAME.to_string(),
                Sources::default(),
            ),
        };
        for (i, (entry, value)) in self.sets.iter().enumerate() {
            if self.sets[..i].iter().any(|(e, _)| e == entry) {
                return Err(RequestError::RepeatedSet {
                    name: entry.clone(),
                });
            }
            config
                .assign(entry, value)
                .map_err(|kind| RequestError::Set {
                    shown: shown(&format!("{entry}={value}")),
                    kind,
                })?;
            if let Some(name) = entry_name(entry) {
                sources.record(name, Source::Set);
            }
        }
        let mut flag = |name: &'static str, flag: &'static str, given: bool| {
            if given {
                sources.record(name, Source::Flag(flag));
            }
        };
        flag("method", "--method", self.method.is_some());
        flag("sim", "--sim", self.sim.is_some());
        flag("camera", "--camera", self.camera.is_some());
        flag("seed", "--seed", self.seed.is_some());
        flag("trials", "--trials", self.trials.is_some());
        config.method = self.method.unwrap_or(config.method);
        config.sim = self.sim.unwrap_or(config.sim);
        config.camera = self.camera.unwrap_or(config.camera);
        config.seed = self.seed.unwrap_or(config.seed);
        config.trials = self.trials.unwrap_or(config.trials);
        let combined = |kind| RequestError::Combined {
            config: name.clone(),
            kind,
        };
        config.take_method_defaults(&sources).map_err(combined)?;
        config.check().map_err(combined)?;
        Ok((config, name, sources))
    }

    /// The run this request asks for.
    pub fn options(&self) -> Result<RunOptions, RequestError> {
        let (config, config_name, sources) = self.sourced_config()?;
        Ok(RunOptions {
            config_name,
            sources,
            urdf: self.urdf.clone(),
            events: self.events.clone(),
            progress: self.progress,
            plot: self.plot,
            folder: self.folder.clone(),
            ..RunOptions::new(config, self.data.clone())
        })
    }

    /// The same request with every path absolute, so it runs the same from any folder.
    pub fn with_absolute_paths(mut self) -> Result<RunRequest, RequestError> {
        self.config = self.config.as_deref().map(absolute).transpose()?;
        self.urdf = self.urdf.as_deref().map(absolute).transpose()?;
        self.data = absolute(&self.data)?;
        self.folder = self.folder.as_deref().map(absolute).transpose()?;
        Ok(self)
    }
}

/// `path` made absolute against the current folder (it need not exist).
fn absolute(path: &Path) -> Result<PathBuf, RequestError> {
    std::path::absolute(path).map_err(|e| RequestError::Path {
        path: path.to_path_buf(),
        reason: e.to_string(),
    })
}

/// Serde through `Display` / `FromStr`, for the typed fields of a request.
mod as_text {
    use serde::de::Error;
    use serde::{Deserialize, Deserializer, Serialize, Serializer};
    use std::fmt::Display;
    use std::str::FromStr;

    /// Values that are stored as their text.
    pub(in crate::experiment) trait Textual: Sized {
        fn to_texts(&self) -> Vec<String>;
        fn from_texts(texts: Vec<String>) -> Result<Self, String>;
    }

    impl<T: Display + FromStr<Err: Display>> Textual for Option<T> {
        fn to_texts(&self) -> Vec<String> {
            self.iter().map(T::to_string).collect()
        }
        fn from_texts(texts: Vec<String>) -> Result<Self, String> {
            texts
                .first()
                .map(|t| t.parse().map_err(|e: T::Err| e.to_string()))
                .transpose()
        }
    }

    impl<T: Display + FromStr<Err: Display>> Textual for Vec<T> {
        fn to_texts(&self) -> Vec<String> {
            self.iter().map(T::to_string).collect()
        }
        fn from_texts(texts: Vec<String>) -> Result<Self, String> {
            texts
                .iter()
                .map(|t| t.parse().map_err(|e: T::Err| e.to_string()))
                .collect()
        }
    }

    pub(in crate::experiment) fn serialize<V: Textual, S: Serializer>(
        value: &V,
        s: S,
    ) -> Result<S::Ok, S::Error> {
        value.to_texts().serialize(s)
    }

    pub(in crate::experiment) fn deserialize<'de, V: Textual, D: Deserializer<'de>>(
        d: D,
    ) -> Result<V, D::Error> {
        V::from_texts(Vec::<String>::deserialize(d)?).map_err(D::Error::custom)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn request(sets: &[(&str, &str)]) -> RunRequest {
        RunRequest {
            sets: sets
                .iter()
                .map(|(n, v)| (n.to_string(), v.to_string()))
                .collect(),
            ..RunRequest::default()
        }
    }

    #[test]
    fn overrides_are_checked_on_the_final_config_not_one_at_a_time() {
        // Each order passes: min_feedback_steps ≤ feedback_steps holds only at the end.
        let a = request(&[("feedback_steps", "2"), ("min_feedback_steps", "1")]);
        let b = request(&[("min_feedback_steps", "1"), ("feedback_steps", "2")]);
        let (ca, _) = a.config().unwrap();
        let (cb, _) = b.config().unwrap();
        assert_eq!(ca, cb);
        assert_eq!((ca.feedback_steps, ca.min_feedback_steps), (2, 1));
    }

    #[test]
    fn an_override_that_changes_nothing_gives_the_same_config_for_every_shipped_config() {
        let configs = Path::new(env!("CARGO_MANIFEST_DIR")).join("configs");
        let files = |folder: &Path| {
            let entries = std::fs::read_dir(folder).unwrap();
            let paths = entries.map(|entry| entry.unwrap().path());
            paths.filter(|path| path.is_file()).collect::<Vec<_>>()
        };
        let arms = files(&configs.join("arms"));
        assert_eq!(arms.len(), 2, "{arms:?}");
        for path in files(&configs).into_iter().chain(arms) {
            let base = Config::from_file(&path).unwrap();
            let same = RunRequest {
                config: Some(path.clone()),
                seed: Some(base.seed),
                ..RunRequest::default()
            };
            assert_eq!(same.config().unwrap().0, base, "{}", path.display());
        }
    }

    #[test]
    fn learning_during_moves_alone_takes_frames_at_the_stated_default_rate() {
        let (config, _) = request(&[("learn_during_moves", "1")]).config().unwrap();
        assert_eq!((config.camera_fps, config.camera_frame_rate()), (0.0, 30.0));
        let (given, _) = request(&[("learn_during_moves", "1"), ("camera_fps", "50")])
            .config()
            .unwrap();
        assert_eq!(given.camera_frame_rate(), 50.0);
    }

    #[test]
    fn a_repeated_or_unknown_set_is_refused() {
        let twice = request(&[("trials", "100"), ("trials", "200")]);
        assert_eq!(
            twice.config().unwrap_err(),
            RequestError::RepeatedSet {
                name: "trials".into()
            }
        );
        let unknown = request(&[("trails", "100")]);
        assert!(matches!(
            unknown.config().unwrap_err(),
            RequestError::Set {
                kind: ConfigErrorKind::UnknownEntry { .. },
                ..
            }
        ));
    }

    #[test]
    fn flags_win_over_sets_and_the_request_round_trips_through_json() {
        let mut r = request(&[("trials", "100")]);
        r.trials = Some(7);
        r.method = Some(Method::Ik);
        r.events = vec!["rotate:3:30".parse().unwrap()];
        let (config, _) = r.config().unwrap();
        assert_eq!((config.trials, config.method), (7, Method::Ik));
        let json = serde_json::to_string(&r).unwrap();
        assert_eq!(serde_json::from_str::<RunRequest>(&json).unwrap(), r);
    }
}
