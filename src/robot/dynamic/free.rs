//! The arm run from a pose, tick by tick: servos off (a passive swing under gravity),
//! holding the pose, or moving every joint to a goal along a straight line under the
//! trapezoidal profile a move follows — to hold the simulator against another engine.

use super::builder::Arm;
use super::energy::Energy;
use super::faults::SpeedFault;
use super::servo_law::SetPoint;
use super::settings::DynamicSettings;
use crate::robot::kinematic::pace::paced_profile;
use crate::robot::{ArmModel, Joints, RobotError, TrapezoidProfile};

/// What the servos do while the arm runs.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Drive {
    /// Servos off, no feed-forward: the arm swings under its weight.
    Passive,
    /// The servos (and the gravity feed-forward) hold the start pose.
    Hold,
    /// The servos move every joint from the start pose to these angles (rad) along the
    /// straight joint-space line, under the trapezoidal profile of the settings' speed
    /// and acceleration for the joint with the farthest to go, slowed where a joint would
    /// turn faster than its URDF velocity limit (as a step move does, with
    /// its velocity and acceleration fed forward), then hold them. A contact that holds the
    /// arm back stops the move where the arm is, which the servos then hold (as the dynamic
    /// simulator stops a move).
    MoveTo(Joints),
}

/// The dynamic arm running free from a start pose.
#[derive(Debug)]
pub struct FreeArm {
    arm: Arm,
    model: ArmModel,
    /// The start pose.
    start: Joints,
    drive: Drive,
    settings: DynamicSettings,
    steps: u64,
    /// The joint angles and speeds before the last step.
    before: Option<(Joints, Joints)>,
    /// The profile of a [`Drive::MoveTo`].
    profile: TrapezoidProfile,
    /// When (s) a contact stopped a [`Drive::MoveTo`], and the pose the servos hold since.
    stopped: Option<(f64, Joints)>,
    /// Steps after which a joint turned faster than its URDF velocity limit.
    speed_faults: u64,
    /// The worst of them.
    worst_fault: Option<SpeedFault>,
}

impl FreeArm {
    /// The arm of `model` at rest at `start` (every joint's angle, rad), stepped with
    /// `settings` (sanitised as the dynamic simulator does); with `limits` false the
    /// joints turn past their URDF limits, with `contacts` false the links pass through
    /// the floor and each other. Fails when an angle of the start (or of a move's goal)
    /// is not finite, or outside its limits while they apply, and when the servos are to
    /// hold or move the arm but a joint's motor is too weak to hold it at the start or
    /// the goal.
    pub fn new(
        model: ArmModel,
        start: &Joints,
        settings: DynamicSettings,
        drive: Drive,
        limits: bool,
        contacts: bool,
    ) -> Result<FreeArm, RobotError> {
        check_pose(&model, start, limits)?;
        let goal = match drive {
            Drive::MoveTo(goal) => {
                check_pose(&model, &goal, limits)?;
                goal
            }
            _ => *start,
        };
        let settings = settings.sanitized();
        let mut arm = Arm::build(&model, &settings);
        if drive != Drive::Passive {
            arm.check_holds(&model, start)?;
            arm.check_holds(&model, &goal)?;
        }
        arm.teleport(start);
        arm.release(limits);
        if !contacts {
            arm.remove_contacts();
        }
        let (moves, line) = (settings.moves, goal - *start);
        let limits = model.joints().iter().map(|joint| joint.velocity);
        let rates = line.map(f64::abs);
        let profile = paced_profile(line.amax(), moves.speed, moves.accel, &rates, limits);
        Ok(FreeArm {
            arm,
            model,
            start: *start,
            drive,
            settings,
            steps: 0,
            before: None,
            profile,
            stopped: None,
            speed_faults: 0,
            worst_fault: None,
        })
    }

    /// One physics step of `dt`.
    pub fn step(&mut self) {
        self.before = Some((self.joints(), self.speeds()));
        let set_point = match (self.drive, self.stopped) {
            (Drive::Passive, _) => None,
            (Drive::Hold, _) => Some(SetPoint::at_rest(self.start)),
            (Drive::MoveTo(_), Some((_, held))) => Some(SetPoint::at_rest(held)),
            (Drive::MoveTo(goal), None) => {
                let dt = self.settings.dt;
                let at = |k: u64| {
                    self.start + (goal - self.start) * self.profile.fraction_at(k as f64 * dt)
                };
                let k = self.steps;
                Some(SetPoint::between(&at(k), &at(k + 1), &at(k + 2), dt))
            }
        };
        self.arm
            .step(&self.model, set_point.as_ref(), &self.settings);
        self.steps += 1;
        let moving = matches!(self.drive, Drive::MoveTo(_)) && self.stopped.is_none();
        if moving && set_point.is_some_and(|s| self.arm.stopped_by_contact(&s.angles)) {
            self.stopped = Some((self.time(), self.joints()));
        }
        let fault = self.arm.speed_fault(&self.model);
        self.speed_faults += u64::from(fault.is_some());
        self.worst_fault = SpeedFault::worse(self.worst_fault, fault);
    }

    /// Steps after which a joint turned faster than its URDF velocity limit, and the worst
    /// such speed.
    pub fn speed_faults(&self) -> (u64, Option<SpeedFault>) {
        (self.speed_faults, self.worst_fault)
    }

    /// When (s) a contact stopped the move, if one did.
    pub fn stopped_by_contact(&self) -> Option<f64> {
        self.stopped.map(|(t, _)| t)
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

    /// The arm's mechanical energy now (J): kinetic and potential, from the model's
    /// kinematics and the simulated masses.
    pub fn energy(&self) -> Energy {
        self.arm.energy(&self.model, &self.joints(), &self.speeds())
    }

    /// The torque about each joint's axis (N·m) that the last step's motion took: the
    /// model's inverse dynamics at the pose and speeds it started from, with its change of
    /// speed over `dt` as the acceleration — everything acting on the joints together
    /// (servos, gravity feed-forward, damping, friction, limits). Zero before the first step.
    pub fn torques(&self) -> Joints {
        match &self.before {
            Some((q, v)) => {
                let a = (self.speeds() - v) / self.dt();
                self.arm.joint_torques(&self.model, q, v, &a)
            }
            None => Joints::zeros(self.model.dof()),
        }
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

/// Fails when an angle of pose `q` is not finite, or outside its limits while they apply.
fn check_pose(model: &ArmModel, q: &Joints, limits: bool) -> Result<(), RobotError> {
    let outside = match q.iter().position(|a| !a.is_finite()) {
        Some(i) => Some(i),
        None if limits => model.violated_limit(q),
        None => None,
    };
    match outside {
        Some(i) => {
            let joint = &model.joints()[i];
            Err(RobotError::OutsideLimits {
                joint: i + 1,
                angle_deg: q[i].to_degrees(),
                lower_deg: joint.lower.to_degrees(),
                upper_deg: joint.upper.to_degrees(),
            })
        }
        None => Ok(()),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The shoulder's travel (rad) in 0.2 s of a passive OSCAR-6 released at rest at `q`,
    /// its shoulder's dry friction `shoulder` (N·m), every other joint held by a friction
    /// far above any torque it meets.
    fn shoulder_travel(q: &Joints, shoulder: f64) -> f64 {
        let oscar6 = ArmModel::oscar6();
        let mut joints = oscar6.joints().to_vec();
        for (i, joint) in joints.iter_mut().enumerate() {
            joint.friction = if i == 1 { shoulder } else { 1e4 };
        }
        let model = ArmModel::from_parts(
            oscar6.name().to_string(),
            joints,
            oscar6.learned(),
            oscar6.camera_mount(),
            oscar6.links().to_vec(),
        )
        .unwrap();
        let settings = DynamicSettings::default();
        let mut arm = FreeArm::new(model, q, settings, Drive::Passive, false, false).unwrap();
        while arm.time() < 0.2 - 1e-9 {
            arm.step();
        }
        arm.joints()[1] - q[1]
    }

    /// The inverse dynamics holds the integration to account: a passive swing (nothing on
    /// the joints) takes no torque but the integration's error, a held pose its weight's.
    #[test]
    fn the_torques_a_motion_took_are_none_free_and_the_weight_held() {
        let oscar6 = ArmModel::oscar6();
        let q = Joints::from_slice(&[0.3, 0.6, 1.2, 0.4, 0.5, 0.2]);
        let settings = DynamicSettings {
            dt: 1e-4,
            ..DynamicSettings::default()
        };
        let arm = Arm::build(&oscar6, &settings.sanitized());
        let weight = arm.weight_torques(&oscar6, &q);
        let scale = weight.iter().fold(0.0f64, |m, t| m.max(t.abs()));
        let mut free =
            FreeArm::new(oscar6.clone(), &q, settings, Drive::Passive, false, false).unwrap();
        let mut worst = 0.0f64;
        for _ in 0..2000 {
            free.step();
            worst = free.torques().iter().fold(worst, |m, t| m.max(t.abs()));
        }
        assert!(
            free.speeds().iter().any(|v| v.abs() > 1.0),
            "the arm swings"
        );
        assert!(
            worst < 1e-3 * scale,
            "{worst} N·m against the weight's {scale}"
        );
        let mut held = FreeArm::new(oscar6, &q, settings, Drive::Hold, true, false).unwrap();
        for _ in 0..2000 {
            held.step();
        }
        let torques = held.torques();
        for (t, w) in torques.iter().zip(weight.iter()) {
            assert!(
                (t - w).abs() < 0.01 * scale,
                "{torques:?} against {weight:?}"
            );
        }
    }

    #[test]
    fn joint_friction_holds_the_weight_below_its_torque_and_slips_above_it() {
        let q = Joints::from_slice(&[0.0, 0.6, -0.3, 0.0, 0.5, 0.0]);
        let oscar6 = ArmModel::oscar6();
        let arm = Arm::build(&oscar6, &DynamicSettings::default().sanitized());
        // The threshold: the weight's torque about the shoulder (121 N·m), from the
        // model's masses and kinematics, not from the physics.
        let weight = arm.weight_torques(&oscar6, &q)[1].abs();
        assert!(weight > 1.0, "{weight}");
        let free = shoulder_travel(&q, 0.0);
        assert!(free.abs() > 0.1, "{free}");
        // Above the threshold the shoulder sticks; 2% below it, it slips with 2% of the
        // free acceleration; half of it halves the acceleration (the travel from rest is
        // ½·a·t²).
        let stuck = shoulder_travel(&q, 1.02 * weight);
        assert!((stuck / free).abs() < 1e-6, "{stuck} {free}");
        let stuck_harder = shoulder_travel(&q, 2.0 * weight);
        assert!((stuck_harder / free).abs() < 1e-6, "{stuck_harder} {free}");
        let slip = shoulder_travel(&q, 0.98 * weight) / free;
        assert!((slip - 0.02).abs() < 0.002, "{slip}");
        let half = shoulder_travel(&q, 0.5 * weight) / free;
        assert!((half - 0.5).abs() < 0.002, "{half}");
    }
}
