//! The run's data files, written as the run goes so an interrupted run keeps what it did:
//! `1step` … `5step`, `nodes`, `bins`, `patterns`, `mem` (trial, value, minutes used),
//! `abs_err` (trial, error per tree level), `merges` (trial, kind, depth, nodes cut) and
//! `changes` (trial of the alarm, estimated trial of the change).
//!
//! Lines are collected whole in memory and a flusher thread writes what has collected
//! twice a second, even while a trial is stuck, so a file only ever grows by whole lines
//! (a killed run may leave at most a torn last line when the disk fills mid-write).

use crate::control::{TrialOutcome, MAX_RECORDED_STEPS};
use crate::experiment::output::number_text::{push_integer, push_six_decimals};
use crate::learn::{LearnerStats, ModelEvent};
use std::fs::File;
use std::io::{self, Write};
use std::path::Path;
use std::sync::mpsc::{self, RecvTimeoutError, Sender};
use std::sync::{Arc, Mutex, MutexGuard};
use std::thread::JoinHandle;
use std::time::{Duration, Instant};

/// How often collected lines are written out.
const FLUSH_EVERY: Duration = Duration::from_millis(500);
/// The files after the step files, in the order of `Lines::files`.
const OTHER_FILES: [&str; 7] = [
    "nodes", "bins", "patterns", "mem", "abs_err", "merges", "changes",
];
const NODES: usize = MAX_RECORDED_STEPS;
const BINS: usize = NODES + 1;
const PATTERNS: usize = NODES + 2;
const MEM: usize = NODES + 3;
const ABS_ERR: usize = NODES + 4;
const MERGES: usize = NODES + 5;
const CHANGES: usize = NODES + 6;

/// A data file and the whole lines waiting to be written to it.
#[derive(Debug)]
struct LineFile {
    file: File,
    pending: Vec<u8>,
}

/// Every file's waiting lines, and the first write error the flusher met.
#[derive(Debug)]
struct Lines {
    files: Vec<LineFile>,
    error: Option<io::Error>,
}

impl Lines {
    /// Writes every file's waiting lines; keeps the first error.
    fn write_out(&mut self) {
        for line_file in &mut self.files {
            if line_file.pending.is_empty() || self.error.is_some() {
                continue;
            }
            if let Err(e) = line_file.file.write_all(&line_file.pending) {
                self.error = Some(e);
            }
            line_file.pending.clear();
        }
    }
}

/// The per-trial data files of one run.
#[derive(Debug)]
pub struct DataFiles {
    lines: Arc<Mutex<Lines>>,
    /// Dropping it tells the flusher to write out and stop.
    stop_flusher: Option<Sender<()>>,
    flusher: Option<JoinHandle<()>>,
    started: Instant,
}

fn lock(lines: &Mutex<Lines>) -> MutexGuard<'_, Lines> {
    lines
        .lock()
        .unwrap_or_else(|poisoned| poisoned.into_inner())
}

fn create(folder: &Path, name: &str) -> io::Result<LineFile> {
    let path = folder.join(name);
    let file = File::create(&path)
        .map_err(|e| io::Error::new(e.kind(), format!("{}: {e}", path.display())))?;
    Ok(LineFile {
        file,
        pending: Vec::new(),
    })
}

impl DataFiles {
    /// Creates the files in `folder` and starts their flusher; minutes count from now.
    pub fn create(folder: &Path) -> io::Result<DataFiles> {
        let step_names = (1..=MAX_RECORDED_STEPS).map(|s| format!("{s}step"));
        let names = step_names.chain(OTHER_FILES.iter().map(|n| n.to_string()));
        let files = names
            .map(|name| create(folder, &name))
            .collect::<io::Result<_>>()?;
        let lines = Arc::new(Mutex::new(Lines { files, error: None }));
        let (stop_flusher, stopped) = mpsc::channel::<()>();
        let shared = Arc::clone(&lines);
        let flusher = std::thread::Builder::new()
            .name("data-flusher".into())
            .spawn(move || loop {
                let timeout = stopped.recv_timeout(FLUSH_EVERY);
                lock(&shared).write_out();
                if timeout != Err(RecvTimeoutError::Timeout) {
                    return;
                }
            })?;
        Ok(DataFiles {
            lines,
            stop_flusher: Some(stop_flusher),
            flusher: Some(flusher),
            started: Instant::now(),
        })
    }

    /// Wall-clock minutes since the files were created.
    pub fn minutes(&self) -> f64 {
        self.started.elapsed().as_secs_f64() / 60.0
    }

    /// The lines, once the flusher's last error (if any) is reported.
    fn lines(&self) -> io::Result<MutexGuard<'_, Lines>> {
        let mut lines = lock(&self.lines);
        match lines.error.take() {
            Some(e) => Err(e),
            None => Ok(lines),
        }
    }

    /// Records a trial's distances and the learner's size after it.
    pub fn record_trial(
        &mut self,
        trial: usize,
        outcome: &TrialOutcome,
        stats: &LearnerStats,
    ) -> io::Result<()> {
        // (Formatted once for the eight lines that carry it.)
        let mut minutes = Vec::with_capacity(24);
        push_six_decimals(&mut minutes, self.minutes());
        let mut lines = self.lines()?;
        let files = &mut lines.files;
        // "{trial} {value} {minutes}\n", as `writeln!` would write it.
        let line = |out: &mut Vec<u8>, value: &dyn Fn(&mut Vec<u8>)| {
            push_integer(out, trial);
            out.push(b' ');
            value(out);
            out.push(b' ');
            out.extend_from_slice(&minutes);
            out.push(b'\n');
        };
        let step_files = &mut files[..MAX_RECORDED_STEPS];
        for (file, &distance) in step_files.iter_mut().zip(&outcome.distances_mm) {
            line(&mut file.pending, &|out| push_six_decimals(out, distance));
        }
        for (index, count) in [
            (NODES, stats.nodes),
            (BINS, stats.bins),
            (PATTERNS, stats.patterns),
        ] {
            line(&mut files[index].pending, &|out| push_integer(out, count));
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
        let mut lines = self.lines()?;
        let files = &mut lines.files;
        writeln!(files[MEM].pending, "{trial} {memory_kb} {minutes:.6}")?;
        let abs_err = &mut files[ABS_ERR].pending;
        write!(abs_err, "{trial}")?;
        for level in &stats.levels {
            match level.error {
                Some(error) => write!(abs_err, " {error:.6e}")?,
                None => write!(abs_err, " -")?,
            }
        }
        writeln!(abs_err)
    }

    /// Records what the learner did to its model during `trial`.
    pub fn record_model_events(&mut self, trial: usize, events: &[ModelEvent]) -> io::Result<()> {
        if events.is_empty() {
            return Ok(());
        }
        let mut lines = self.lines()?;
        let files = &mut lines.files;
        for event in events {
            match *event {
                ModelEvent::Merge { kind, depth, nodes } => {
                    writeln!(files[MERGES].pending, "{trial} {kind} {depth} {nodes}")?
                }
                ModelEvent::Change { estimated_trial } => {
                    writeln!(files[CHANGES].pending, "{trial} {estimated_trial}")?
                }
            }
        }
        Ok(())
    }

    /// Writes every collected line to disk now.
    pub fn flush(&mut self) -> io::Result<()> {
        let mut lines = self.lines()?;
        lines.write_out();
        match lines.error.take() {
            Some(e) => Err(e),
            None => Ok(()),
        }
    }
}

impl Drop for DataFiles {
    fn drop(&mut self) {
        drop(self.stop_flusher.take());
        if let Some(flusher) = self.flusher.take() {
            let _ = flusher.join();
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::learn::LearnerStats;

    #[test]
    fn lines_reach_the_disk_within_a_second_without_a_flush() {
        let dir = tempfile::tempdir().unwrap();
        let mut files = DataFiles::create(dir.path()).unwrap();
        let outcome = TrialOutcome {
            distances_mm: vec![12.5, 3.0, 1.0, 1.0, 1.0, 0.5, 0.25],
            failure: None,
            reached: true,
            seconds: 4.0,
            moved_deg: 3.0,
            proposed_deg: 3.0,
            start_distance_mm: Some(50.0),
        };
        files
            .record_trial(1, &outcome, &LearnerStats::default())
            .unwrap();
        std::thread::sleep(FLUSH_EVERY * 2);
        let two = std::fs::read_to_string(dir.path().join("2step")).unwrap();
        assert!(
            two.starts_with("1 3.000000 ") && two.ends_with('\n'),
            "{two}"
        );
        let nodes = std::fs::read_to_string(dir.path().join("nodes")).unwrap();
        assert!(
            nodes.starts_with("1 0 ") && nodes.lines().count() == 1,
            "{nodes}"
        );
    }
}
