//! One feedback step of a trial as the trial loop reports it, for callers that drive a
//! trial move by move (the Python `Testbed`, the Gymnasium environment) as well as for
//! [`TrialLoop::run_trial`](super::TrialLoop::run_trial).

use super::Failure;
use crate::camera::NotSeen;
use nalgebra::{Point3, Vector3};

/// Why a trial is over after a feedback step.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum TrialEnd {
    /// The camera is within ε of the target after at least `min_feedback_steps` steps.
    Reached,
    /// `feedback_steps` steps were taken without reaching ε.
    StepsUsed,
    /// The object left the image.
    Lost(NotSeen),
}

impl TrialEnd {
    /// The trial's failure, when the end is one.
    pub fn failure(self) -> Option<Failure> {
        match self {
            TrialEnd::Lost(not_seen) => Some(Failure::LostObject(not_seen)),
            TrialEnd::Reached | TrialEnd::StepsUsed => None,
        }
    }
}

/// What one feedback step did.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StepReport {
    /// Feedback steps taken in this trial, this one included.
    pub step: usize,
    /// The controlled joint angles (θ1, θ2, θ3) after the move (degrees), as the encoders
    /// report them (with their noise) when the object is seen; the exact angles otherwise.
    pub theta_deg: Vector3<f64>,
    /// The camera reading after the move (with its noise), or why the object is not seen.
    pub reading: Result<Vector3<f64>, NotSeen>,
    /// The true distance from the camera to the target after the move (mm).
    pub distance_mm: f64,
    /// Simulated seconds since the trial's first frame: the moves' durations, settling
    /// included, and under a camera clock the waits for frames (this step's delivery).
    pub seconds: f64,
    /// Whether this step ended the trial, and why.
    pub end: Option<TrialEnd>,
}

/// A feedback step that could not be taken; nothing moved.
#[derive(Debug, Clone, Copy, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum StepError {
    /// No trial is going on: none was begun, or the last one is over.
    #[error("no trial is going on: begin one first (the last one, if any, is over)")]
    NoTrial,
    /// The move has a non-finite component.
    #[error("the move ({}, {}, {}) degrees is not finite", .delta_deg.x, .delta_deg.y, .delta_deg.z)]
    NonFiniteMove {
        /// The move asked for (degrees).
        delta_deg: Vector3<f64>,
    },
}

/// The trial going on: where the object is and how far the trial got.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct ActiveTrial {
    /// The object's centre (world, m).
    pub(super) object: Point3<f64>,
    /// Where the camera must be to be at the target (world, m).
    pub(super) goal: Point3<f64>,
    /// Feedback steps taken.
    pub(super) steps: usize,
    /// Simulated seconds since the trial's first frame.
    pub(super) seconds: f64,
    /// Why the trial is over, once it is.
    pub(super) end: Option<TrialEnd>,
}

/// What the caller of a trial hears as it goes: each feedback step, and the moment the
/// learner starts learning from it (a caller's report on a long trial). A closure
/// `FnMut(step, seconds)` hears the steps alone.
pub trait TrialObserver {
    /// Feedback step `step` is done, `seconds` simulated seconds into the trial.
    fn step_done(&mut self, step: usize, seconds: f64);
    /// The steps are over: the learner learns from the trial now.
    fn learning(&mut self) {}
}

impl<F: FnMut(usize, f64)> TrialObserver for F {
    fn step_done(&mut self, step: usize, seconds: f64) {
        self(step, seconds)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::camera::ProjectionCamera;
    use crate::control::{TrialLoop, TrialSettings};
    use crate::learn::{IkLearner, Learner};
    use crate::robot::{ArmModel, KinematicSim, MoveSettings};

    fn trial_loop(seed: u64) -> TrialLoop {
        let sim = KinematicSim::new(ArmModel::oscar6(), MoveSettings::from_degrees(30.0, 60.0));
        let settings = TrialSettings {
            feedback_steps: 5,
            min_feedback_steps: 2,
            epsilon: 0.001,
            noise: Default::default(),
            timing: Default::default(),
            move_frames: None,
        };
        TrialLoop::new(
            Box::new(sim),
            Box::new(ProjectionCamera::default()),
            settings,
            seed,
        )
    }

    #[test]
    fn a_trial_driven_step_by_step_matches_run_trial() {
        let mut ik = IkLearner::new(ArmModel::oscar6(), Default::default());
        let mut whole = trial_loop(7);
        let mut pieces = trial_loop(7);
        for _ in 0..3 {
            let outcome = whole.run_trial(&mut ik).unwrap();
            let mut here = pieces.begin_trial().unwrap();
            let mut distances = Vec::new();
            loop {
                let report = pieces.step_trial(&ik.propose(&here.query())).unwrap();
                distances.push(report.distance_mm);
                here = *pieces.path().last().unwrap();
                if report.end.is_some() {
                    assert_eq!(report.end, Some(TrialEnd::Reached), "ik reaches ε");
                    assert_eq!(report.step, 2, "after min_feedback_steps");
                    break;
                }
            }
            assert_eq!(distances, outcome.distances_mm);
            assert_eq!(pieces.path(), whole.path());
            assert_eq!(
                pieces.step_trial(&Vector3::zeros()),
                Err(StepError::NoTrial),
                "an ended trial takes no more steps"
            );
            pieces.finish_trial(&mut ik).unwrap();
        }
    }

    #[test]
    fn a_non_finite_move_is_refused_and_nothing_moves() {
        let mut trials = trial_loop(3);
        assert_eq!(
            trials.step_trial(&Vector3::zeros()),
            Err(StepError::NoTrial)
        );
        let start = trials.begin_trial().unwrap();
        let bad = Vector3::new(1.0, f64::NAN, 0.0);
        assert!(matches!(
            trials.step_trial(&bad),
            Err(StepError::NonFiniteMove { .. })
        ));
        assert_eq!(trials.trial_state(), Some((0, None)));
        let report = trials.step_trial(&Vector3::zeros()).unwrap();
        assert_eq!(report.theta_deg, start.theta_deg);
        assert_eq!(report.reading, Ok(start.c));
    }
}
