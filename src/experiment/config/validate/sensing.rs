//! The sane ranges of the sensing entries: sensor noise and the camera's clock, which
//! needs the dynamic simulator.

use super::{rule, within, Check};
use crate::control::ServoMode;
use crate::experiment::config_values::SimKind;
use crate::experiment::Config;

impl Config {
    pub(super) fn check_sensors(&self) -> Check {
        within(
            "raycast_noise",
            self.raycast_noise,
            0.0,
            0.3,
            " (of a pixel's full grey level)",
        )?;
        within(
            "camera_noise_px",
            self.camera_noise_px,
            0.0,
            50.0,
            " pixels",
        )?;
        within(
            "camera_area_noise",
            self.camera_area_noise,
            0.0,
            0.5,
            " (a fraction of the area)",
        )?;
        within("joint_noise_deg", self.joint_noise_deg, 0.0, 10.0, "°")
    }

    pub(super) fn check_timing(&self) -> Check {
        let dynamic = self.sim == SimKind::Dynamic;
        let needs_clock = " needs the dynamic simulator (sim dynamic): the kinematic one has \
                           no clock, its frames come as each move ends";
        let ticks_per_second = 1.0 / self.dt;
        within(
            "camera_fps",
            self.camera_fps,
            0.0,
            1000.0,
            " frames per second (0: a frame as each move settles)",
        )?;
        rule(
            self.camera_fps == 0.0 || dynamic,
            "camera_fps",
            &self.camera_fps,
            &format!("above 0{needs_clock}"),
        )?;
        rule(
            self.camera_fps <= ticks_per_second * (1.0 + 1e-9),
            "camera_fps",
            &self.camera_fps,
            &format!("must be at most one frame per time step (1/dt = {ticks_per_second})"),
        )?;
        within(
            "camera_latency_ms",
            self.camera_latency_ms,
            0.0,
            1000.0,
            " ms",
        )?;
        rule(
            self.camera_latency_ms == 0.0 || dynamic,
            "camera_latency_ms",
            &self.camera_latency_ms,
            &format!("above 0{needs_clock}"),
        )?;
        let ticks = self.camera_latency_ms / (1000.0 * self.dt);
        rule(
            (ticks - ticks.round()).abs() <= 1e-6 * ticks.max(1.0),
            "camera_latency_ms",
            &self.camera_latency_ms,
            &format!(
                "must be a whole number of time steps (dt = {} ms)",
                self.dt * 1000.0
            ),
        )?;
        let continuous = self.servo_mode == ServoMode::Continuous;
        rule(
            !continuous || dynamic,
            "servo_mode",
            &self.servo_mode,
            &format!("continuous{needs_clock}"),
        )?;
        rule(
            !continuous || self.camera_fps > 0.0,
            "camera_fps",
            &self.camera_fps,
            "must be above 0 with servo_mode continuous (the camera takes frames at that \
             rate while the arm moves)",
        )
    }
}
