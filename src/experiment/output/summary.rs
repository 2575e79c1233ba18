//! The run's `summary.json`: what ran, how fast, and the distance figures over its last
//! trials (from [`StepFigures`](crate::experiment::StepFigures)).

use crate::control::MAX_RECORDED_STEPS;
use crate::experiment::verdict::failures::FailureTally;
use crate::experiment::verdict::learning_verdict::NotLearned;
use crate::experiment::Config;
use crate::learn::{LearnerStats, Method};
use crate::robot::SpeedFault;
use serde::{Deserialize, Serialize};
use std::io;
use std::path::Path;

/// What `summary.json` holds. Field names are a public interface.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct RunSummary {
    /// The learning method.
    pub method: String,
    /// The simulator.
    pub sim: String,
    /// The camera model.
    pub camera: String,
    /// The config file the run read (`defaults` for none: every entry at its declared
    /// default but what flags and `--set` gave; absent in older summaries).
    #[serde(default)]
    pub config_file: String,
    /// The run's seed.
    pub seed: u64,
    /// Trials run.
    pub trials: usize,
    /// Wall-clock seconds of the trials (pre-learning included).
    pub wall_seconds: f64,
    /// Trials per wall-clock second.
    pub trials_per_second: f64,
    /// Peak resident memory of the process (kB).
    pub peak_rss_kb: u64,
    /// Approximators at the end.
    pub nodes: usize,
    /// Bins at the end.
    pub bins: usize,
    /// Stored patterns at the end.
    pub patterns: usize,
    /// Trials that failed (object lost or not seen, unreachable target, bad move).
    pub failures: usize,
    /// The failed trials by reason; they add up to `failures` (absent in older summaries).
    #[serde(default)]
    pub failures_by_reason: FailureTally,
    /// Physics steps the simulator took per trial (0 on the kinematic simulator).
    pub physics_steps_per_trial: f64,
    /// Simulated seconds of moves per trial, settling included.
    pub simulated_seconds_per_trial: f64,
    /// Moves, placings and link changes after which the dynamic arm had not settled in time.
    pub settle_timeouts: u64,
    /// Moves stopped by a contact: the floor, an obstacle or another link.
    pub stopped_by_contact: u64,
    /// Moves the arm made (absent in older summaries).
    #[serde(default)]
    pub moves: u64,
    /// Physics steps after which a joint of the dynamic arm turned faster than its URDF
    /// velocity limit (absent in older summaries: 0).
    #[serde(default)]
    pub speed_faults: u64,
    /// The joint furthest beyond its velocity limit in those steps (null: none was).
    #[serde(default)]
    pub worst_speed_fault: Option<SpeedFaultSummary>,
    /// Times a merge cut the learner's tree at its root, so that it started over (absent
    /// in older summaries).
    #[serde(default)]
    pub root_merges: usize,
    /// The run's events (`rotate:TRIAL:DEG`, `elongate:TRIAL:LINK:CM`), in trial order.
    pub events: Vec<String>,
    /// The obstacle boxes, each `[x, y, z, sx, sy, sz]`: centre and side lengths (cm,
    /// world frame) as the config's `obstacle` lines give them (absent in older summaries).
    #[serde(default)]
    pub obstacles: Vec<[f64; 6]>,
    /// The number of last trials the distance figures are taken over.
    pub window: usize,
    /// Mean distance (mm) after feedback steps 1..5 over the window (null: no such step).
    pub mean_distance_mm: [Option<f64>; MAX_RECORDED_STEPS],
    /// Median distance (mm) after feedback steps 1..5 over the window.
    pub median_distance_mm: [Option<f64>; MAX_RECORDED_STEPS],
    /// Mean distance (mm) after every feedback step 1..`feedback_steps` over the window,
    /// over the trials that took that step (a trial stops early once within ε).
    pub mean_distance_by_step_mm: Vec<Option<f64>>,
    /// True when SIGINT or SIGTERM stopped the run early: `trials` is then the trials it
    /// finished (absent in summaries written before the field existed: false).
    #[serde(default)]
    pub interrupted: bool,
    /// Mean distance (mm) after the last feedback step of each trial of the window.
    #[serde(default)]
    pub mean_final_distance_mm: Option<f64>,
    /// Median distance (mm) after the last feedback step of each trial of the window.
    #[serde(default)]
    pub median_final_distance_mm: Option<f64>,
    /// Trials of the window that came within ε.
    #[serde(default)]
    pub reached_epsilon: usize,
    /// Mean simulated seconds from the first frame to the frame within ε that ended the
    /// trial, over the window's trials that came within ε (null: none did).
    #[serde(default)]
    pub mean_seconds_to_epsilon: Option<f64>,
    /// The sensors: noise, the ray-cast camera's pixel noise, the camera's clock.
    #[serde(default)]
    pub sensors: SensorSummary,
    /// False when the run learned nothing: every trial failed, no trial gave the learner a
    /// pattern, or the arm stayed at its start pose in every trial of the window (absent in
    /// older summaries: true).
    #[serde(default = "learned_by_default")]
    pub learned: bool,
    /// How the run learned nothing, and the likely cause (null when it learned).
    #[serde(default)]
    pub not_learned: Option<NotLearned>,
}

/// A joint that turned faster than its URDF velocity limit, as `summary.json` names it.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct SpeedFaultSummary {
    /// 1-based joint number.
    pub joint: usize,
    /// How fast it turned (°/s, either way).
    pub speed_deg_s: f64,
    /// Its URDF velocity limit (°/s).
    pub limit_deg_s: f64,
}

impl From<SpeedFault> for SpeedFaultSummary {
    fn from(fault: SpeedFault) -> Self {
        SpeedFaultSummary {
            joint: fault.joint,
            speed_deg_s: fault.speed.to_degrees(),
            limit_deg_s: fault.limit.to_degrees(),
        }
    }
}

/// What a summary written before `learned` existed says.
fn learned_by_default() -> bool {
    true
}

/// The run's sensing entries, as `summary.json` reports them (field names are the config
/// entries').
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct SensorSummary {
    /// σ of the blob centroid (pixels).
    pub camera_noise_px: f64,
    /// σ of the blob area, relative to itself.
    pub camera_area_noise: f64,
    /// σ of each joint encoder (degrees).
    pub joint_noise_deg: f64,
    /// σ of each pixel's grey level of the ray-cast camera.
    pub raycast_noise: f64,
    /// Frames per second of a free-running camera (0: a frame as each move settles).
    pub camera_fps: f64,
    /// Age of a frame when it is delivered (ms).
    pub camera_latency_ms: f64,
    /// `step` or `continuous`.
    pub servo_mode: String,
}

impl Default for SensorSummary {
    /// The study's exact sensors (for summaries written before the field existed).
    fn default() -> Self {
        SensorSummary {
            camera_noise_px: 0.0,
            camera_area_noise: 0.0,
            joint_noise_deg: 0.0,
            raycast_noise: 0.0,
            camera_fps: 0.0,
            camera_latency_ms: 0.0,
            servo_mode: "step".into(),
        }
    }
}

impl SensorSummary {
    /// The sensing entries of `config`.
    pub fn of(config: &Config) -> SensorSummary {
        SensorSummary {
            camera_noise_px: config.camera_noise_px,
            camera_area_noise: config.camera_area_noise,
            joint_noise_deg: config.joint_noise_deg,
            raycast_noise: config.raycast_noise,
            camera_fps: config.camera_frame_rate(),
            camera_latency_ms: config.camera_latency_ms,
            servo_mode: config.servo_mode.to_string(),
        }
    }
}

impl RunSummary {
    /// Writes `<folder>/summary.json` under a temporary name and renames it, so the file
    /// is whole or absent.
    pub fn write(&self, folder: &Path) -> io::Result<()> {
        let json = serde_json::to_string_pretty(self).map_err(io::Error::other)?;
        let partial = folder.join(".summary.partial.json");
        std::fs::write(&partial, json + "\n")
            .and_then(|()| std::fs::rename(&partial, folder.join("summary.json")))
            .inspect_err(|_| {
                let _ = std::fs::remove_file(&partial);
            })
    }

    /// The learner's size in its own terms, ending in `; `, as its method's facts give it
    /// (nothing for one that has none to speak of: ik, ffn's one net); a learner written
    /// outside the crate gets a generic one.
    fn model_size(&self) -> String {
        let stats = LearnerStats {
            nodes: self.nodes,
            bins: self.bins,
            patterns: self.patterns,
            ..LearnerStats::default()
        };
        match self.method.parse::<Method>() {
            Ok(method) => (method.facts().size)(&stats),
            Err(_) => format!("model: {} nodes, {} patterns; ", self.nodes, self.patterns),
        }
    }

    /// What the arm met on its moves, ending in a newline: on the dynamic simulator its
    /// physics steps, settle time-outs, contact stops and speed faults (the worst named);
    /// on the kinematic one its contact stops, if any (nothing otherwise).
    fn arm_line(&self) -> String {
        if self.sim != "dynamic" {
            return match self.stopped_by_contact {
                0 => String::new(),
                n => format!("{n} of {} moves stopped by a contact\n", self.moves),
            };
        }
        let worst = self.worst_speed_fault.map_or(String::new(), |w| {
            format!(
                " (worst: joint {} at {:.1}°/s, its limit {:.1}°/s)",
                w.joint, w.speed_deg_s, w.limit_deg_s
            )
        });
        format!(
            "dynamic arm: {:.1} physics steps per trial, {} settle time-outs, {} of {} moves stopped by a contact, {} steps with a joint beyond its velocity limit{worst}\n",
            self.physics_steps_per_trial,
            self.settle_timeouts,
            self.stopped_by_contact,
            self.moves,
            self.speed_faults
        )
    }

    /// A short human-readable report of the run.
    pub fn one_screen(&self) -> String {
        let figure = |v: &Option<f64>| v.map_or("-".to_string(), |v| format!("{v:.4}"));
        let failed = match self.failures {
            0 => "none failed".to_string(),
            n => format!("{n} failed: {}", self.failures_by_reason),
        };
        let mut text = format!(
            "{} on the {} simulator ({} camera), config {}, seed {}: {} trials in {:.2} s ({:.0} trials/s), {failed}\n",
            self.method, self.sim, self.camera, self.config_file, self.seed, self.trials, self.wall_seconds, self.trials_per_second
        );
        if self.interrupted {
            text += "interrupted: the trials above are those finished before the signal\n";
        }
        text += &format!("{}peak memory {} kB\n", self.model_size(), self.peak_rss_kb);
        text += &self.arm_line();
        text += &format!(
            "distance to target over the last {} trials (mm):\n",
            self.window
        );
        text += "  after step      1         2         3         4         5\n";
        let row = |name: &str, values: &[Option<f64>]| {
            let cells: Vec<String> = values.iter().map(|v| format!("{:>9}", figure(v))).collect();
            format!("  {name:<10}{}\n", cells.join(" "))
        };
        text += &row("mean", &self.mean_distance_mm);
        text += &row("median", &self.median_distance_mm);
        text
    }
}
