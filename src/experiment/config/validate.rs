//! The sane range of every entry and the rules between entries, checked on a whole config
//! (after every `--set`), so a value is judged against the others' final values.

mod lwpr;
mod sensing;

use super::memory::machine_memory;
use super::{Config, ConfigErrorKind};
use crate::experiment::config_values::{ConfigValue, ReachSetting};

/// Most feedback steps a trial may take: a trial learns every pair of its poses, so
/// N steps give N(N+1)/2 patterns (500,500 at 1000).
const MAX_FEEDBACK_STEPS: usize = 1000;
/// Most physics steps one settling may take.
const MAX_SETTLE_STEPS: f64 = 1e5;
/// Largest magnitude of an input boundary.
const MAX_BOUNDARY: f64 = 1e6;

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

/// `value` in `low..=high`, said as "must be LOW to HIGH UNIT".
fn within<T: ConfigValue + PartialOrd + std::fmt::Display>(
    name: &'static str,
    value: T,
    low: T,
    high: T,
    unit: &str,
) -> Check {
    let ok = value >= low && value <= high;
    rule(ok, name, &value, &format!("must be {low} to {high}{unit}"))
}

/// `value` ≥ `low`.
fn at_least(name: &'static str, value: usize, low: usize) -> Check {
    rule(
        value >= low,
        name,
        &value,
        &format!("must be at least {low}"),
    )
}

/// `value` in `(0, high]`.
fn positive_up_to(name: &'static str, value: f64, high: f64, unit: &str) -> Check {
    let ok = value > 0.0 && value <= high;
    rule(
        ok,
        name,
        &value,
        &format!("must be above 0 and at most {high}{unit}"),
    )
}

impl Config {
    /// Checks every entry's range and the rules between entries; the error names the
    /// first entry at fault.
    pub fn check(&self) -> Check {
        self.check_memory(machine_memory())?;
        self.check_inputs()?;
        self.check_control_loop()?;
        self.check_events()?;
        self.check_tree()?;
        self.check_dynamics()?;
        self.check_sensors()?;
        self.check_timing()?;
        self.check_networks()?;
        self.check_arm()?;
        self.check_lwpr()
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
        let [a, b, c] = &self.learned_joints;
        rule(
            a != b && b != c && a != c,
            "learned_joints",
            &self.learned_joints,
            "must name three different joints",
        )?;
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

    fn check_inputs(&self) -> Check {
        const LOW: [&str; 8] = [
            "boundary_0_low",
            "boundary_1_low",
            "boundary_2_low",
            "boundary_3_low",
            "boundary_4_low",
            "boundary_5_low",
            "boundary_6_low",
            "boundary_7_low",
        ];
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
        for i in 0..8 {
            let (low, high) = self.boundary(i);
            within(LOW[i], low, -MAX_BOUNDARY, MAX_BOUNDARY, "")?;
            within(HIGH[i], high, -MAX_BOUNDARY, MAX_BOUNDARY, "")?;
            rule(
                low < high,
                HIGH[i],
                &high,
                &format!("must be above boundary_{i}_low ({low})"),
            )?;
        }
        Ok(())
    }

    fn check_control_loop(&self) -> Check {
        within("trials", self.trials, 1, 1_000_000_000, "")?;
        positive_up_to("min_target_distance", self.min_target_distance, 10.0, " cm")?;
        rule(
            (1..=MAX_FEEDBACK_STEPS).contains(&self.feedback_steps),
            "feedback_steps",
            &self.feedback_steps,
            &format!(
                "must be 1 to {MAX_FEEDBACK_STEPS} (a trial learns every pair of its poses: \
                 {} steps would give {:.1e} patterns a trial)",
                self.feedback_steps,
                self.feedback_steps as f64 * (self.feedback_steps as f64 + 1.0) / 2.0
            ),
        )?;
        rule(
            self.min_feedback_steps <= self.feedback_steps,
            "min_feedback_steps",
            &self.min_feedback_steps,
            &format!("must not exceed feedback_steps ({})", self.feedback_steps),
        )?;
        within(
            "minimal_joint_move",
            self.minimal_joint_move,
            0.0,
            10.0,
            "°",
        )?;
        positive_up_to("robot_speed", self.robot_speed, 3600.0, " °/s")?;
        positive_up_to("robot_accel", self.robot_accel, 100_000.0, " °/s²")?;
        at_least("depth_info", self.depth_info, 1)
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
        within("rotate_degrees", self.rotate_degrees, -360.0, 360.0, "°")?;
        rule(
            self.elongate_trial == 0 || (1..=3).contains(&self.elongate_link),
            "elongate_link",
            &self.elongate_link,
            "must be 1, 2 or 3",
        )
    }

    fn check_tree(&self) -> Check {
        within("tree_depth", self.tree_depth, 1, 12, "")?;
        rule(
            self.split_error >= 0.0,
            "split_error",
            &self.split_error,
            "must not be negative",
        )?;
        rule(
            self.merge_error >= 0.0,
            "merge_error",
            &self.merge_error,
            "must not be negative",
        )?;
        within(
            "min_pats_for_split",
            self.min_pats_for_split,
            1,
            1_000_000,
            "",
        )?;
        within("bin_size", self.bin_size, 1, 10_000, "")?;
        rule(
            self.max_stored_patterns == 0 || self.max_stored_patterns >= self.bin_size,
            "max_stored_patterns",
            &self.max_stored_patterns,
            &format!(
                "must be 0 (no cap) or at least bin_size ({})",
                self.bin_size
            ),
        )?;
        within("monitor_ave", self.monitor_ave, 1, 10_000_000, "")?;
        rule(
            self.am_error_tresh > 0.0,
            "am_error_tresh",
            &self.am_error_tresh,
            "must be above 0 (degrees)",
        )?;
        within("am_error_iters", self.am_error_iters, 1, 10_000, "")?;
        within("nr_of_matrices", self.nr_of_matrices, 1, 1000, "")?;
        rule(
            self.max_pats_in_mat >= self.nr_of_matrices,
            "max_pats_in_mat",
            &self.max_pats_in_mat,
            &format!("must be at least nr_of_matrices ({})", self.nr_of_matrices),
        )?;
        within(
            "known_pattern_perc",
            self.known_pattern_perc,
            0.0,
            1000.0,
            "",
        )?;
        let shrink = self.error_area_shrink;
        positive_up_to("error_area_shrink", shrink, 1.0, "")?;
        rule(
            self.change_drift >= 0.0,
            "change_drift",
            &self.change_drift,
            "must not be negative",
        )?;
        rule(
            self.change_threshold > 0.0,
            "change_threshold",
            &self.change_threshold,
            "must be above 0",
        )?;
        within(
            "change_baseline",
            self.change_baseline,
            1,
            1_000_000_000,
            "",
        )?;
        within("change_lag", self.change_lag, 0, 1_000_000, "")?;
        rule(
            self.change_warmup > self.change_lag,
            "change_warmup",
            &self.change_warmup,
            &format!("must be above change_lag ({})", self.change_lag),
        )?;
        at_least("change_grace", self.change_grace, 1)
    }

    fn check_dynamics(&self) -> Check {
        within("dt", self.dt, 1e-5, 0.1, " seconds")?;
        within("solver_iterations", self.solver_iterations, 1, 100, "")?;
        positive_up_to("motor_stiffness", self.motor_stiffness, 1e9, " per s²")?;
        positive_up_to("motor_damping", self.motor_damping, 1e6, " per s")?;
        positive_up_to("settle_position_tol", self.settle_position_tol, 10.0, "°")?;
        positive_up_to("settle_speed_tol", self.settle_speed_tol, 1000.0, "°/s")?;
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
        )?;
        within(
            "floor_z",
            self.floor_z,
            -1000.0,
            0.0,
            " cm (at or below the base plane)",
        )?;
        within("raycast_resolution", self.raycast_resolution, 16, 4096, "")
    }

    fn check_networks(&self) -> Check {
        positive_up_to("wrange", self.wrange, 10.0, "")?;
        within("hidden_units", self.hidden_units, 1, 10_000, "")?;
        within("nnw_train_limit", self.nnw_train_limit, 0, 1_000_000, "")?;
        within("ffn_hidden_units", self.ffn_hidden_units, 1, 10_000, "")?;
        within("ffn_window", self.ffn_window, 1, 1_000_000, "")?;
        within("ffn_cg_iterations", self.ffn_cg_iterations, 0, 10_000, "")?;
        within("kohonen_side", self.kohonen_side, 2, 12, "")?;
        at_least("kohonen_anneal_patterns", self.kohonen_anneal_patterns, 1)
    }
}
