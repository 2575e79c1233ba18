//! A one-node Slurm cluster for tests and benchmarks (`scripts/slurm-local.sh`), and what
//! they check a sweep by: the table without its speed column, data files without minutes.

#![allow(dead_code)]

use std::path::Path;
use std::process::{Command, Output};
use std::time::{Duration, Instant};

const PROJECT: &str = env!("CARGO_MANIFEST_DIR");
/// How long the array may take on a loaded machine before the test gives up.
pub const JOB_LIMIT: Duration = Duration::from_secs(300);

/// The cluster this test started; stopped (queue emptied first) when dropped.
pub struct Cluster {
    state: tempfile::TempDir,
    port: u16,
}

impl Cluster {
    fn script(&self, action: &str) -> Output {
        Command::new(Path::new(PROJECT).join("scripts/slurm-local.sh"))
            .arg(action)
            .env("EYEHAND_SLURM_DIR", self.state.path())
            .env("EYEHAND_SLURM_PORT", self.port.to_string())
            .env("EYEHAND_SLURM_WAIT", "60")
            .output()
            .expect("scripts/slurm-local.sh runs")
    }

    pub fn start() -> Cluster {
        let cluster = Cluster {
            state: tempfile::tempdir().unwrap(),
            port: 20000 + (std::process::id() % 10000) as u16 * 2,
        };
        let out = cluster.script("start");
        assert!(
            out.status.success(),
            "the local Slurm cluster must start (apt-get install slurm-wlm munge): {}{}",
            text(&out.stdout),
            text(&out.stderr)
        );
        cluster
    }

    /// A Slurm client command talking to this cluster, run in `cwd`.
    pub fn client(&self, program: &str, cwd: &Path) -> Command {
        let mut command = Command::new(program);
        command
            .env("SLURM_CONF", self.state.path().join("slurm.conf"))
            .current_dir(cwd);
        command
    }

    /// Waits until job `id` (every task of it) has left the queue.
    pub fn wait_for(&self, id: &str) {
        let started = Instant::now();
        loop {
            let out = self
                .client("squeue", Path::new("/"))
                .args(["-h", "-j", id])
                .output()
                .unwrap();
            let gone = text(&out.stderr).contains("Invalid job id");
            if gone || out.status.success() && out.stdout.is_empty() {
                return;
            }
            assert!(
                started.elapsed() < JOB_LIMIT,
                "job {id} still queued after {JOB_LIMIT:?}: {}",
                text(&out.stdout)
            );
            std::thread::sleep(Duration::from_millis(200));
        }
    }
}

impl Drop for Cluster {
    fn drop(&mut self) {
        let out = self.script("stop");
        if !out.status.success() {
            eprintln!(
                "stopping the cluster: {}{}",
                text(&out.stdout),
                text(&out.stderr)
            );
        }
    }
}

/// `eyehand ARGS…` run in `cwd`.
pub fn eyehand(args: &[&str], cwd: &Path) -> Output {
    Command::new(env!("CARGO_BIN_EXE_eyehand"))
        .args(args)
        .current_dir(cwd)
        .output()
        .unwrap()
}

/// Bytes a process wrote, as text.
pub fn text(bytes: &[u8]) -> String {
    String::from_utf8_lossy(bytes).to_string()
}

/// The table's rows without the trials/s column (the only one that may differ).
pub fn rows_but_speed(table: &str) -> Vec<Vec<String>> {
    table
        .lines()
        .filter(|l| l.starts_with("| ") && !l.starts_with("| cell"))
        .map(|l| {
            let mut fields: Vec<String> = l.split('|').map(|f| f.trim().to_string()).collect();
            fields.remove(9);
            fields
        })
        .collect()
}

/// A data file without its last (minutes) column.
pub fn without_minutes(path: &Path) -> Vec<String> {
    std::fs::read_to_string(path)
        .unwrap()
        .lines()
        .map(|l| l.rsplit_once(' ').unwrap().0.to_string())
        .collect()
}

/// `sbatch --parsable ARGS…` from `cwd`: the job id.
pub fn submit(cluster: &Cluster, args: &[&str], cwd: &Path) -> String {
    let out = cluster
        .client("sbatch", cwd)
        .arg("--parsable")
        .args(args)
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "sbatch {args:?}: {}",
        text(&out.stderr)
    );
    text(&out.stdout)
        .trim()
        .split(';')
        .next()
        .unwrap()
        .to_string()
}
