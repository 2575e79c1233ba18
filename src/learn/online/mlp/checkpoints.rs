//! The net's weights and Adam's state as they were at the start of each recent trial, kept
//! under `change_recovery correct` so that a detected change can set them back to those
//! before it: the steps taken on the changed robot's patterns before the alarm would stay
//! in the net the correction carries the new readings back to.

use super::adam::Adam;
use std::collections::VecDeque;

/// The net's weights and its optimiser at the start of a trial.
#[derive(Debug, Clone, PartialEq)]
struct Checkpoint {
    trial: usize,
    params: Vec<f64>,
    adam: Adam,
}

/// The states at the start of the last `capacity` trials, oldest first.
#[derive(Debug, Clone, PartialEq)]
pub(super) struct Checkpoints {
    states: VecDeque<Checkpoint>,
    capacity: usize,
}

impl Checkpoints {
    /// Room for the states of `capacity` trials (0: none are kept).
    pub(super) fn new(capacity: usize) -> Checkpoints {
        Checkpoints {
            states: VecDeque::with_capacity(capacity),
            capacity,
        }
    }

    /// Keeps the state at the start of `trial`; once full, in the place of the oldest,
    /// whose memory it reuses.
    pub(super) fn keep(&mut self, trial: usize, params: &[f64], adam: &Adam) {
        if self.capacity == 0 {
            return;
        }
        let state = match (self.states.len() == self.capacity)
            .then(|| self.states.pop_front())
            .flatten()
        {
            Some(mut state) => {
                state.trial = trial;
                state.params.copy_from_slice(params);
                state.adam.copy_from(adam);
                state
            }
            None => Checkpoint {
                trial,
                params: params.to_vec(),
                adam: adam.clone(),
            },
        };
        self.states.push_back(state);
    }

    /// Writes the state at the start of `trial` (the oldest kept, if that is later) into
    /// `params` and `adam` and drops the states after it; with none kept, leaves them.
    pub(super) fn restore(&mut self, trial: usize, params: &mut [f64], adam: &mut Adam) {
        while self.states.len() > 1 && self.states.back().is_some_and(|s| s.trial > trial) {
            self.states.pop_back();
        }
        if let Some(state) = self.states.back() {
            params.copy_from_slice(&state.params);
            adam.copy_from(&state.adam);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn stepped(steps: usize) -> (Vec<f64>, Adam) {
        let (mut params, mut adam) = (vec![0.5, -0.25], Adam::new(0.01, 2));
        for _ in 0..steps {
            adam.step(&mut params, &[1.0, -2.0]);
        }
        (params, adam)
    }

    #[test]
    fn a_restore_gives_the_state_at_the_start_of_the_trial() {
        let mut checkpoints = Checkpoints::new(3);
        for trial in 1..=5 {
            let (params, adam) = stepped(trial);
            checkpoints.keep(trial, &params, &adam);
        }
        let (mut params, mut adam) = stepped(9);
        checkpoints.restore(4, &mut params, &mut adam);
        assert_eq!((params, adam), stepped(4));
        // Trial 2 is no longer kept: the oldest, trial 3, is the nearest.
        let (mut params, mut adam) = stepped(9);
        checkpoints.restore(2, &mut params, &mut adam);
        assert_eq!((params, adam), stepped(3));
    }

    #[test]
    fn nothing_is_kept_without_room() {
        let mut checkpoints = Checkpoints::new(0);
        let (params, adam) = stepped(1);
        checkpoints.keep(1, &params, &adam);
        let (mut params, mut adam) = stepped(2);
        checkpoints.restore(1, &mut params, &mut adam);
        assert_eq!((params, adam), stepped(2));
    }
}
