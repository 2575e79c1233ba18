//! A sweep through a real one-node Slurm cluster (`scripts/slurm-local.sh`): written with
//! `--slurm`, submitted with `sbatch` from another folder, waited for, gathered, and equal to
//! the same sweep run here (distances and node counts exactly, data files byte for byte but
//! the minutes column); a cell that lost its summary is resubmitted with the line gather
//! prints. Needs slurm-wlm and munge installed: the test fails, never skips, without them.

#[path = "common/slurm.rs"]
mod slurm;

use eyehand::experiment::study::shell_quote;
use slurm::{eyehand, rows_but_speed, submit, text, without_minutes, Cluster};
use std::path::{Path, PathBuf};
use std::time::Instant;

const PROJECT: &str = env!("CARGO_MANIFEST_DIR");

#[test]
fn a_sweep_on_a_local_slurm_cluster_equals_the_same_sweep_run_here() {
    let started = Instant::now();
    let cluster = Cluster::start();
    let work = tempfile::tempdir().unwrap();
    let config = PathBuf::from(PROJECT).join("configs/lin5.conf");
    let sweep = [
        "sweep",
        "--config",
        config.to_str().unwrap(),
        "--set",
        "split_error=1e-4,1e-5",
        "--set",
        "trials=300",
        "--seeds",
        "1,2",
        "--data",
        // A folder name a shell would expand or split, as a user may have one.
        "d s/it's \"q\" $HOME `x`",
    ];
    let local = eyehand(&sweep, work.path());
    assert!(local.status.success(), "{}", text(&local.stderr));
    let local_dir = PathBuf::from(text(&local.stdout).lines().next().unwrap());

    let written = eyehand(&[&sweep[..], &["--slurm"]].concat(), work.path());
    assert!(written.status.success(), "{}", text(&written.stderr));
    let script = text(&written.stdout).lines().next().unwrap().to_string();
    let slurm_dir = Path::new(&script).parent().unwrap().to_path_buf();
    assert_ne!(slurm_dir, local_dir);

    // Submitted from a folder that holds neither the configs nor the data.
    let elsewhere = tempfile::tempdir().unwrap();
    let job = submit(&cluster, &[&script], elsewhere.path());
    cluster.wait_for(&job);
    let gathered = eyehand(
        &["sweep", "gather", slurm_dir.to_str().unwrap()],
        elsewhere.path(),
    );
    assert!(
        gathered.status.success(),
        "{}{}",
        text(&gathered.stdout),
        text(&gathered.stderr)
    );
    let local_table = std::fs::read_to_string(local_dir.join("table.md")).unwrap();
    let slurm_table = std::fs::read_to_string(slurm_dir.join("table.md")).unwrap();
    assert_eq!(rows_but_speed(&local_table).len(), 4);
    assert_eq!(rows_but_speed(&slurm_table), rows_but_speed(&local_table));
    let logs = std::fs::read_dir(slurm_dir.join("logs")).unwrap().count();
    assert_eq!(logs, 4, "one log per task in logs/");
    for cell in 0..4 {
        for file in ["4step", "nodes"] {
            let path = |dir: &Path| dir.join(format!("cells/{cell}/{file}"));
            assert_eq!(
                without_minutes(&path(&slurm_dir)),
                without_minutes(&path(&local_dir))
            );
        }
    }

    // A cell that lost its summary is listed with the line that resubmits only it.
    std::fs::remove_file(slurm_dir.join("cells/2/summary.json")).unwrap();
    let partial = eyehand(
        &["sweep", "gather", slurm_dir.to_str().unwrap()],
        elsewhere.path(),
    );
    assert_eq!(partial.status.code(), Some(1));
    let stdout = text(&partial.stdout);
    let line = stdout
        .lines()
        .find_map(|l| l.strip_prefix("rerun them: "))
        .unwrap_or_else(|| panic!("a resubmit line in\n{stdout}"));
    assert_eq!(line, format!("sbatch --array=2 {}", shell_quote(&script)));
    let job = submit(&cluster, &["--array=2", &script], elsewhere.path());
    cluster.wait_for(&job);
    let again = eyehand(
        &["sweep", "gather", slurm_dir.to_str().unwrap()],
        elsewhere.path(),
    );
    assert!(again.status.success(), "{}", text(&again.stdout));
    let slurm_table = std::fs::read_to_string(slurm_dir.join("table.md")).unwrap();
    assert_eq!(rows_but_speed(&slurm_table), rows_but_speed(&local_table));
    drop(cluster);
    eprintln!(
        "local Slurm sweep test: {:.1} s",
        started.elapsed().as_secs_f64()
    );
}
