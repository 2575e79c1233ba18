//! What the search for another camera mount met when no mount did: each mount tried and,
//! in a few words, why it did not do — what a refusal then adds.

use crate::camera::NotSeen;
use crate::experiment::setup::other_mount::TRIED_TRIALS;
use crate::experiment::setup::start_check::PrelearningFault;
use crate::experiment::{PreflightError, RunError};
use crate::robot::description::DescriptionErrorKind as Kind;

/// Why a mount tried did not do.
#[derive(Debug)]
pub(super) enum Unfit {
    /// The arm is refused before a run.
    Refused(RunError),
    /// More than half of the short run's first trials failed (how many), or it could not
    /// be made (`None`).
    Failed(Option<usize>),
    /// The arm stayed at its start in every one of the short run's first trials: the
    /// learner, given no pattern, answered zero moves.
    Still,
}

impl std::fmt::Display for Unfit {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Unfit::Failed(Some(failed)) => {
                write!(f, "it fails {failed} of its first {TRIED_TRIALS} trials")
            }
            Unfit::Failed(None) => write!(f, "its first trials cannot be run"),
            Unfit::Still => write!(
                f,
                "the arm stays at its start in each of its first {TRIED_TRIALS} trials"
            ),
            Unfit::Refused(refusal) => write!(f, "{}", refused_in_short(refusal)),
        }
    }
}

/// A refusal about where the camera looks in a few words; any other whole.
fn refused_in_short(refusal: &RunError) -> String {
    let description = match refusal {
        RunError::Urdf(error) => Some(&error.kind),
        RunError::ArmEntry { source, .. } => Some(&source.kind),
        _ => None,
    };
    match (description, refusal) {
        (Some(Kind::CannotLookDown { .. }), _) => "the wrist cannot turn it down".into(),
        (Some(Kind::CameraFacesArm { .. }), _) => "it looks back into the arm".into(),
        (_, RunError::Preflight(PreflightError::NoReachSpace(failure))) => format!(
            "no reach space fits, the wrist looking down at {:.0}% of the poses sampled",
            100.0 * (1.0 - failure.no_wrist as f64 / failure.sampled.max(1) as f64)
        ),
        (
            _,
            RunError::Preflight(PreflightError::Unreachable {
                reachable, sampled, ..
            }),
        ) => format!("it reaches {reachable} of {sampled} points of the space fitted"),
        (
            _,
            RunError::Preflight(PreflightError::Prelearning {
                fault: PrelearningFault::NotSeen(NotSeen::Hidden),
                ..
            }),
        ) => "the arm hides the object from the pre-learning starts".into(),
        (_, RunError::Preflight(PreflightError::NoPrelearningPose { .. })) => {
            "the middle of the space it fits is not reached looking down".into()
        }
        _ => refusal.to_string(),
    }
}

/// Every other mount the search tried, none of which did, and why each did not.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct NoOtherMount {
    /// Each mount tried (the link's axis the camera looked along, and how far it was
    /// moved out of the arm where it was) and why it did not do, in the order tried.
    pub tried: Vec<(String, String)>,
    /// The joints the arm learns, and the other joints of its chain, left to turn the
    /// camera down (URDF names); both empty when the arm could not be read with any mount.
    pub joints: (Vec<String>, Vec<String>),
}

impl std::fmt::Display for NoOtherMount {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let tried: Vec<String> = self
            .tried
            .iter()
            .map(|(mount, why)| format!("along {mount}: {why}"))
            .collect();
        let named = |joints: &[String]| {
            let named: Vec<String> = joints.iter().map(|j| format!("`{j}`")).collect();
            named.join(", ")
        };
        let joints = match &self.joints {
            (learned, others) if !learned.is_empty() => format!(
                " with {} learned (the others, {}, left to turn it down)",
                named(learned),
                named(others)
            ),
            _ => String::new(),
        };
        write!(
            f,
            "no other axis of the camera link does either ({}): no camera on this link looking \
             along one of its axes lets the arm work looking down{joints}; to use this arm, \
             name other joints for it to learn with learned_joints, another link for the \
             camera with camera_link, or say how the camera is mounted with camera_mount",
            tried.join("; ")
        )
    }
}
