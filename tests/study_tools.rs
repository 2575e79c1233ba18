//! Plots, comparisons and sweeps: the PNG has its panels, a comparison reproduces separate
//! runs, a sweep expands exactly, its Slurm script runs a cell from any folder, bad study
//! requests are refused before anything runs, and a study passes signals on to its cells
//! and shows its progress on a terminal.

#[path = "common/slurm.rs"]
mod slurm;

use eyehand::experiment::plot::{plot_run, PANELS, PLOT_SIZE};
use eyehand::experiment::study::{
    compare_plan, shell_quote, sweep_plan, CompareRequest, Setting, StudyError,
};
use eyehand::experiment::{run, Config, RequestError, RunOptions};
use eyehand::learn::Method;
use slurm::{eyehand, text, without_minutes};
use std::path::Path;
use std::process::Command;

const EYEHAND: &str = env!("CARGO_BIN_EXE_eyehand");

fn configs() -> &'static Path {
    Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/configs"))
}

/// Decodes a PNG into (width, height, RGB rows).
fn decode(path: &Path) -> (u32, u32, Vec<u8>) {
    let decoder = png::Decoder::new(std::fs::File::open(path).unwrap());
    let mut reader = decoder.read_info().unwrap();
    let mut buffer = vec![0; reader.output_buffer_size()];
    let info = reader.next_frame(&mut buffer).unwrap();
    assert_eq!(info.color_type, png::ColorType::Rgb);
    buffer.truncate(info.buffer_size());
    (info.width, info.height, buffer)
}

#[test]
fn a_run_plot_is_a_png_with_every_panel_drawn() {
    let data = tempfile::tempdir().unwrap();
    let mut config = Config::default_config();
    config.method = Method::Ik;
    config.trials = 120;
    let options = RunOptions {
        events: vec!["rotate:60:30".parse().unwrap()],
        plot: true,
        ..RunOptions::new(config, data.path())
    };
    let folder = run(&options).unwrap().folder;
    let png = folder.join("plot.png");
    assert!(png.is_file(), "run writes plot.png unless told not to");
    std::fs::remove_file(&png).unwrap();
    assert_eq!(plot_run(&folder, 10).unwrap(), png);
    let (width, height, pixels) = decode(&png);
    assert_eq!((width, height), PLOT_SIZE);
    assert_eq!(PANELS.len(), 10);
    // 5 rows × 2 columns below the title: each panel's inner area has non-white pixels.
    let (rows, cols, title) = (5, 2, 40);
    for (i, name) in PANELS.iter().enumerate() {
        let (row, col) = (i / cols, i % cols);
        let (pw, ph) = (width / cols as u32, (height - title) / rows as u32);
        let (x0, y0) = (col as u32 * pw + pw / 4, title + row as u32 * ph + ph / 4);
        let drawn = (y0..y0 + ph / 2)
            .flat_map(|y| (x0..x0 + pw / 2).map(move |x| (x, y)))
            .filter(|&(x, y)| {
                let at = ((y * width + x) * 3) as usize;
                pixels[at..at + 3] != [255, 255, 255]
            })
            .count();
        assert!(drawn > 100, "panel `{name}` is drawn ({drawn} pixels)");
    }
}

#[test]
fn plot_refuses_a_folder_that_is_not_a_run() {
    let empty = tempfile::tempdir().unwrap();
    let out = Command::new(EYEHAND)
        .arg("plot")
        .arg(empty.path())
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
}

#[test]
fn compare_gives_the_numbers_of_separate_runs() {
    let data = tempfile::tempdir().unwrap();
    let config_dir = configs().display().to_string();
    let out = eyehand(
        &[
            "compare",
            "--methods",
            "ik,lin5",
            "--trials",
            "40",
            "--seeds",
            "1,2",
            "--configs",
            &config_dir,
            "--data",
            "d",
        ],
        data.path(),
    );
    assert!(out.status.success(), "{}", text(&out.stderr));
    let stderr = text(&out.stderr);
    for done in 1..=4 {
        assert!(
            stderr.contains(" finished after ")
                && stderr.contains(" trials/s (")
                && stderr.contains(&format!("({done} of 4 done, about ")),
            "a line per finished cell with its pace: {stderr}"
        );
    }
    let stdout = text(&out.stdout);
    let folder = Path::new(stdout.lines().next().unwrap());
    assert_eq!(
        folder,
        data.path().join("d/compare/0"),
        "absolute study folder"
    );
    assert!(folder.join("table.md").is_file() && folder.join("curves.png").is_file());
    assert!(
        stdout.contains("| ik | 2 |") && stdout.contains("| lin5 | 2 |"),
        "{stdout}"
    );
    assert!(
        stdout.contains("| nodes | trials to 1 mm | trials to 0.1 mm |\n"),
        "no recovery column without an event: {stdout}"
    );
    // Cells are methods × seeds in order, each in its fixed folder; no run id is taken.
    assert!(!data.path().join("d/ik").exists() && !data.path().join("d/lin5").exists());
    let alone = tempfile::tempdir().unwrap();
    for (method, seed, cell) in [("ik", 1, 0), ("lin5", 2, 3)] {
        let config = configs().join(format!("{method}.conf"));
        let out = eyehand(
            &[
                "run",
                "--config",
                config.to_str().unwrap(),
                "--method",
                method,
                "--trials",
                "40",
                "--seed",
                &seed.to_string(),
                "--quiet",
                "--no-plot",
            ],
            alone.path(),
        );
        assert!(out.status.success(), "{}", text(&out.stderr));
        let separate = alone.path().join(text(&out.stdout).trim());
        let compared = folder.join("cells").join(cell.to_string());
        assert_eq!(
            without_minutes(&separate.join("1step")),
            without_minutes(&compared.join("1step")),
            "{method} seed {seed}"
        );
    }
}

/// Each seed's trials to a 200-trial 4-step mean of 1 mm and 0.1 mm, and to recover after
/// the event: ik (which is not told of the camera turn) never recovers, lin5 does.
#[test]
fn compare_gives_each_seeds_trials_to_a_level_and_to_recover_after_the_event() {
    let data = tempfile::tempdir().unwrap();
    let config_dir = configs().display().to_string();
    let out = eyehand(
        &[
            "compare",
            "--methods",
            "ik,lin5",
            "--trials",
            "400",
            "--seeds",
            "1,2",
            "--event",
            "rotate:250:30",
            "--configs",
            &config_dir,
            "--data",
            "d",
        ],
        data.path(),
    );
    assert!(out.status.success(), "{}", text(&out.stderr));
    let stdout = text(&out.stdout);
    let lines: Vec<&str> = stdout.lines().collect();
    let header = lines
        .iter()
        .position(|l| l.starts_with("| method |"))
        .unwrap();
    assert!(
        lines[header - 2].starts_with("Distances: mean over the last 40 trials of each run"),
        "the table states its window: {stdout}"
    );
    assert!(
        lines[header].ends_with(
            "| nodes | trials to 1 mm | trials to 0.1 mm | trials to recover after rotate:250:30 |"
        ),
        "{stdout}"
    );
    // A column per feedback step taken (ik after the turn takes all ten).
    assert!(
        lines[header].contains("| 1 step (mm) | 2 steps |")
            && lines[header].contains("| 10 steps | trials/s |"),
        "{stdout}"
    );
    assert_eq!(lines[header + 1].matches("---|").count(), 18, "{stdout}");
    let row = |method: &str| {
        lines
            .iter()
            .find(|l| l.starts_with(&format!("| {method} |")))
            .unwrap_or_else(|| panic!("no {method} row: {stdout}"))
            .to_string()
    };
    assert!(
        row("ik").ends_with("| 200, 200 | 200, 200 | never, never |"),
        "{stdout}"
    );
    assert!(
        row("lin5").ends_with("| 222, 247 | never, never | 120, 121 |"),
        "{stdout}"
    );
    // The comparison's page: a panel per feedback step, a curve per cell, the table.
    let out = eyehand(&["report", lines[0]], data.path());
    assert!(out.status.success(), "{}", text(&out.stderr));
    let page = std::fs::read_to_string(data.path().join(lines[0]).join("report.html")).unwrap();
    assert!(page.contains(r#""kind":"study""#));
    assert_eq!(page.matches(r#""title":"distance after step "#).count(), 5);
    assert!(
        page.contains(r#""label":"3: lin5 seed 2""#),
        "a curve per cell"
    );
    assert!(
        page.contains("trials to recover after rotate:250:30"),
        "its table"
    );
}

#[test]
fn compare_plans_cover_every_method_and_seed_and_refuse_duplicates() {
    let mut request = CompareRequest {
        methods: vec![Method::Ik, Method::Lin5],
        trials: 10,
        seeds: vec![4, 5, 6],
        events: vec!["rotate:5:90".parse().unwrap()],
        sets: Vec::new(),
        configs: Some(configs().to_path_buf()),
    };
    let plan = compare_plan(&request).unwrap();
    assert_eq!(plan.cells.len(), 6);
    assert!(plan
        .cells
        .iter()
        .all(|c| c.request.events == request.events && c.request.trials == Some(10)));
    assert_eq!(
        (plan.cells[3].label.as_str(), plan.cells[3].seed),
        ("lin5", 4)
    );
    assert_eq!(
        plan.cells[3].request.config,
        Some(configs().join("lin5.conf"))
    );

    request.methods = vec![Method::Lin5, Method::Lin5];
    assert!(matches!(
        compare_plan(&request),
        Err(StudyError::Duplicate { .. })
    ));
    request.methods = vec![Method::Lin5];
    request.seeds = vec![1, 1];
    assert!(matches!(
        compare_plan(&request),
        Err(StudyError::Duplicate { .. })
    ));
    request.seeds = vec![1];
    request.configs = Some("/nonexistent".into());
    assert!(matches!(
        compare_plan(&request),
        Err(StudyError::MissingConfigs { .. })
    ));
}

#[test]
fn a_sweep_expands_settings_and_seeds_exactly() {
    let config = configs().join("ik.conf");
    let sets: Vec<Setting> = vec![
        "split_error=1e-4,1e-5".parse().unwrap(),
        "bin_size=3,5,8".parse().unwrap(),
    ];
    let plan = sweep_plan(&config, &sets, &[1, 2]).unwrap();
    assert_eq!(plan.cells.len(), 2 * 3 * 2);
    let mut seen: Vec<(String, u64)> = plan
        .cells
        .iter()
        .map(|c| (c.label.clone(), c.seed))
        .collect();
    seen.sort();
    seen.dedup();
    assert_eq!(seen.len(), 12, "every combination once");
    let last = plan.cells.last().unwrap();
    assert_eq!(
        (last.label.as_str(), last.seed),
        ("split_error=1e-5 bin_size=8", 2)
    );
    assert_eq!(last.request.seed, Some(2));
    assert_eq!(
        last.request.sets,
        [
            ("split_error".into(), "1e-5".into()),
            ("bin_size".into(), "8".into())
        ]
    );
}

#[test]
fn a_bad_sweep_fails_before_any_run() {
    let config = configs().join("ik.conf");
    for bad in ["split_eror=1e-4", "tree_depth=2.5", "tree_depth=99"] {
        let err = sweep_plan(&config, &[bad.parse().unwrap()], &[1]).unwrap_err();
        let StudyError::Cell { source, .. } = &err else {
            panic!("{bad}: {err:?}");
        };
        assert!(
            matches!(
                **source,
                RequestError::Set { .. } | RequestError::Combined { .. }
            ),
            "{bad}: {err:?}"
        );
    }
    let twice: Vec<Setting> = vec!["trials=100".parse().unwrap(), "trials=200".parse().unwrap()];
    assert!(matches!(
        sweep_plan(&config, &twice, &[1]),
        Err(StudyError::RepeatedSetting { .. })
    ));
    let seed: Vec<Setting> = vec!["seed=1,2,3".parse().unwrap()];
    assert!(matches!(
        sweep_plan(&config, &seed, &[1]),
        Err(StudyError::SeedSetting)
    ));
    // Settings are checked together on each cell's final config, in either order.
    for pair in [
        ["feedback_steps=2", "min_feedback_steps=1"],
        ["min_feedback_steps=1", "feedback_steps=2"],
    ] {
        let sets: Vec<Setting> = pair.iter().map(|s| s.parse().unwrap()).collect();
        assert!(sweep_plan(&config, &sets, &[1]).is_ok(), "{pair:?}");
    }

    let data = tempfile::tempdir().unwrap();
    let ik = config.to_str().unwrap();
    let cases: &[&[&str]] = &[
        &[
            "sweep",
            "--config",
            ik,
            "--set",
            "no_such_entry=1,2",
            "--seeds",
            "1..3",
        ],
        &["sweep", "--config", ik, "--set", "seed=1,2,3"],
        &[
            "sweep",
            "--config",
            ik,
            "--set",
            "trials=100",
            "--set",
            "trials=200",
        ],
        &[
            "sweep",
            "--config",
            ik,
            "--set",
            "trials=10",
            "--seeds",
            "1..18446744073709551615",
            "--slurm",
        ],
        &["compare", "--methods", "lin5,lin5", "--trials", "10"],
        &[
            "compare",
            "--methods",
            "ik",
            "--trials",
            "10",
            "--seeds",
            "1,1",
        ],
        &[
            "compare",
            "--methods",
            "ik",
            "--trials",
            "10",
            "--configs",
            "/nonexistent",
        ],
        &[
            "compare",
            "--methods",
            "ik",
            "--trials",
            "10",
            "--seeds",
            "1..1000000",
        ],
        &["sweep", "gather", "/nonexistent"],
    ];
    for args in cases {
        let out = eyehand(args, data.path());
        assert_eq!(
            out.status.code(),
            Some(2),
            "{args:?}: {}",
            text(&out.stderr)
        );
        assert!(text(&out.stderr).starts_with("eyehand: "), "{args:?}");
    }
    // A bad per-method config is bad input too.
    let bad_configs = data.path().join("configs");
    std::fs::create_dir(&bad_configs).unwrap();
    std::fs::write(bad_configs.join("ik.conf"), "trials ten\n").unwrap();
    let out = eyehand(
        &[
            "compare",
            "--methods",
            "ik",
            "--trials",
            "10",
            "--configs",
            "configs",
        ],
        data.path(),
    );
    assert_eq!(out.status.code(), Some(2), "{}", text(&out.stderr));
    assert_eq!(
        std::fs::read_dir(data.path()).unwrap().count(),
        1,
        "nothing ran, no data folder made"
    );
}

#[test]
fn the_slurm_script_runs_a_cell_from_any_folder_and_gather_lists_the_rest() {
    let project = tempfile::tempdir().unwrap();
    let ik = configs().join("ik.conf");
    let out = eyehand(
        &[
            "sweep",
            "--config",
            ik.to_str().unwrap(),
            "--set",
            "bin_size=3,5",
            "--set",
            "trials=20",
            "--seeds",
            "1,2",
            "--data",
            "my data",
            "--slurm",
            "--slurm-time",
            "0:10:00",
            "--slurm-partition",
            "short",
            "--slurm-extra",
            "--qos=low",
        ],
        project.path(),
    );
    assert!(out.status.success(), "{}", text(&out.stderr));
    let script = std::path::PathBuf::from(text(&out.stdout).lines().next().unwrap());
    let study = project.path().join("my data/sweep/0");
    assert_eq!(script, study.join("sweep.sbatch"));
    let body = std::fs::read_to_string(&script).unwrap();
    for line in [
        "#SBATCH --array=0-3".to_string(),
        format!("#SBATCH --chdir=\"{}\"", study.display()),
        format!("#SBATCH --output=\"{}/logs/%A_%a.out\"", study.display()),
        "#SBATCH --mem=256M".into(),
        "#SBATCH --time=0:10:00".into(),
        "#SBATCH --partition=short".into(),
        "#SBATCH --qos=low".into(),
    ] {
        assert!(body.lines().any(|l| l == line), "`{line}` in\n{body}");
    }
    assert!(
        body.contains(EYEHAND),
        "the binary's absolute path:\n{body}"
    );
    assert!(Command::new("bash")
        .arg("-n")
        .arg(&script)
        .status()
        .unwrap()
        .success());

    // Outside Slurm, from another folder: without a cell it says how to run it; with one it
    // runs that cell into its fixed folder.
    let elsewhere = tempfile::tempdir().unwrap();
    let bare = Command::new("bash")
        .arg(&script)
        .current_dir(elsewhere.path())
        .output()
        .unwrap();
    assert_eq!(bare.status.code(), Some(2));
    assert!(
        text(&bare.stderr).contains("sbatch"),
        "{}",
        text(&bare.stderr)
    );
    let one = Command::new("bash")
        .arg(&script)
        .arg("1")
        .current_dir(elsewhere.path())
        .output()
        .unwrap();
    assert!(one.status.success(), "{}", text(&one.stderr));
    assert!(study.join("cells/1/summary.json").is_file());

    let out = eyehand(
        &["sweep", "gather", study.to_str().unwrap()],
        elsewhere.path(),
    );
    assert_eq!(out.status.code(), Some(1), "3 cells are not done");
    let stdout = text(&out.stdout);
    assert!(
        stdout.contains("| 1 | bin_size=3 trials=20 | 2 |"),
        "{stdout}"
    );
    assert!(stdout.contains("3 of 4 cells did not finish"), "{stdout}");
    let rerun = format!("sbatch --array=0,2-3 '{}'", script.display());
    assert!(stdout.lines().any(|l| l.ends_with(&rerun)), "{stdout}");
    assert!(study.join("table.md").is_file() && study.join("curves.png").is_file());
}

/// Processes whose command line mentions `needle` (other than this test's).
fn processes_mentioning(needle: &str) -> Vec<u32> {
    std::fs::read_dir("/proc")
        .unwrap()
        .filter_map(|e| e.ok()?.file_name().to_str()?.parse::<u32>().ok())
        .filter(|&pid| pid != std::process::id())
        .filter(|pid| {
            std::fs::read(format!("/proc/{pid}/cmdline"))
                .is_ok_and(|c| String::from_utf8_lossy(&c).contains(needle))
        })
        .collect()
}

#[test]
fn an_interrupted_sweep_stops_its_cells_and_waits_for_them() {
    for (signal, code) in [("-INT", 130), ("-TERM", 143)] {
        let data = tempfile::tempdir().unwrap();
        let study = data.path().join("sweep/0");
        let needle = study.display().to_string();
        let ik = configs().join("ik.conf");
        let mut sweep = Command::new(EYEHAND)
            .args(["sweep", "--config", ik.to_str().unwrap()])
            .args(["--set", "trials=10000000", "--seeds", "1,2", "--data"])
            .arg(data.path())
            .stdout(std::process::Stdio::null())
            .stderr(std::process::Stdio::null())
            .spawn()
            .unwrap();
        let started = std::time::Instant::now();
        while !study.join("cells/0/1step").exists() {
            assert!(started.elapsed().as_secs() < 30, "the cells never started");
            std::thread::sleep(std::time::Duration::from_millis(50));
        }
        assert!(
            !processes_mentioning(&needle).is_empty(),
            "cells run as processes"
        );
        let sent = Command::new("kill")
            .args([signal, &sweep.id().to_string()])
            .status();
        assert!(sent.unwrap().success());
        let status = sweep.wait().unwrap();
        assert_eq!(status.code(), Some(code), "{signal}: exits after its cells");
        assert!(
            processes_mentioning(&needle).is_empty(),
            "{signal}: no cell is left running"
        );
        // The cells stopped after a trial and said so; gather does not count them as done.
        let summary = std::fs::read_to_string(study.join("cells/0/summary.json")).unwrap();
        assert!(summary.contains("\"interrupted\": true"), "{summary}");
        let out = eyehand(&["sweep", "gather", &needle], data.path());
        assert_eq!(out.status.code(), Some(1));
        assert!(
            text(&out.stdout).contains("2 of 2 cells did not finish"),
            "{}",
            text(&out.stdout)
        );
    }
}

#[test]
fn a_killed_sweep_takes_its_cells_with_it() {
    let data = tempfile::tempdir().unwrap();
    let study = data.path().join("sweep/0");
    let needle = study.display().to_string();
    let ik = configs().join("ik.conf");
    let mut sweep = Command::new(EYEHAND)
        .args(["sweep", "--config", ik.to_str().unwrap()])
        .args(["--set", "trials=10000000", "--seeds", "1,2", "--data"])
        .arg(data.path())
        .stdout(std::process::Stdio::null())
        .stderr(std::process::Stdio::null())
        .spawn()
        .unwrap();
    let started = std::time::Instant::now();
    while !study.join("cells/0/1step").exists() {
        assert!(started.elapsed().as_secs() < 30, "the cells never started");
        std::thread::sleep(std::time::Duration::from_millis(50));
    }
    assert!(!processes_mentioning(&needle).is_empty(), "cells run");
    sweep.kill().unwrap(); // SIGKILL: the study passes nothing on
    sweep.wait().unwrap();
    let killed = std::time::Instant::now();
    while !processes_mentioning(&needle).is_empty() {
        assert!(
            killed.elapsed().as_secs() < 10,
            "cells left running after their study was killed: {:?}",
            processes_mentioning(&needle)
        );
        std::thread::sleep(std::time::Duration::from_millis(50));
    }
    // Each cell got SIGTERM, finished its trial and wrote its summary, marked interrupted.
    let summary = std::fs::read_to_string(study.join("cells/0/summary.json")).unwrap();
    assert!(summary.contains("\"interrupted\": true"), "{summary}");
}

#[test]
fn a_comparison_for_slurm_runs_by_hand_and_gathers_like_a_sweep() {
    let project = tempfile::tempdir().unwrap();
    let configs = configs().display().to_string();
    let out = eyehand(
        &[
            "compare",
            "--methods",
            "ik",
            "--trials",
            "20",
            "--seeds",
            "1,2",
            "--configs",
            &configs,
            "--data",
            "d",
            "--slurm",
        ],
        project.path(),
    );
    assert!(out.status.success(), "{}", text(&out.stderr));
    let script = std::path::PathBuf::from(text(&out.stdout).lines().next().unwrap());
    assert_eq!(script, project.path().join("d/compare/0/compare.sbatch"));
    for cell in ["0", "1"] {
        let ran = Command::new("bash")
            .arg(&script)
            .arg(cell)
            .output()
            .unwrap();
        assert!(ran.status.success(), "{}", text(&ran.stderr));
    }
    let study = script.parent().unwrap().to_str().unwrap();
    let out = eyehand(&["compare", "gather", study], project.path());
    assert!(out.status.success(), "{}", text(&out.stderr));
    assert!(
        text(&out.stdout).contains("| ik | 2 |"),
        "{}",
        text(&out.stdout)
    );
    // A cell folder holding another run (seed 2's summary in seed 1's cell) is not
    // gathered under the cell's label.
    let cells = script.parent().unwrap().join("cells");
    std::fs::copy(cells.join("1/summary.json"), cells.join("0/summary.json")).unwrap();
    let out = eyehand(&["compare", "gather", study], project.path());
    assert_eq!(out.status.code(), Some(1), "{}", text(&out.stderr));
    assert!(
        text(&out.stdout).contains("| ik | 1 |")
            && text(&out.stdout).contains(
                "cell 0 (ik, seed 1): its summary.json is another run's (method ik, seed 2; the cell runs method ik, seed 1)"
            ),
        "{}",
        text(&out.stdout)
    );
}

/// A study whose `cells.json` lists no cells is no study: `gather` refuses it rather than
/// writing an empty table.
#[test]
fn gather_refuses_a_study_without_cells() {
    let project = tempfile::tempdir().unwrap();
    let lin5 = configs().join("lin5.conf");
    let args = [
        "sweep",
        "--config",
        lin5.to_str().unwrap(),
        "--set",
        "trials=10",
    ];
    let out = eyehand(
        &[&args[..], &["--data", "d", "--slurm"]].concat(),
        project.path(),
    );
    assert!(out.status.success(), "{}", text(&out.stderr));
    let study = project.path().join("d/sweep/0");
    let plan_path = study.join("cells.json");
    let mut plan: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&plan_path).unwrap()).unwrap();
    plan["cells"] = serde_json::json!([]);
    std::fs::write(&plan_path, plan.to_string()).unwrap();
    let gathered = eyehand(
        &["sweep", "gather", study.to_str().unwrap()],
        project.path(),
    );
    assert_eq!(
        gathered.status.code(),
        Some(2),
        "{}",
        text(&gathered.stdout)
    );
    assert!(
        text(&gathered.stderr).contains("cells.json lists no cells"),
        "{}",
        text(&gathered.stderr)
    );
    assert!(!study.join("table.md").exists(), "no empty table written");
}

/// Runs `compare` under `script`, whose pseudo-terminal is the study's stderr, and returns
/// what the terminal was sent.
fn compare_on_a_terminal(data: &Path) -> String {
    let command = format!(
        "{} compare --methods lin5,lin8 --trials 2000 --seeds 1 --configs {} --data {}",
        shell_quote(EYEHAND),
        shell_quote(&configs().display().to_string()),
        shell_quote(&data.display().to_string())
    );
    let out = Command::new("script")
        .args(["-q", "-e", "-c", &command, "/dev/null"])
        .stdin(std::process::Stdio::null())
        .output()
        .expect("script (util-linux) runs the study on a pseudo-terminal");
    assert!(out.status.success(), "{}", text(&out.stderr));
    text(&out.stdout)
}

#[test]
fn a_study_on_a_terminal_shows_cells_done_and_trials_per_second() {
    let data = tempfile::tempdir().unwrap();
    let screen = compare_on_a_terminal(data.path());
    // The terminal's redraws are separated by carriage returns; a bar is one of them.
    let bar = screen
        .split(['\r', '\n'])
        .find(|shown| shown.contains("2/2 cells"))
        .unwrap_or_else(|| panic!("no bar of cells done in {screen:?}"));
    assert!(
        bar.contains(" running, ") && bar.contains(" trials/s"),
        "no cells running and trials per second in the bar {bar:?}"
    );
    assert!(
        screen.contains("cell 1 finished"),
        "no line per cell in {screen:?}"
    );
}

#[test]
fn compare_set_changes_every_cells_config_and_a_bad_entry_is_refused_before_any_run() {
    let mut request = CompareRequest {
        methods: vec![Method::Lin5, Method::Mlp],
        trials: 10,
        seeds: vec![1, 2],
        events: Vec::new(),
        sets: vec![("camera_noise_px".into(), "0.25".into())],
        configs: Some(configs().to_path_buf()),
    };
    let plan = compare_plan(&request).unwrap();
    let configs = plan.check().unwrap();
    assert_eq!(configs.len(), 4);
    assert!(
        configs.iter().all(|c| c.camera_noise_px == 0.25),
        "every cell sets it"
    );
    request.sets.clear();
    let plain = compare_plan(&request).unwrap().check().unwrap();
    assert!(
        plain.iter().all(|c| c.camera_noise_px == 0.0),
        "the default without --set"
    );
    request.sets = vec![("no_such_entry".into(), "1".into())];
    let refused = compare_plan(&request).unwrap_err().to_string();
    assert!(refused.contains("no_such_entry"), "{refused}");
}
