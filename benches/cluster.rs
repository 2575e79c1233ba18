//! `cargo bench --bench cluster`: a 40-cell sweep (`split_error` at 10 values × seeds 1..4,
//! 300 trials, configs/lin5.conf) run here and through a one-node Slurm cluster on this
//! machine (`scripts/slurm-local.sh`); prints docs/CLUSTER.md's table: cells done, wall
//! times, and whether gather's table equals the local one (distances and nodes exactly).

#[path = "../tests/common/slurm.rs"]
mod slurm;

use slurm::{rows_but_speed, submit, text, Cluster};
use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::Instant;

const EYEHAND: &str = env!("CARGO_BIN_EXE_eyehand");
const SPLIT_ERRORS: &str = "split_error=1e-3,5e-4,2e-4,1e-4,5e-5,2e-5,1e-5,5e-6,2e-6,1e-6";

/// Runs `eyehand ARGS…` in `cwd`; its first stdout line and its exit code.
fn eyehand(args: &[&str], cwd: &Path) -> (String, Option<i32>) {
    let out = Command::new(EYEHAND)
        .args(args)
        .current_dir(cwd)
        .output()
        .unwrap();
    let first = text(&out.stdout).lines().next().unwrap_or("").to_string();
    (first, out.status.code())
}

fn main() {
    let cluster = Cluster::start();
    let work = tempfile::tempdir().unwrap();
    let config = Path::new(env!("CARGO_MANIFEST_DIR")).join("configs/lin5.conf");
    let sweep = [
        "sweep",
        "--config",
        config.to_str().unwrap(),
        "--set",
        SPLIT_ERRORS,
        "--set",
        "trials=300",
        "--seeds",
        "1..4",
        "--data",
        "data",
    ];
    let clock = Instant::now();
    let (local_dir, code) = eyehand(&sweep, work.path());
    assert_eq!(code, Some(0), "the local sweep finishes");
    let local_seconds = clock.elapsed().as_secs_f64();

    let clock = Instant::now();
    let (script, code) = eyehand(&[&sweep[..], &["--slurm"]].concat(), work.path());
    assert_eq!(code, Some(0));
    let job = submit(&cluster, &[&script], Path::new("/"));
    cluster.wait_for(&job);
    let slurm_dir = PathBuf::from(&script).parent().unwrap().to_path_buf();
    let (_, gathered) = eyehand(
        &["sweep", "gather", slurm_dir.to_str().unwrap()],
        work.path(),
    );
    let slurm_seconds = clock.elapsed().as_secs_f64();

    let table = |dir: &str| std::fs::read_to_string(Path::new(dir).join("table.md")).unwrap();
    let local_rows = rows_but_speed(&table(&local_dir));
    let slurm_rows = rows_but_speed(&table(slurm_dir.to_str().unwrap()));
    println!("| run | cells | done | wall (s) | table equals the local one |");
    println!("|---|---|---|---|---|");
    println!(
        "| here (one cell per core) | 40 | {} | {local_seconds:.1} | - |",
        local_rows.len()
    );
    println!(
        "| local Slurm (sbatch → gather, exit {}) | 40 | {} | {slurm_seconds:.1} | {} |",
        gathered.unwrap_or(-1),
        slurm_rows.len(),
        if slurm_rows == local_rows {
            "yes"
        } else {
            "NO"
        }
    );
    assert_eq!(
        slurm_rows, local_rows,
        "gather's table equals the local sweep's"
    );
}
