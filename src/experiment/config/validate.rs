//! The checks of config values against each other.

use super::Config;

impl Config {
    /// Checks the values against each other; the error names the offending entry.
    pub(super) fn validate(&self) -> Result<(), (&'static str, String)> {
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
            (0.0..=0.3).contains(&self.raycast_noise),
            "raycast_noise",
            "must be 0 to 0.3 (of a pixel's full grey level)",
        )?;
        check(
            (0.0..=50.0).contains(&self.camera_noise_px),
            "camera_noise_px",
            "must be 0 to 50 (pixels)",
        )?;
        check(
            (0.0..=0.5).contains(&self.camera_area_noise),
            "camera_area_noise",
            "must be 0 to 0.5 (a fraction of the area)",
        )?;
        check(
            (0.0..=10.0).contains(&self.joint_noise_deg),
            "joint_noise_deg",
            "must be 0 to 10 (degrees)",
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
        check(self.wrange > 0.0, "wrange", "must be positive")?;
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
            self.change_warmup > self.change_lag,
            "change_warmup",
            &format!("must be above change_lag ({})", self.change_lag),
        )?;
        check(self.change_grace >= 1, "change_grace", "must be at least 1")?;
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
