//! What a trial did: its distances, why it failed if it did, how far the arm moved.

use crate::camera::NotSeen;

/// Distances after steps 1..=this are written to the `1step`…`5step` files.
pub const MAX_RECORDED_STEPS: usize = 5;

/// Why a trial could not be completed; counted, never fatal.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Failure {
    /// No reachable target was drawn.
    UnreachableTarget,
    /// No start pose from which the object is seen was drawn.
    NoStartSeen,
    /// The object left the image after a move.
    LostObject(NotSeen),
    /// The learner proposed a non-finite move.
    NonFiniteMove,
}

/// What a trial did (`Default`: nothing yet, no distance, no failure).
#[derive(Debug, Clone, Default, PartialEq)]
pub struct TrialOutcome {
    /// Distance to the target (mm) after each feedback step taken.
    pub distances_mm: Vec<f64>,
    /// Why the trial stopped early, if it did.
    pub failure: Option<Failure>,
    /// True when the camera came within ε of the target.
    pub reached: bool,
    /// Simulated seconds of the feedback steps: from the first frame's delivery to the
    /// last step's frame (moves, settling and waits for frames).
    pub seconds: f64,
    /// The largest change (degrees) of a controlled joint from the trial's start pose over
    /// the trial, in the simulator's true angles (no encoder noise): 0 for an arm that
    /// never left its start.
    pub moved_deg: f64,
    /// The largest joint move (degrees) the learner proposed in the trial.
    pub proposed_deg: f64,
    /// Distance to the target (mm) at the trial's start, before any move (`None` when no
    /// target or start was drawn).
    pub start_distance_mm: Option<f64>,
}
