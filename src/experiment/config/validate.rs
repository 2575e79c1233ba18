//! The rules between entries, checked on a whole config (after every `--set`), so a value
//! is judged against the others' final values; each entry's own range is declared beside
//! it (`entries.rs`) and checked first.

mod cost;
mod issgp;
mod lwpr;
mod sensing;

use super::memory_estimate::machine_memory;
use super::values::{ConfigValue, ReachSetting};
use super::{Config, ConfigErrorKind};
use crate::learn::change::ChangeRecovery;
use crate::learn::{MergeStrategy, Method};
use crate::robot::LearnedJoints;

/// Most physics steps one settling may take.
const MAX_SETTLE_STEPS: f64 = 1e5;

/// Checks one rule: `ok`, or entry `name` (holding `value`) breaks `rule`.
fn rule(ok: bool, name: &'static str, value: &impl ConfigValue, rule: &str) -> Check {
    if ok {
        Ok(())
    } else {
        Err(ConfigErrorKind::OutOfRange {
            name,
            value: value.render(),
            rule: rule.to_string(),
        })
    }
}

type Check = Result<(), ConfigErrorKind>;

impl Config {
    /// Checks the memory the values would need, every entry's own rule and the rules
    /// between entries; the error names the first entry at fault.
    pub fn check(&self) -> Check {
        self.check_memory(machine_memory())?;
        self.check_each_entry()?;
        self.check_inputs()?;
        self.check_control_loop()?;
        self.check_events()?;
        self.check_tree()?;
        self.check_dynamics()?;
        self.check_timing()?;
        self.check_arm()?;
        self.check_lwpr()?;
        self.check_issgp()?;
        self.check_cost()
    }

    /// The arm entries on their own; whether the URDF has such a link and joints is
    /// checked when the arm is read.
    fn check_arm(&self) -> Check {
        rule(
            self.camera_offset.iter().all(|v| v.abs() <= 1000.0),
            "camera_offset",
            &self.camera_offset,
            "must be within 1000 cm of the camera link's origin on each axis",
        )?;
        let mount = &self.camera_mount;
        rule(
            mount.offset_m.iter().all(|v| v.abs() <= 10.0)
                && mount.rpy_deg.iter().all(|v| v.abs() <= 360.0),
            "camera_mount",
            mount,
            "must lie within 10 m of the camera link's origin on each axis and turn at most 360° \
             about each",
        )?;
        rule(
            mount.offset_m == [0.0; 3] || self.camera_offset == [0.0; 3],
            "camera_mount",
            mount,
            "gives the camera's offset while camera_offset gives it too: give it in one of them",
        )?;
        if let LearnedJoints::Named([a, b, c]) = &self.learned_joints {
            rule(
                a != b && b != c && a != c,
                "learned_joints",
                &self.learned_joints,
                "must name three different joints",
            )?;
        }
        if let Some(folder) = self.package_paths.missing_folder() {
            rule(
                false,
                "package_paths",
                &self.package_paths,
                &format!(
                    "must name existing folders; `{}` is not one",
                    folder.display()
                ),
            )?;
        }
        if let ReachSetting::Given([r_min, r_max, z_min, z_max]) = self.reach_space {
            rule(
                (0.0..r_max).contains(&r_min) && r_max <= 10_000.0 && z_min < z_max,
                "reach_space",
                &self.reach_space,
                "must be `auto` or r_min,r_max,z_min,z_max with 0 ≤ r_min < r_max ≤ 10000 cm and z_min < z_max",
            )?;
        }
        Ok(())
    }

    /// Each boundary's high end above its low end.
    fn check_inputs(&self) -> Check {
        const HIGH: [&str; 8] = [
            "boundary_0_high",
            "boundary_1_high",
            "boundary_2_high",
            "boundary_3_high",
            "boundary_4_high",
            "boundary_5_high",
            "boundary_6_high",
            "boundary_7_high",
        ];
        for (i, name) in HIGH.into_iter().enumerate() {
            let (low, high) = self.boundary(i);
            rule(
                low < high,
                name,
                &high,
                &format!("must be above boundary_{i}_low ({low})"),
            )?;
        }
        Ok(())
    }

    fn check_control_loop(&self) -> Check {
        rule(
            self.min_feedback_steps <= self.feedback_steps,
            "min_feedback_steps",
            &self.min_feedback_steps,
            &format!("must not exceed feedback_steps ({})", self.feedback_steps),
        )
    }

    fn check_events(&self) -> Check {
        for (name, trial) in [
            ("rotate_trial", self.rotate_trial),
            ("elongate_trial", self.elongate_trial),
        ] {
            if trial > self.trials {
                return Err(ConfigErrorKind::EventAfterLastTrial {
                    name: name.to_string(),
                    trial,
                    trials: self.trials,
                });
            }
        }
        rule(
            self.elongate_trial == 0 || (1..=3).contains(&self.elongate_link),
            "elongate_link",
            &self.elongate_link,
            "must be 1, 2 or 3",
        )
    }

    fn check_tree(&self) -> Check {
        rule(
            self.max_stored_patterns == 0 || self.max_stored_patterns >= self.bin_size,
            "max_stored_patterns",
            &self.max_stored_patterns,
            &format!(
                "must be 0 (no cap) or at least bin_size ({})",
                self.bin_size
            ),
        )?;
        rule(
            self.max_pats_in_mat >= self.nr_of_matrices,
            "max_pats_in_mat",
            &self.max_pats_in_mat,
            &format!("must be at least nr_of_matrices ({})", self.nr_of_matrices),
        )?;
        rule(
            self.change_warmup > self.change_lag,
            "change_warmup",
            &self.change_warmup,
            &format!("must be above change_lag ({})", self.change_lag),
        )?;
        let forgets = [Method::Ffn, Method::Kohonen].contains(&self.method)
            && self.merge_strategy == MergeStrategy::ChangeDetection;
        rule(
            !forgets || self.change_recovery == ChangeRecovery::Correct,
            "change_recovery",
            &self.change_recovery,
            &format!(
                "must be correct for {} under merge_strategy change_detection (it has no \
                 forget)",
                self.method
            ),
        )
    }

    fn check_dynamics(&self) -> Check {
        rule(
            self.settle_timeout >= self.dt && self.settle_timeout <= 60.0,
            "settle_timeout",
            &self.settle_timeout,
            "must be at least one time step (dt) and at most 60 seconds",
        )?;
        rule(
            self.settle_timeout / self.dt <= MAX_SETTLE_STEPS,
            "settle_timeout",
            &self.settle_timeout,
            &format!(
                "must be at most {MAX_SETTLE_STEPS} time steps of dt {} s",
                self.dt
            ),
        )
    }
}
