//! Plots, comparisons and sweeps: the PNG has its panels, a comparison reproduces separate
//! runs, a sweep expands exactly and its Slurm script runs the same cells.

use eyehand::experiment::plot::{plot_run, PANELS, PLOT_SIZE};
use eyehand::experiment::{
    compare_cells, run, run_cells, slurm_script, sweep_cells, CompareRequest, Config, RunOptions,
    Setting,
};
use eyehand::learn::Method;
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
    let out = Command::new(EYEHAND)
        .args([
            "compare",
            "--methods",
            "ik,lin5",
            "--trials",
            "40",
            "--seeds",
            "1,2",
            "--configs",
        ])
        .arg(configs())
        .arg("--data")
        .arg(data.path())
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let stdout = String::from_utf8_lossy(&out.stdout);
    let folder = Path::new(stdout.lines().next().unwrap());
    assert!(folder.join("table.md").is_file() && folder.join("curves.png").is_file());
    assert!(
        stdout.contains("| ik | 2 |") && stdout.contains("| lin5 | 2 |"),
        "{stdout}"
    );

    let alone = tempfile::tempdir().unwrap();
    for (method, seed) in [("ik", 1), ("lin5", 2)] {
        let out = Command::new(EYEHAND)
            .args(["run", "--config"])
            .arg(configs().join(format!("{method}.conf")))
            .args([
                "--method",
                method,
                "--trials",
                "40",
                "--seed",
                &seed.to_string(),
                "--quiet",
                "--no-plot",
                "--data",
            ])
            .arg(alone.path())
            .output()
            .unwrap();
        assert!(out.status.success());
        let folder = String::from_utf8_lossy(&out.stdout).trim().to_string();
        let separate = std::fs::read_to_string(Path::new(&folder).join("1step")).unwrap();
        let compared_folder = data
            .path()
            .join(method)
            .join(if seed == 1 { "0" } else { "1" });
        let compared = std::fs::read_to_string(compared_folder.join("1step")).unwrap();
        let strip = |t: &str| {
            t.lines()
                .map(|l| l.rsplit_once(' ').unwrap().0.to_string())
                .collect::<Vec<_>>()
        };
        assert_eq!(strip(&separate), strip(&compared), "{method} seed {seed}");
    }
}

#[test]
fn compare_cells_cover_every_method_and_seed() {
    let request = CompareRequest {
        methods: vec![Method::Ik, Method::Lin5],
        trials: 10,
        seeds: vec![4, 5, 6],
        events: vec!["rotate:5:90".parse().unwrap()],
        data: "d".into(),
        configs: configs().to_path_buf(),
    };
    let cells = compare_cells(&request);
    assert_eq!(cells.len(), 6);
    assert!(cells
        .iter()
        .all(|c| c.args.windows(2).any(|w| w == ["--event", "rotate:5:90"])));
    assert_eq!(cells[3].label, "lin5");
    assert_eq!(cells[3].seed, 4);
}

#[test]
fn a_sweep_expands_settings_and_seeds_exactly() {
    let config = configs().join("ik.conf");
    let sets: Vec<Setting> = vec![
        "split_error=1e-4,1e-5".parse().unwrap(),
        "bin_size=3,5,8".parse().unwrap(),
    ];
    let cells = sweep_cells(&config, &sets, &[1, 2], Path::new("d")).unwrap();
    assert_eq!(cells.len(), 2 * 3 * 2);
    let mut seen: Vec<(String, u64)> = cells.iter().map(|c| (c.label.clone(), c.seed)).collect();
    seen.sort();
    seen.dedup();
    assert_eq!(seen.len(), 12, "every combination once");
    assert!(cells
        .iter()
        .any(|c| c.label == "split_error=1e-5 bin_size=8" && c.seed == 2));
    assert!(cells[0]
        .args
        .windows(2)
        .any(|w| w == ["--set", "split_error=1e-4"]));
}

#[test]
fn a_bad_sweep_setting_fails_before_any_run() {
    let config = configs().join("ik.conf");
    for bad in ["split_eror=1e-4", "tree_depth=2.5", "tree_depth=99"] {
        let err = sweep_cells(&config, &[bad.parse().unwrap()], &[1], Path::new("d")).unwrap_err();
        assert!(err.contains(bad.split('=').next().unwrap()), "{err}");
    }
    let data = tempfile::tempdir().unwrap();
    let out = Command::new(EYEHAND)
        .args(["sweep", "--config"])
        .arg(&config)
        .args(["--set", "no_such_entry=1,2", "--seeds", "1..3", "--data"])
        .arg(data.path())
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    assert_eq!(
        std::fs::read_dir(data.path()).unwrap().count(),
        0,
        "nothing ran, no folder made"
    );
}

#[test]
fn the_slurm_script_runs_each_cell_with_the_same_command_line() {
    let config = configs().join("ik.conf");
    let cells = sweep_cells(
        &config,
        &["bin_size=3,5".parse().unwrap()],
        &[1, 2, 3],
        Path::new("/data/my runs"),
    )
    .unwrap();
    let script = slurm_script(&cells, "eyehand");
    assert!(script.contains("#SBATCH --array=0-5"));
    for (i, cell) in cells.iter().enumerate() {
        let line = script
            .lines()
            .find(|l| l.trim_start().starts_with(&format!("{i})")))
            .unwrap();
        assert_eq!(
            line.trim(),
            format!("{i}) exec {} ;;", cell.command_line("eyehand"))
        );
        assert!(line.contains("'/data/my runs'"), "paths are quoted: {line}");
    }
    // The script is valid bash.
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("sweep.sbatch");
    std::fs::write(&path, &script).unwrap();
    assert!(Command::new("bash")
        .arg("-n")
        .arg(&path)
        .status()
        .unwrap()
        .success());
    // A local run of the same cells works (the first one, quickly).
    let data = tempfile::tempdir().unwrap();
    let quick = sweep_cells(&config, &["bin_size=3".parse().unwrap()], &[1], data.path()).unwrap();
    let mut cell = quick[0].clone();
    cell.args.extend(["--trials".into(), "5".into()]);
    let results = run_cells(Path::new(EYEHAND), &[cell]);
    assert!(results[0].is_ok(), "{:?}", results[0]);
}
