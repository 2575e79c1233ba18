//! The run's data files, written as the run goes (flushed at least once a second), so an
//! interrupted run keeps what it did: `1step` … `5step`, `nodes`, `bins`, `patterns`, `mem`
//! (trial, value, minutes used), `abs_err` (trial, error per tree level), `merges` (trial,
//! kind, depth, nodes cut) and `changes` (trial of the alarm, estimated trial of the change).

use crate::control::{TrialOutcome, MAX_RECORDED_STEPS};
use crate::learn::{LearnerStats, ModelEvent};
use std::fs::File;
use std::io::{self, BufWriter, Write};
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

const FLUSH_EVERY: Duration = Duration::from_secs(1);

/// The per-trial data files of one run.
#[derive(Debug)]
pub struct DataFiles {
    steps: Vec<BufWriter<File>>,
    nodes: BufWriter<File>,
    bins: BufWriter<File>,
    patterns: BufWriter<File>,
    mem: BufWriter<File>,
    abs_err: BufWriter<File>,
    merges: BufWriter<File>,
    changes: BufWriter<File>,
    started: Instant,
    last_flush: Instant,
}

fn create(folder: &Path, name: &str) -> io::Result<BufWriter<File>> {
    let path: PathBuf = folder.join(name);
    File::create(&path)
        .map(BufWriter::new)
        .map_err(|e| io::Error::new(e.kind(), format!("{}: {e}", path.display())))
}

impl DataFiles {
    /// Creates the files in `folder`; minutes count from now.
    pub fn create(folder: &Path) -> io::Result<DataFiles> {
        let steps = (1..=MAX_RECORDED_STEPS)
            .map(|s| create(folder, &format!("{s}step")))
            .collect::<io::Result<_>>()?;
        let now = Instant::now();
        Ok(DataFiles {
            steps,
            nodes: create(folder, "nodes")?,
            bins: create(folder, "bins")?,
            patterns: create(folder, "patterns")?,
            mem: create(folder, "mem")?,
            abs_err: create(folder, "abs_err")?,
            merges: create(folder, "merges")?,
            changes: create(folder, "changes")?,
            started: now,
            last_flush: now,
        })
    }

    /// Wall-clock minutes since the files were created.
    pub fn minutes(&self) -> f64 {
        self.started.elapsed().as_secs_f64() / 60.0
    }

    /// Records a trial's distances and the learner's size after it.
    pub fn record_trial(
        &mut self,
        trial: usize,
        outcome: &TrialOutcome,
        stats: &LearnerStats,
    ) -> io::Result<()> {
        let minutes = self.minutes();
        for (file, distance) in self.steps.iter_mut().zip(&outcome.distances_mm) {
            writeln!(file, "{trial} {distance:.6} {minutes:.6}")?;
        }
        writeln!(self.nodes, "{trial} {} {minutes:.6}", stats.nodes)?;
        writeln!(self.bins, "{trial} {} {minutes:.6}", stats.bins)?;
        writeln!(self.patterns, "{trial} {} {minutes:.6}", stats.patterns)?;
        if self.last_flush.elapsed() >= FLUSH_EVERY {
            self.flush()?;
        }
        Ok(())
    }

    /// Records the resident memory (kB) and the error of every tree level.
    pub fn record_depth_info(
        &mut self,
        trial: usize,
        memory_kb: u64,
        stats: &LearnerStats,
    ) -> io::Result<()> {
        let minutes = self.minutes();
        writeln!(self.mem, "{trial} {memory_kb} {minutes:.6}")?;
        write!(self.abs_err, "{trial}")?;
        for level in &stats.levels {
            match level.error {
                Some(error) => write!(self.abs_err, " {error:.6e}")?,
                None => write!(self.abs_err, " -")?,
            }
        }
        writeln!(self.abs_err)
    }

    /// Records what the learner did to its model during `trial`.
    pub fn record_model_events(&mut self, trial: usize, events: &[ModelEvent]) -> io::Result<()> {
        for event in events {
            match *event {
                ModelEvent::Merge { kind, depth, nodes } => {
                    writeln!(self.merges, "{trial} {kind} {depth} {nodes}")?
                }
                ModelEvent::Change { estimated_trial } => {
                    writeln!(self.changes, "{trial} {estimated_trial}")?
                }
            }
        }
        Ok(())
    }

    /// Writes everything buffered to disk.
    pub fn flush(&mut self) -> io::Result<()> {
        self.last_flush = Instant::now();
        for file in self.steps.iter_mut() {
            file.flush()?;
        }
        for file in [
            &mut self.nodes,
            &mut self.bins,
            &mut self.patterns,
            &mut self.mem,
            &mut self.abs_err,
        ] {
            file.flush()?;
        }
        Ok(())
    }
}
