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

    /// Under `change_recovery correct`: a change of the mapping was dated to trial
    /// `changed_at`; the model drops the patterns it learned since, in the readings of the
    /// changed robot that its correction is about to carry back, where it keeps them apart
    /// (ffn's window, mlp's buffer). A model that mixed them in for good keeps them.
    fn unlearn_since(&mut self, _changed_at: usize) {}
}
