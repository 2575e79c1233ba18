//! The config file (the study's appendix A.2 format): `name value` lines, `#` comments and
//! blank lines, in any order. Every entry must be given exactly once; an unknown name, a
//! name given twice, a missing name, a value of the wrong kind (a real number for an
//! integer) or a value out of range stops with `file:line: reason`.

use super::config_values::{CameraKind, ConfigValue, MergeStrategy, SimKind};
use crate::learn::Method;
use crate::robot::{DynamicSettings, MoveSettings};
use std::fmt;
use std::path::Path;

/// The shipped default config (`configs/lin5.conf`), built into the binary.
const DEFAULT_CONFIG: &str = include_str!("../../configs/lin5.conf");
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

macro_rules! config_entries {
    ($( $(#[doc = $doc:literal])* $name:ident : $ty:ty, )*) => {
        /// Every setting of a run. Field names are the config entries' names; lengths are in
        /// cm, angles in degrees, distances to the target in cm as in the study.
        #[derive(Debug, Clone, PartialEq)]
        pub struct Config {
            $( $(#[doc = $doc])* pub $name: $ty, )*
        }

        /// Every entry name, in the order `Config` declares them.
        pub const ENTRY_NAMES: &[&str] = &[$(stringify!($name)),*];

        /// Entries read so far, with the line each came from.
        #[derive(Debug, Default)]
        struct Entries {
            $( $name: Option<($ty, usize)>, )*
        }

        impl Entries {
            /// Stores `raw` under `name`; the error says why it can't be.
            fn put(&mut self, name: &str, raw: &str, line: usize) -> Result<(), String> {
                match name {
                    $(stringify!($name) => {
                        if let Some((_, first)) = self.$name {
                            return Err(format!("`{name}` is given twice (first on line {first})"));
                        }
                        let value = <$ty as ConfigValue>::parse_value(raw)
                            .map_err(|e| format!("{name}: {e}"))?;
                        self.$name = Some((value, line));
                        Ok(())
                    })*
                    _ => Err(format!("unknown entry `{name}`")),
                }
            }

            fn missing(&self) -> Vec<&'static str> {
                let mut missing = Vec::new();
                $( if self.$name.is_none() { missing.push(stringify!($name)); } )*
                missing
            }

            fn line_of(&self, name: &str) -> Option<usize> {
                match name {
                    $(stringify!($name) => self.$name.as_ref().map(|(_, l)| *l),)*
                    _ => None,
                }
            }

            /// The config, once nothing is missing.
            fn complete(self) -> Option<Config> {
                Some(Config { $( $name: self.$name?.0, )* })
            }
        }

        impl Config {
            /// Sets one entry from its text, as a config line or a command-line override would.
            pub fn set(&mut self, name: &str, raw: &str) -> Result<(), String> {
                match name {
                    $(stringify!($name) => {
                        self.$name = <$ty as ConfigValue>::parse_value(raw)
                            .map_err(|e| format!("{name}: {e}"))?;
                    })*
                    _ => return Err(format!("unknown entry `{name}`")),
                }
                self.validate().map_err(|(_, reason)| reason)
            }

            /// Every entry with its value as a config file would write it.
            pub fn entries(&self) -> Vec<(&'static str, String)> {
                vec![$( (stringify!($name), self.$name.render()), )*]
            }
        }
    };
}

config_entries! {
    /// The learning method.
    method: Method,
    /// The simulator: kinematic or dynamic.
    sim: SimKind,
    /// The camera model: projection or raycast.
    camera: CameraKind,
    /// Seed of the run's random generator.
    seed: u64,
    /// Trials to run.
    trials: usize,
    /// Input boundary 0 (θ2, degrees), low end.
    boundary_0_low: f64,
    /// Input boundary 0 (θ2, degrees), high end.
    boundary_0_high: f64,
    /// Input boundary 1 (θ3, degrees), low end.
    boundary_1_low: f64,
    /// Input boundary 1 (θ3, degrees), high end.
    boundary_1_high: f64,
    /// Input boundary 2 (cx, pixels), low end.
    boundary_2_low: f64,
    /// Input boundary 2 (cx, pixels), high end.
    boundary_2_high: f64,
    /// Input boundary 3 (cy, pixels), low end.
    boundary_3_low: f64,
    /// Input boundary 3 (cy, pixels), high end.
    boundary_3_high: f64,
    /// Input boundary 4 (cz), low end.
    boundary_4_low: f64,
    /// Input boundary 4 (cz), high end.
    boundary_4_high: f64,
    /// Input boundary 5 (dx, pixels, lin8), low end.
    boundary_5_low: f64,
    /// Input boundary 5 (dx, pixels, lin8), high end.
    boundary_5_high: f64,
    /// Input boundary 6 (dy, pixels, lin8), low end.
    boundary_6_low: f64,
    /// Input boundary 6 (dy, pixels, lin8), high end.
    boundary_6_high: f64,
    /// Input boundary 7 (dz, lin8), low end.
    boundary_7_low: f64,
    /// Input boundary 7 (dz, lin8), high end.
    boundary_7_high: f64,
    /// ε: a trial stops once the camera is this close to the target (cm).
    min_target_distance: f64,
    /// Kept from the study's config, whose author did not know its use; unused.
    split_extension: f64,
    /// Relative merge error.
    merge_error: f64,
    /// Split error.
    split_error: f64,
    /// At most this many feedback steps per trial.
    feedback_steps: usize,
    /// At least this many feedback steps per trial before ε can stop it.
    min_feedback_steps: usize,
    /// Maximum depth of the tree.
    tree_depth: usize,
    /// Trial before which the camera is turned (0: never).
    rotate_trial: usize,
    /// Degrees the camera turns about its optical axis at `rotate_trial`.
    rotate_degrees: f64,
    /// Trial before which a link is stretched (0: never).
    elongate_trial: usize,
    /// The link stretched at `elongate_trial` (1, 2 or 3).
    elongate_link: usize,
    /// Signed length added to that link (cm).
    elongate_cm: f64,
    /// Staggered perceptrons (sum-sets) per node.
    nr_of_matrices: usize,
    /// Patterns a sum-set holds before it is cleared.
    max_pats_in_mat: usize,
    /// Patterns a sub-box needs before it can be split off.
    min_pats_for_split: usize,
    /// A pose pair is a learning pattern only if some joint moved at least this (degrees).
    minimal_joint_move: f64,
    /// Patterns averaged by the per-level error monitor.
    monitor_ave: usize,
    /// How changes of the mapping are handled: thesis or change_detection.
    merge_strategy: MergeStrategy,
    /// change_detection: rise of the log pattern error above its baseline that counts.
    change_drift: f64,
    /// change_detection: alarm level of the CUSUM statistic (log units).
    change_threshold: f64,
    /// change_detection: patterns the error baseline averages over.
    change_baseline: usize,
    /// change_detection: patterns watched before the first alarm can come.
    change_warmup: usize,
    /// Absolute merge threshold of a node's running error.
    am_error_tresh: f64,
    /// Patterns averaged for the absolute merge.
    am_error_iters: usize,
    /// lin8: shrink factor of the d boundaries per depth.
    error_area_shrink: f64,
    /// 0: store patterns in the run's `pat_file`; anything else: in memory.
    use_pat_file: i64,
    /// The tree's per-level figures are recorded every this many trials.
    depth_info: usize,
    /// 1: print progress information during a run; 0: quiet.
    verbose_output: i64,
    /// Top joint speed of a move (degrees per second).
    robot_speed: f64,
    /// Joint acceleration of a move (degrees per second²).
    robot_accel: f64,
    /// Dynamic simulator: physics and servo time step (seconds).
    dt: f64,
    /// Dynamic simulator: constraint solver iterations per step.
    solver_iterations: usize,
    /// Dynamic simulator: joint servo position gain (1/s², scaled by the joint's inertia).
    motor_stiffness: f64,
    /// Dynamic simulator: joint servo velocity gain (1/s, scaled by the joint's inertia).
    motor_damping: f64,
    /// Dynamic simulator: a move has settled once every joint is this close to its
    /// set-point (degrees) …
    settle_position_tol: f64,
    /// … and turns slower than this (degrees per second).
    settle_speed_tol: f64,
    /// Dynamic simulator: simulated seconds a move may take to settle before it is
    /// reported as not settled.
    settle_timeout: f64,
    /// Raycast camera: rays per image side (the 512×512 image is sampled N×N).
    raycast_resolution: usize,
    /// Known patterns trained per 100 regular patterns.
    known_pattern_perc: f64,
    /// Learning patterns each bin keeps.
    bin_size: usize,
    /// nnw: at most this many patterns re-trained per node after a trial.
    nnw_train_limit: usize,
    /// nnw: a node is re-trained once it got this many new patterns.
    nnw_train_delay: usize,
    /// nnw: initial weights are drawn in ±wrange.
    wrange: f64,
    /// nnw: hidden units per network.
    hidden_units: usize,
    /// ffn: hidden units of the single network.
    ffn_hidden_units: usize,
    /// ffn: most recent patterns the network is trained on.
    ffn_window: usize,
    /// ffn: conjugate-gradient iterations after each trial.
    ffn_cg_iterations: usize,
    /// kohonen: neurons per side of the 5-D lattice.
    kohonen_side: usize,
    /// kohonen: patterns over which neighbourhood and rates shrink.
    kohonen_anneal_patterns: usize,
}

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

    /// The dynamic simulator's settings (SI units) from `robot_speed`, `robot_accel`, `dt`,
    /// `solver_iterations`, the motor gains and the settling entries.
    pub fn dynamic_settings(&self) -> DynamicSettings {
        DynamicSettings {
            moves: MoveSettings::from_degrees(self.robot_speed, self.robot_accel),
            dt: self.dt,
            solver_iterations: self.solver_iterations,
            motor_stiffness: self.motor_stiffness,
            motor_damping: self.motor_damping,
            settle_position_tol: self.settle_position_tol.to_radians(),
            settle_speed_tol: self.settle_speed_tol.to_radians(),
            settle_timeout: self.settle_timeout,
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

    /// Checks the values against each other; the error names the offending entry.
    fn validate(&self) -> Result<(), (&'static str, String)> {
        fn check(ok: bool, name: &'static str, why: &str) -> Result<(), (&'static str, String)> {
            if ok {
                Ok(())
            } else {
                Err((name, format!("{name}: {why}")))
            }
        }
        const HIGH_NAMES: [&str; 8] = [
            "boundary_0_high",
            "boundary_1_high",
            "boundary_2_high",
            "boundary_3_high",
            "boundary_4_high",
            "boundary_5_high",
            "boundary_6_high",
            "boundary_7_high",
        ];
        for (i, name) in HIGH_NAMES.into_iter().enumerate() {
            let (low, high) = self.boundary(i);
            check(
                low < high,
                name,
                &format!("must be above boundary_{i}_low ({low})"),
            )?;
        }
        check(self.trials >= 1, "trials", "must be at least 1")?;
        check(
            self.min_target_distance > 0.0,
            "min_target_distance",
            "must be positive",
        )?;
        check(
            self.feedback_steps >= 1,
            "feedback_steps",
            "must be at least 1",
        )?;
        check(
            self.min_feedback_steps <= self.feedback_steps,
            "min_feedback_steps",
            &format!("must not exceed feedback_steps ({})", self.feedback_steps),
        )?;
        check(
            (1..=12).contains(&self.tree_depth),
            "tree_depth",
            "must be 1 to 12",
        )?;
        check(
            self.nr_of_matrices >= 1,
            "nr_of_matrices",
            "must be at least 1",
        )?;
        check(
            self.max_pats_in_mat >= self.nr_of_matrices,
            "max_pats_in_mat",
            "must be at least nr_of_matrices",
        )?;
        check(self.bin_size >= 1, "bin_size", "must be at least 1")?;
        check(
            self.minimal_joint_move >= 0.0,
            "minimal_joint_move",
            "must not be negative",
        )?;
        check(self.monitor_ave >= 1, "monitor_ave", "must be at least 1")?;
        check(
            self.am_error_iters >= 1,
            "am_error_iters",
            "must be at least 1",
        )?;
        check(self.depth_info >= 1, "depth_info", "must be at least 1")?;
        check(self.robot_speed > 0.0, "robot_speed", "must be positive")?;
        check(self.robot_accel > 0.0, "robot_accel", "must be positive")?;
        check(
            self.dt > 0.0 && self.dt <= 0.1,
            "dt",
            "must be in (0, 0.1] seconds",
        )?;
        check(
            (1..=100).contains(&self.solver_iterations),
            "solver_iterations",
            "must be 1 to 100",
        )?;
        check(
            self.motor_stiffness > 0.0,
            "motor_stiffness",
            "must be positive",
        )?;
        check(
            self.motor_damping > 0.0,
            "motor_damping",
            "must be positive",
        )?;
        check(
            self.settle_position_tol > 0.0,
            "settle_position_tol",
            "must be positive",
        )?;
        check(
            self.settle_speed_tol > 0.0,
            "settle_speed_tol",
            "must be positive",
        )?;
        check(
            self.settle_timeout >= self.dt,
            "settle_timeout",
            "must be at least one time step (dt)",
        )?;
        check(
            (16..=4096).contains(&self.raycast_resolution),
            "raycast_resolution",
            "must be 16 to 4096",
        )?;
        check(
            (0.0..=1000.0).contains(&self.known_pattern_perc),
            "known_pattern_perc",
            "must be 0 to 1000",
        )?;
        check(
            self.error_area_shrink > 0.0 && self.error_area_shrink <= 1.0,
            "error_area_shrink",
            "must be in (0, 1]",
        )?;
        check(
            self.elongate_trial == 0 || (1..=3).contains(&self.elongate_link),
            "elongate_link",
            "must be 1, 2 or 3",
        )?;
        check(self.hidden_units >= 1, "hidden_units", "must be at least 1")?;
        check(
            self.change_drift >= 0.0,
            "change_drift",
            "must not be negative",
        )?;
        check(
            self.change_threshold > 0.0,
            "change_threshold",
            "must be positive",
        )?;
        check(
            self.change_baseline >= 1,
            "change_baseline",
            "must be at least 1",
        )?;
        check(
            self.ffn_hidden_units >= 1,
            "ffn_hidden_units",
            "must be at least 1",
        )?;
        check(self.ffn_window >= 1, "ffn_window", "must be at least 1")?;
        check(
            (2..=12).contains(&self.kohonen_side),
            "kohonen_side",
            "must be 2 to 12",
        )?;
        check(
            self.kohonen_anneal_patterns >= 1,
            "kohonen_anneal_patterns",
            "must be at least 1",
        )?;
        Ok(())
    }
}

impl fmt::Display for Config {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.to_text())
    }
}
