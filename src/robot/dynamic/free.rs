//! The arm left to itself from a pose, tick by tick: servos off (a passive swing under
//! gravity) or holding the pose — to hold the simulator against another engine.

use super::builder::Arm;
use super::settings::DynamicSettings;
use crate::robot::{ArmModel, Joints, RobotError};

/// What the servos do while the arm runs free.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Drive {
    /// Servos off, no gravity feed-forward: the arm swings under its weight.
    Passive,
    /// The servos (and the gravity feed-forward) hold the start pose.
    Hold,
}

/// The dynamic arm running free from a start pose.
#[derive(Debug)]
pub struct FreeArm {
    arm: Arm,
    model: ArmModel,
    hold: Joints,
    drive: Drive,
    settings: DynamicSettings,
    steps: u64,
}

impl FreeArm {
    /// The arm of `model` at rest at `start` (every joint's angle, rad), stepped with
    /// `settings` (sanitised as the dynamic simulator does); with `limits` false the
    /// joints turn past their URDF limits, with `contacts` false the links pass through
    /// the floor and each other. Fails when a start angle is not finite, or outside its
    /// limits while they apply.
    pub fn new(
        model: ArmModel,
        start: &Joints,
        settings: DynamicSettings,
        drive: Drive,
        limits: bool,
        contacts: bool,
    ) -> Result<FreeArm, RobotError> {
        let outside = match start.iter().position(|a| !a.is_finite()) {
            Some(i) => Some(i),
            None if limits => model.violated_limit(start),
            None => None,
        };
        if let Some(i) = outside {
            let joint = &model.joints()[i];
            return Err(RobotError::OutsideLimits {
                joint: i + 1,
                angle_deg: start[i].to_degrees(),
                lower_deg: joint.lower.to_degrees(),
                upper_deg: joint.upper.to_degrees(),
            });
        }
        let settings = settings.sanitized();
        let mut arm = Arm::build(&model, &settings);
        arm.teleport(start);
        if drive == Drive::Passive || !limits {
            arm.release(limits);
        }
        if !contacts {
            arm.remove_contacts();
        }
        Ok(FreeArm {
            arm,
            model,
            hold: *start,
            drive,
            settings,
            steps: 0,
        })
    }

    /// One physics step of `dt`.
    pub fn step(&mut self) {
        if self.drive == Drive::Hold {
            let efforts = self.arm.hold_weight(&self.model, &self.hold);
            self.arm.drive(
                &self.hold,
                &Joints::zeros(self.hold.len()),
                &efforts,
                &self.settings,
            );
        }
        self.arm.world.step();
        self.steps += 1;
    }

    /// Simulated time since the start (s).
    pub fn time(&self) -> f64 {
        self.steps as f64 * self.settings.dt
    }

    /// The time step (s).
    pub fn dt(&self) -> f64 {
        self.settings.dt
    }

    /// The joint angles (rad).
    pub fn joints(&self) -> Joints {
        self.arm.joints()
    }

    /// The joint speeds (rad/s).
    pub fn speeds(&self) -> Joints {
        self.arm.speeds()
    }

    /// The joint accelerations (rad/s²) of the arm at rest at `q` with its servos off:
    /// one step from rest, its speeds over `dt` (the instant's accelerations as `dt` goes
    /// to 0; joint limits and contacts off).
    pub fn accelerations_at_rest(
        model: ArmModel,
        q: &Joints,
        settings: DynamicSettings,
    ) -> Result<Joints, RobotError> {
        let mut arm = FreeArm::new(model, q, settings, Drive::Passive, false, false)?;
        arm.step();
        Ok(arm.speeds() / arm.dt())
    }
}
