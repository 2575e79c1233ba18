//! Running a study's cells: each as its own process (its own memory figures, and the same
//! path a Slurm task takes), started by a [`CellLauncher`] that names only the binary and the
//! subcommand that runs one cell; several side by side; signals passed on to them.

use super::cell_progress::StudyProgress;
use super::plan::StudyFolder;
use super::signals::{forward, Interrupts};
use super::StudyError;
use crate::experiment::{run, RunError, RunResult, StopRequest};
use std::os::unix::process::CommandExt;
use std::path::{Path, PathBuf};
use std::process::{Child, Command, Stdio};
use std::time::Duration;
use std::time::Instant;

/// How often the running cells are looked at.
const POLL: Duration = Duration::from_millis(20);

/// How to start the process that runs one cell: `PROGRAM ARGS… STUDY_FOLDER INDEX`.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct CellLauncher {
    /// The binary, absolute.
    pub program: PathBuf,
    /// The arguments before the study folder and the cell index.
    pub args: Vec<String>,
}

impl CellLauncher {
    /// The command line up to (without) the cell index, shell-quoted.
    pub fn command_line(&self, study: &Path) -> String {
        std::iter::once(self.program.display().to_string())
            .chain(self.args.iter().cloned())
            .chain([study.display().to_string()])
            .map(|a| shell_quote(&a))
            .collect::<Vec<_>>()
            .join(" ")
    }

    fn command(&self, study: &Path, index: usize) -> Command {
        let mut command = Command::new(&self.program);
        command.args(&self.args).arg(study).arg(index.to_string());
        command
    }
}

/// `arg` quoted for a POSIX shell.
pub fn shell_quote(arg: &str) -> String {
    let plain = !arg.is_empty()
        && arg
            .chars()
            .all(|c| c.is_ascii_alphanumeric() || "-_./=:,+".contains(c));
    if plain {
        arg.to_string()
    } else {
        format!("'{}'", arg.replace('\'', r"'\''"))
    }
}

/// Why running one cell in this process failed.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum CellRunError {
    /// The study or the cell is not there or not valid.
    #[error(transparent)]
    Study(#[from] StudyError),
    /// The run failed.
    #[error(transparent)]
    Run(#[from] RunError),
}

/// Runs cell `index` of the study in `folder` here, into its fixed folder `cells/<index>/`
/// (emptied first, so a rerun overwrites it); `summary.json` is written last. `stop` ends
/// it after its current trial, as it does a run.
pub fn run_cell(
    folder: &StudyFolder,
    index: usize,
    stop: StopRequest,
) -> Result<RunResult, CellRunError> {
    let plan = folder.plan()?;
    let cell = plan.cells.get(index).ok_or(StudyError::NoSuchCell {
        index,
        cells: plan.cells.len(),
    })?;
    let mut options = cell.request.options().map_err(|source| StudyError::Cell {
        index,
        label: cell.label.clone(),
        seed: cell.seed,
        source: Box::new(source),
    })?;
    options.stop = stop;
    Ok(run(&options)?)
}

/// How a local run of a study's cells ended.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum LocalRunEnd {
    /// Every cell was started and has ended (gather tells which finished).
    Completed,
    /// A signal (SIGINT or SIGTERM) came: it was passed to the running cells, which were
    /// waited for; no further cell was started.
    Interrupted(i32),
}

/// Runs every cell of the study, `jobs` at a time, each as `launcher`'s process with its
/// output in `logs/local_<i>.out`, and says on stderr as each cell ends (how it ended, how
/// long it took, its trials and trials per second, how many are done and about how long the
/// rest will take at the cells' pace so far). If a cell cannot be started, none after it is, and
/// the running ones are waited for before the error is returned.
pub fn run_locally(
    folder: &StudyFolder,
    cells: usize,
    launcher: &CellLauncher,
    jobs: usize,
) -> Result<LocalRunEnd, StudyError> {
    let mut interrupts = Interrupts::catch().map_err(StudyError::io("signal handlers"))?;
    let mut next = 0;
    let mut done = 0;
    let mut cell_seconds = 0.0;
    let mut running: Vec<(usize, Child, Instant)> = Vec::new();
    let mut forwarded = None;
    let mut failure = None;
    let mut progress = StudyProgress::new(cells);
    let mut finished = Vec::new();
    let mut shown_running = 0;
    loop {
        for signal in interrupts.received() {
            for (_, child, _) in &running {
                forward(child.id(), signal);
            }
            forwarded = Some(signal);
        }
        let launching = forwarded.is_none() && failure.is_none();
        while launching && next < cells && running.len() < jobs.max(1) {
            match start(folder, launcher, next) {
                Ok(child) => running.push((next, child, Instant::now())),
                Err(e) => {
                    failure = Some(e);
                    break;
                }
            }
            next += 1;
        }
        if running.len() != shown_running {
            shown_running = running.len();
            progress.running(shown_running);
        }
        // A child that cannot be waited for is dropped: it was ours and is reaped on exit.
        running.retain_mut(|(index, child, started)| match child.try_wait() {
            Ok(None) => true,
            ended => {
                done += 1;
                let seconds = started.elapsed().as_secs_f64();
                cell_seconds += seconds;
                let left = (cells - done) as f64 * cell_seconds / done as f64 / jobs.max(1) as f64;
                let ended = CellEnd {
                    index: *index,
                    ended,
                    seconds,
                    done,
                    cells,
                    left,
                };
                finished.push(ended.line(folder));
                false
            }
        });
        for (line, trials) in finished.drain(..) {
            shown_running = running.len();
            progress.cell_done(&line, trials, shown_running);
        }
        let more = forwarded.is_none() && failure.is_none() && next < cells;
        if running.is_empty() && !more {
            break;
        }
        std::thread::sleep(POLL);
    }
    progress.finish();
    match (failure, forwarded) {
        (Some(e), _) => Err(e),
        (None, Some(signal)) => Ok(LocalRunEnd::Interrupted(signal)),
        (None, None) => Ok(LocalRunEnd::Completed),
    }
}

/// How one cell ended, and where the study stands after it.
struct CellEnd {
    index: usize,
    ended: std::io::Result<Option<std::process::ExitStatus>>,
    seconds: f64,
    done: usize,
    cells: usize,
    left: f64,
}

impl CellEnd {
    /// The line that says it, and the cell's trials (0 when its summary cannot be read).
    fn line(self, folder: &StudyFolder) -> (String, u64) {
        let how = match self.ended {
            Ok(Some(status)) if status.success() => "finished".to_string(),
            Ok(Some(status)) => format!("ended with {status}"),
            _ => "could not be waited for".to_string(),
        };
        let summary = super::gather::read_summary(&folder.cell(self.index)).ok();
        let pace = summary.as_ref().map_or(String::new(), |s| {
            format!(
                ": {} trials at {:.0} trials/s",
                s.trials, s.trials_per_second
            )
        });
        let line = format!(
            "eyehand: cell {} {how} after {:.2} s{pace} ({} of {} done, about {:.0} s left; \
             log: {})",
            self.index,
            self.seconds,
            self.done,
            self.cells,
            self.left,
            folder.local_log(self.index).display()
        );
        (line, summary.map_or(0, |s| s.trials as u64))
    }
}

fn start(folder: &StudyFolder, launcher: &CellLauncher, index: usize) -> Result<Child, StudyError> {
    let log_path = folder.local_log(index);
    let log = std::fs::File::create(&log_path).map_err(StudyError::io(&log_path))?;
    let err = log.try_clone().map_err(StudyError::io(&log_path))?;
    // Its own process group: a terminal's Ctrl-C reaches the study alone, which passes it on
    // once to every cell. A study that dies without passing a signal on (SIGKILL) takes its
    // cells with it: each gets SIGTERM when its parent dies.
    let mut command = launcher.command(&folder.0, index);
    let parent = std::process::id();
    // SAFETY: between fork and exec the hook calls only prctl(2), getppid(2) and _exit(2),
    // which are async-signal-safe, and allocates nothing.
    unsafe {
        command.pre_exec(move || {
            if libc::prctl(libc::PR_SET_PDEATHSIG, libc::SIGTERM) != 0 {
                return Err(std::io::Error::last_os_error());
            }
            if libc::getppid() as u32 != parent {
                libc::_exit(128 + libc::SIGTERM); // the study died before the call
            }
            Ok(())
        });
    }
    command
        .process_group(0)
        .stdin(Stdio::null())
        .stdout(log)
        .stderr(err)
        .spawn()
        .map_err(StudyError::io(&launcher.program))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn arguments_are_quoted_only_when_needed() {
        assert_eq!(shell_quote("split_error=1e-5"), "split_error=1e-5");
        assert_eq!(shell_quote("/tmp/my data"), "'/tmp/my data'");
        assert_eq!(shell_quote("it's"), r"'it'\''s'");
        assert_eq!(shell_quote(""), "''");
    }
}
