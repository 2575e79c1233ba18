//! What a learner with one model (lwpr, issgp, mlp, ffn, kohonen) gives the shared
//! [`WatchedLearner`](super::WatchedLearner): how it forgets after a detected change.

use crate::learn::Learner;

/// A learner with a single model, watched for changes by a
/// [`WatchedLearner`](super::WatchedLearner).
pub trait SingleModel: Learner {
    /// Under `change_recovery forget`: a change of the mapping was dated to trial
    /// `changed_at`; the model forgets what it learned before that trial as far as it can.
    /// A model that cannot forget (ffn, kohonen: the config refuses `forget` for them)
    /// keeps everything.
    fn forget_before(&mut self, _changed_at: usize) {}

    /// Under `change_recovery correct`, before the first trial: the model is to keep what
    /// [`SingleModel::unlearn_since`] needs of the last `SEED_TRIALS` (200) trials, as far
    /// as it keeps anything for it (issgp: the patterns; mlp: its weights as they were).
    fn keep_recent_trials(&mut self) {}

    /// Under `change_recovery correct`: a change of the mapping was dated to trial
    /// `changed_at`; the model drops what it learned since, in the readings of the changed
    /// robot that its correction is about to carry back: the patterns it keeps apart (ffn's
    /// window, mlp's buffer), issgp's patterns taken out of its posterior, mlp's weights
    /// set back to those before that trial. Learned, those trials would stay in the model
    /// the correction carries the new readings back to (docs/ADAPTATION.md). A model that
    /// mixed them in for good (lwpr, kohonen) keeps them.
    fn unlearn_since(&mut self, _changed_at: usize) {}
}
