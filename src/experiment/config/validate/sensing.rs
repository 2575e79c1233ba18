//! The rules of the camera's clock: it needs the dynamic simulator, and its frames and
//! latency fit the time step.

use super::{rule, Check};
use crate::control::ServoMode;
use crate::experiment::config::Config;
use crate::experiment::config::SimKind;

impl Config {
    pub(super) fn check_timing(&self) -> Check {
        let dynamic = self.sim == SimKind::Dynamic;
        let needs_clock = " needs the dynamic simulator (sim dynamic): the kinematic one has \
                           no clock, its frames come as each move ends";
        let ticks_per_second = 1.0 / self.dt;
        let learning = self.learn_during_moves == 1;
        rule(
            self.camera_fps == 0.0 || dynamic || learning,
            "camera_fps",
            &self.camera_fps,
            "above 0 needs the dynamic simulator (sim dynamic), or learn_during_moves 1 \
             (frames along the kinematic simulator's moves): the kinematic one has no clock, \
             its frames come as each move ends",
        )?;
        rule(
            self.camera_fps == 0.0 || self.camera_fps >= 1.0,
            "camera_fps",
            &self.camera_fps,
            "must be 0 or at least 1 frame per second (the arm waits for frames)",
        )?;
        rule(
            self.camera_fps <= ticks_per_second * (1.0 + 1e-9),
            "camera_fps",
            &self.camera_fps,
            &format!("must be at most one frame per time step (1/dt = {ticks_per_second})"),
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
