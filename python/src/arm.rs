//! One arm of the vector environment: a trial loop stepped as `eyehand/Reach-v0` steps its
//! testbed (the action a share of the move bound, the observation clipped to its space, the
//! reward minus the distance or the lost object's penalty), with Gymnasium's next-step
//! autoreset: the step after an episode ends resets the arm instead of moving it.

use eyehand::control::{Failure, TrialEnd, TrialLoop};
use eyehand::learn::Observation;
use eyehand::units::MM_PER_M;
use nalgebra::Vector3;

/// Values in an observation (cx, cy, cz, θ2, θ3).
pub const OBS_LEN: usize = 5;

/// What every arm shares: the move bound, the observation's bounds and the lost object's
/// reward.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ArmRules {
    /// The largest move of each joint (degrees) an action of ±1 makes.
    pub max_move_deg: [f64; 3],
    /// The observation space's low bounds.
    pub obs_low: [f32; OBS_LEN],
    /// The observation space's high bounds.
    pub obs_high: [f32; OBS_LEN],
    /// The reward of a move that loses the object.
    pub lost_reward: f64,
}

/// Why an episode ended, as the `end` codes of a batch give it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[repr(u8)]
pub enum EndCode {
    /// Going on (or just reset).
    Running = 0,
    /// Within ε after at least `min_feedback_steps` steps.
    Reached = 1,
    /// `feedback_steps` were taken.
    StepsUsed = 2,
    /// The object left the image.
    Lost = 3,
}

/// What one arm reports after a reset or a step, written into a batch's columns.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ArmReport {
    /// The observation, clipped to its space.
    pub obs: [f32; OBS_LEN],
    /// The step's reward (0 for a reset).
    pub reward: f64,
    /// Why the episode ended.
    pub end: EndCode,
    /// The distance (mm) from the camera to the goal point.
    pub distance_mm: f64,
    /// θ1, θ2, θ3 (degrees) as the encoders report them.
    pub joints_deg: [f64; 3],
    /// Whether the object is seen.
    pub seen: bool,
    /// The camera's position (world, mm).
    pub camera_mm: [f64; 3],
    /// The goal point (world, mm): a standoff above the object.
    pub goal_mm: [f64; 3],
}

/// One arm and whether its next step is a reset.
#[derive(Debug)]
pub struct Arm {
    trials: TrialLoop,
    /// The episode ended at the last step: the next step resets the arm.
    pending_reset: bool,
    /// The goal point of the episode going on (world, mm).
    goal_mm: [f64; 3],
}

impl Arm {
    /// An arm on `trials`, to be reset before it steps.
    pub fn new(trials: TrialLoop) -> Arm {
        Arm {
            trials,
            pending_reset: true,
            goal_mm: [0.0; 3],
        }
    }

    /// Begins an episode (its draws restarted from `seed` when given).
    pub fn reset(&mut self, seed: Option<u64>, rules: &ArmRules) -> Result<ArmReport, Failure> {
        if let Some(seed) = seed {
            self.trials.reseed(seed);
        }
        let start = self.trials.begin_trial()?;
        self.pending_reset = false;
        let begun = (self.trials.goal(), self.trials.distance_mm());
        // Both are there once a trial has begun.
        let (Some(goal), Some(distance_mm)) = begun else {
            return Err(Failure::UnreachableTarget);
        };
        self.goal_mm = (goal.coords * MM_PER_M).into();
        Ok(self.report(
            &start,
            start.theta_deg,
            0.0,
            EndCode::Running,
            distance_mm,
            true,
            rules,
        ))
    }

    /// Takes the step of `action` (shares of the move bound, clipped to ±1), or resets the
    /// arm when its last step ended the episode.
    pub fn step(&mut self, action: [f32; 3], rules: &ArmRules) -> Result<ArmReport, Failure> {
        if self.pending_reset {
            return self.reset(None, rules);
        }
        let share = |k: usize| f64::from(action[k]).clamp(-1.0, 1.0) * rules.max_move_deg[k];
        let delta = Vector3::new(share(0), share(1), share(2));
        let report = self
            .trials
            .step_trial(&delta)
            .map_err(|_| Failure::NonFiniteMove)?;
        let end = match report.end {
            None => EndCode::Running,
            Some(TrialEnd::Reached) => EndCode::Reached,
            Some(TrialEnd::StepsUsed) => EndCode::StepsUsed,
            Some(TrialEnd::Lost(_)) => EndCode::Lost,
        };
        self.pending_reset = end != EndCode::Running;
        let reward = match end {
            EndCode::Lost => rules.lost_reward,
            _ => -report.distance_mm,
        };
        // The path holds the start at least.
        let last = *self.trials.path().last().ok_or(Failure::NoStartSeen)?;
        let seen = report.reading.is_ok();
        Ok(self.report(
            &last,
            report.theta_deg,
            reward,
            end,
            report.distance_mm,
            seen,
            rules,
        ))
    }

    /// The report of the arm as it is now, `last` the pose at which the object was seen
    /// last.
    #[allow(clippy::too_many_arguments)]
    fn report(
        &self,
        last: &Observation,
        joints_deg: Vector3<f64>,
        reward: f64,
        end: EndCode,
        distance_mm: f64,
        seen: bool,
        rules: &ArmRules,
    ) -> ArmReport {
        let q = last.query();
        let raw = [q.c.x, q.c.y, q.c.z, q.theta2_deg, q.theta3_deg];
        let obs = std::array::from_fn(|k| {
            let (low, high) = (f64::from(rules.obs_low[k]), f64::from(rules.obs_high[k]));
            raw[k].clamp(low, high) as f32
        });
        let camera = self.trials.sim().camera_pose().translation.vector * MM_PER_M;
        ArmReport {
            obs,
            reward,
            end,
            distance_mm,
            joints_deg: joints_deg.into(),
            seen,
            camera_mm: camera.into(),
            goal_mm: self.goal_mm,
        }
    }
}
