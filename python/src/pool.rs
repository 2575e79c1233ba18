//! The vector environment's arms, split into shards of consecutive arms: the first shard is
//! stepped on the calling thread, every other one on a worker thread that builds its arms
//! and keeps them for its life (a trial loop stays on the thread that made it). A call hands
//! each worker its shard's batch — inputs in, reports out, the same buffers every call — and
//! steps the first shard meanwhile.

use crate::arm::{Arm, ArmReport, ArmRules};
use eyehand::control::Failure;
use eyehand::experiment::RunSetup;
use std::ops::Range;
use std::sync::mpsc::{channel, Receiver, Sender};
use std::thread::JoinHandle;

/// Why the arms could not be stepped.
#[derive(Debug, thiserror::Error)]
pub enum PoolError {
    /// An arm could not begin an episode or take a step.
    #[error("arm {arm}: {}", failure_words(*.failure))]
    Arm {
        /// The arm's index.
        arm: usize,
        /// What failed.
        failure: Failure,
    },
    /// A worker thread could not be started or has stopped.
    #[error("a worker thread of the vector environment stopped: {0}")]
    Worker(String),
}

/// A failure in words.
fn failure_words(failure: Failure) -> String {
    match failure {
        Failure::UnreachableTarget => "no reachable target was drawn".into(),
        Failure::NoStartSeen => "no start pose from which the object is seen was drawn".into(),
        Failure::NonFiniteMove => "a non-finite action".into(),
        other => format!("the episode could not go on: {other:?}"),
    }
}

/// What a call asks of a shard.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Call {
    /// Reset the masked arms, with their seeds.
    Reset,
    /// Step every arm with its action.
    Step,
}

/// One shard's inputs and reports for a call.
#[derive(Debug)]
struct Batch {
    call: Call,
    /// Three shares of the move bound per arm.
    actions: Vec<f32>,
    /// The seed of each arm's reset.
    seeds: Vec<Option<u64>>,
    /// Which arms a reset resets.
    mask: Vec<bool>,
    /// One report per arm (a reset leaves the unmasked arms' reports as they were).
    reports: Vec<ArmReport>,
    /// The first arm that failed (its index in the shard) and why.
    failure: Option<(usize, Failure)>,
}

impl Batch {
    fn new(len: usize) -> Batch {
        let blank = ArmReport {
            obs: [0.0; 5],
            reward: 0.0,
            end: crate::arm::EndCode::Running,
            distance_mm: 0.0,
            joints_deg: [0.0; 3],
            seen: false,
            camera_mm: [0.0; 3],
            goal_mm: [0.0; 3],
        };
        Batch {
            call: Call::Step,
            actions: vec![0.0; 3 * len],
            seeds: vec![None; len],
            mask: vec![false; len],
            reports: vec![blank; len],
            failure: None,
        }
    }
}

/// The arms of one shard.
#[derive(Debug)]
struct Shard {
    arms: Vec<Arm>,
    rules: ArmRules,
}

impl Shard {
    /// Arms `range` of the vector, arm i seeded with `seed + i`.
    fn build(setup: &RunSetup, seed: u64, range: Range<usize>, rules: ArmRules) -> Shard {
        let mut setup = setup.clone();
        let arms = range
            .map(|i| {
                setup.config.seed = seed.wrapping_add(i as u64);
                Arm::new(setup.trial_loop())
            })
            .collect();
        Shard { arms, rules }
    }

    /// Does what `batch` asks of every arm, stopping at the first failure.
    fn run(&mut self, batch: &mut Batch) {
        batch.failure = None;
        for (k, arm) in self.arms.iter_mut().enumerate() {
            let result = match batch.call {
                Call::Reset if !batch.mask[k] => continue,
                Call::Reset => arm.reset(batch.seeds[k], &self.rules),
                Call::Step => {
                    let a = &batch.actions[3 * k..3 * k + 3];
                    arm.step([a[0], a[1], a[2]], &self.rules)
                }
            };
            match result {
                Ok(report) => batch.reports[k] = report,
                Err(failure) => {
                    batch.failure = Some((k, failure));
                    return;
                }
            }
        }
    }
}

/// A worker thread and the channels to it; `batch` is here between calls.
#[derive(Debug)]
struct Worker {
    range: Range<usize>,
    jobs: Option<Sender<Batch>>,
    done: Receiver<Batch>,
    batch: Option<Batch>,
    thread: Option<JoinHandle<()>>,
}

impl Worker {
    fn spawn(setup: &RunSetup, seed: u64, range: Range<usize>, rules: ArmRules) -> Worker {
        let (jobs, inbox) = channel::<Batch>();
        let (outbox, done) = channel();
        let (setup, shard_range) = (setup.clone(), range.clone());
        let thread = std::thread::spawn(move || {
            let mut shard = Shard::build(&setup, seed, shard_range, rules);
            for mut batch in inbox {
                shard.run(&mut batch);
                if outbox.send(batch).is_err() {
                    break;
                }
            }
        });
        Worker {
            batch: Some(Batch::new(range.len())),
            range,
            jobs: Some(jobs),
            done,
            thread: Some(thread),
        }
    }
}

impl Drop for Worker {
    fn drop(&mut self) {
        self.jobs = None;
        if let Some(thread) = self.thread.take() {
            let _ = thread.join();
        }
    }
}

/// Every arm of the vector environment, and their latest reports.
#[derive(Debug)]
pub struct ArmPool {
    local: Shard,
    local_batch: Batch,
    workers: Vec<Worker>,
    len: usize,
}

impl ArmPool {
    /// `len` arms (arm i's draws seeded with `seed + i`) in `threads` shards of nearly
    /// equal size (at least one, at most one per arm).
    pub fn new(
        setup: &RunSetup,
        seed: u64,
        len: usize,
        threads: usize,
        rules: ArmRules,
    ) -> ArmPool {
        let shards = threads.clamp(1, len.max(1));
        let bound = |s: usize| s * len / shards;
        let workers = (1..shards)
            .map(|s| Worker::spawn(setup, seed, bound(s)..bound(s + 1), rules))
            .collect();
        ArmPool {
            local: Shard::build(setup, seed, 0..bound(1), rules),
            local_batch: Batch::new(bound(1)),
            workers,
            len,
        }
    }

    /// How many arms there are.
    pub fn len(&self) -> usize {
        self.len
    }

    /// Resets the arms `mask` picks, arm i's draws restarted from `seeds[i]` when given.
    pub fn reset(&mut self, seeds: &[Option<u64>], mask: &[bool]) -> Result<(), PoolError> {
        self.call(Call::Reset, |batch, range| {
            batch.seeds.copy_from_slice(&seeds[range.clone()]);
            batch.mask.copy_from_slice(&mask[range]);
        })
    }

    /// Steps every arm with its action (three shares per arm, arm after arm).
    pub fn step(&mut self, actions: &[f32]) -> Result<(), PoolError> {
        self.call(Call::Step, |batch, range| {
            batch
                .actions
                .copy_from_slice(&actions[3 * range.start..3 * range.end]);
        })
    }

    /// The latest report of every arm, in order.
    pub fn reports(&self) -> impl Iterator<Item = &ArmReport> {
        let remote = self.workers.iter().flat_map(|w| w.batch.iter());
        std::iter::once(&self.local_batch)
            .chain(remote)
            .flat_map(|batch| batch.reports.iter())
    }

    /// Hands every shard its part of the call (`fill` puts the inputs of arms `range` in
    /// its batch) and waits for all of them.
    fn call(
        &mut self,
        call: Call,
        fill: impl Fn(&mut Batch, Range<usize>),
    ) -> Result<(), PoolError> {
        let stopped = || PoolError::Worker("it is no longer running".into());
        for worker in &mut self.workers {
            let mut batch = worker.batch.take().ok_or_else(stopped)?;
            batch.call = call;
            fill(&mut batch, worker.range.clone());
            let jobs = worker.jobs.as_ref().ok_or_else(stopped)?;
            jobs.send(batch).map_err(|_| stopped())?;
        }
        self.local_batch.call = call;
        fill(&mut self.local_batch, 0..self.local.arms.len());
        self.local.run(&mut self.local_batch);
        let mut first_failure = self.local_batch.failure;
        for worker in &mut self.workers {
            let batch = worker.done.recv().map_err(|_| stopped())?;
            if first_failure.is_none() {
                first_failure = batch.failure.map(|(k, f)| (worker.range.start + k, f));
            }
            worker.batch = Some(batch);
        }
        match first_failure {
            Some((arm, failure)) => Err(PoolError::Arm { arm, failure }),
            None => Ok(()),
        }
    }
}
