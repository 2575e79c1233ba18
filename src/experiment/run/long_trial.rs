//! A trial that runs long says where it stands every [`LONG_TRIAL`] on stderr, bar or not,
//! wherever its time goes — its moves or its learner's learning: a thread of the run looks
//! at where the trial stands (which the trial loop tells it) and says so.

use super::progress_bar::LinePrinter;
use crate::control::TrialObserver;
use crate::learn::Method;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Arc, Mutex, PoisonError};
use std::thread::JoinHandle;
use std::time::{Duration, Instant};

/// Wall-clock time a trial runs before it says where it stands, and between two such lines.
pub(super) const LONG_TRIAL: Duration = Duration::from_secs(10);
/// How often the watching thread looks.
const LOOK_EVERY: Duration = Duration::from_millis(200);

/// Where the trial going on stands.
#[derive(Debug, Clone)]
struct Standing {
    /// The trial (0: none going on).
    trial: usize,
    /// Feedback steps taken, and the simulated seconds they took.
    step: usize,
    simulated: f64,
    /// When its learner began learning from it, once it has.
    learning_since: Option<Instant>,
    started: Instant,
    last_said: Instant,
    /// The entries that make a trial's learning long, in words.
    learner_entries: String,
}

impl Standing {
    /// The line to print at `now`, when the trial has run [`LONG_TRIAL`] since it began or
    /// since the last line.
    fn line(&mut self, now: Instant) -> Option<String> {
        if self.trial == 0 || now.duration_since(self.last_said) < LONG_TRIAL {
            return None;
        }
        self.last_said = now;
        let so_far = now.duration_since(self.started).as_secs_f64();
        let (trial, step, simulated) = (self.trial, self.step, self.simulated);
        Some(match self.learning_since {
            None => format!(
                "eyehand: trial {trial} is long: {step} steps, {simulated:.1} simulated s in {so_far:.0} s so far (feedback_steps, dt, robot_speed, settle_timeout, camera_fps)"
            ),
            Some(since) => format!(
                "eyehand: trial {trial} is long: its learner has learned from its {step} steps for {:.0} s, {so_far:.0} s into the trial ({})",
                now.duration_since(since).as_secs_f64(),
                self.learner_entries
            ),
        })
    }
}

/// The watch on a run's trials: tell it where each trial stands; its thread says so when a
/// trial runs long. Dropping it ends the thread.
#[derive(Debug)]
pub(super) struct LongTrialWatch {
    standing: Arc<Mutex<Standing>>,
    done: Arc<AtomicBool>,
    thread: Option<JoinHandle<()>>,
}

impl LongTrialWatch {
    /// A watch printing through `printer` on a run of `method`.
    pub(super) fn start(printer: LinePrinter, method: Method) -> LongTrialWatch {
        let now = Instant::now();
        let standing = Arc::new(Mutex::new(Standing {
            trial: 0,
            step: 0,
            simulated: 0.0,
            learning_since: None,
            started: now,
            last_said: now,
            learner_entries: method.facts().slow_entries.to_string(),
        }));
        let done = Arc::new(AtomicBool::new(false));
        let thread = {
            let (standing, done) = (Arc::clone(&standing), Arc::clone(&done));
            std::thread::Builder::new()
                .name("long-trial".into())
                .spawn(move || {
                    while !done.load(Ordering::Relaxed) {
                        std::thread::sleep(LOOK_EVERY);
                        let line = lock(&standing).line(Instant::now());
                        if let Some(line) = line {
                            printer.println(&line);
                        }
                    }
                })
                .ok()
        };
        LongTrialWatch {
            standing,
            done,
            thread,
        }
    }

    /// Trial `trial` begins (0: none goes on).
    pub(super) fn trial_begins(&self, trial: usize) {
        let now = Instant::now();
        let mut standing = lock(&self.standing);
        standing.trial = trial;
        (standing.step, standing.simulated) = (0, 0.0);
        standing.learning_since = None;
        (standing.started, standing.last_said) = (now, now);
    }

    /// What the trial loop tells of the trial going on.
    pub(super) fn observer(&self) -> impl TrialObserver + '_ {
        Observer(self)
    }
}

/// The trial loop's side of the watch.
struct Observer<'a>(&'a LongTrialWatch);

impl TrialObserver for Observer<'_> {
    fn step_done(&mut self, step: usize, seconds: f64) {
        let mut standing = lock(&self.0.standing);
        (standing.step, standing.simulated) = (step, seconds);
    }

    fn learning(&mut self) {
        lock(&self.0.standing).learning_since = Some(Instant::now());
    }
}

impl Drop for LongTrialWatch {
    fn drop(&mut self) {
        self.done.store(true, Ordering::Relaxed);
        if let Some(thread) = self.thread.take() {
            let _ = thread.join();
        }
    }
}

fn lock(standing: &Mutex<Standing>) -> std::sync::MutexGuard<'_, Standing> {
    standing.lock().unwrap_or_else(PoisonError::into_inner)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn standing(trial: usize, start: Instant) -> Standing {
        Standing {
            trial,
            step: 0,
            simulated: 0.0,
            learning_since: None,
            started: start,
            last_said: start,
            learner_entries: "mlp_steps_per_trial, mlp_batch, mlp_hidden".into(),
        }
    }

    #[test]
    fn a_trial_says_where_it_stands_once_per_long_interval_in_its_moves_or_its_learning() {
        let start = Instant::now();
        let mut s = standing(3, start);
        assert_eq!(s.line(start + LONG_TRIAL / 2), None);
        (s.step, s.simulated) = (3, 900.0);
        let line = s.line(start + LONG_TRIAL).unwrap();
        assert!(
            line.starts_with("eyehand: trial 3 is long: 3 steps, 900.0 simulated s in 10 s so far"),
            "{line}"
        );
        assert_eq!(s.line(start + LONG_TRIAL * 3 / 2), None);
        s.learning_since = Some(start + LONG_TRIAL);
        let line = s.line(start + LONG_TRIAL * 2).unwrap();
        assert_eq!(
            line,
            "eyehand: trial 3 is long: its learner has learned from its 3 steps for 10 s, 20 s into the trial (mlp_steps_per_trial, mlp_batch, mlp_hidden)"
        );
        assert_eq!(
            standing(0, start).line(start + LONG_TRIAL * 5),
            None,
            "no trial"
        );
    }
}
