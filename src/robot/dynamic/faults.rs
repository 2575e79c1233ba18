//! Faults the dynamic arm reports rather than passes over: a joint turning faster than
//! its URDF `velocity` limit (counted per tick, the worst named).

use super::builder::Arm;
use crate::robot::ArmModel;

/// A joint turning faster than its URDF `velocity` limit.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SpeedFault {
    /// 1-based joint number.
    pub joint: usize,
    /// How fast it turned (rad/s, either way).
    pub speed: f64,
    /// Its URDF velocity limit (rad/s).
    pub limit: f64,
}

impl SpeedFault {
    /// How many times its limit the joint turned.
    pub fn excess(&self) -> f64 {
        self.speed / self.limit
    }

    /// The worse of two faults (the larger excess), either or both absent.
    pub fn worse(a: Option<SpeedFault>, b: Option<SpeedFault>) -> Option<SpeedFault> {
        match (a, b) {
            (Some(a), Some(b)) => Some(if b.excess() > a.excess() { b } else { a }),
            (a, b) => a.or(b),
        }
    }
}

impl std::fmt::Display for SpeedFault {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "joint {} turned at {:.1}°/s, beyond its URDF velocity limit of {:.1}°/s",
            self.joint,
            self.speed.to_degrees(),
            self.limit.to_degrees()
        )
    }
}

impl Arm {
    /// The joint furthest beyond its URDF velocity limit now (a speed that is not finite
    /// counts as beyond), if any is.
    pub(super) fn speed_fault(&self, model: &ArmModel) -> Option<SpeedFault> {
        let speeds = self.speeds();
        model
            .joints()
            .iter()
            .take(self.dof)
            .enumerate()
            .filter(|(i, joint)| !speeds[*i].is_finite() || speeds[*i].abs() > joint.velocity)
            .map(|(i, joint)| SpeedFault {
                joint: i + 1,
                speed: speeds[i].abs(),
                limit: joint.velocity,
            })
            .fold(None, |worst, fault| SpeedFault::worse(worst, Some(fault)))
    }
}
