//! `eyehand report`: the page opened in headless Chromium (Debian's `chromium`, which
//! `.ci/run` installs) draws the arm where the kinematic model puts it, its slider moves
//! it, and a Panda run's page carries the Panda's meshes. The test fails when Chromium is
//! missing.

use eyehand::experiment::report::{VIEW_ORIGIN, VIEW_SIZE};
use eyehand::experiment::show::{show_trials, TrialRange};
use eyehand::experiment::{run, Config, RunOptions};
use eyehand::robot::{ArmModel, Joints};
use nalgebra::{Isometry3, Point3, Quaternion, Translation3, UnitQuaternion, Vector3};
use serde_json::Value;
use std::path::{Path, PathBuf};
use std::process::Command;

const EYEHAND: &str = env!("CARGO_BIN_EXE_eyehand");

/// The page's data: the JSON in its `report-data` script element.
fn page_data(html: &Path) -> Value {
    let text = std::fs::read_to_string(html).unwrap();
    let start = text
        .find(r#"<script id="report-data" type="application/json">"#)
        .unwrap();
    let rest = &text[start..];
    let json = &rest[rest.find('>').unwrap() + 1..rest.find("</script>").unwrap()];
    serde_json::from_str(json).unwrap()
}

/// Runs Debian's `chromium` headless on `url` with `args`; a missing Chromium fails the test.
fn chromium(url: &str, args: &[String]) -> std::process::Output {
    let profile = tempfile::tempdir().unwrap();
    let mut command = Command::new("chromium");
    command.args([
        "--headless",
        "--no-sandbox",
        "--disable-gpu",
        // WebGL in software (SwiftShader), which Chromium no longer falls back to by itself.
        "--enable-unsafe-swiftshader",
        "--disable-quic",
        "--no-first-run",
        "--disable-background-networking",
        "--disable-component-update",
        "--disable-sync",
        "--hide-scrollbars",
        "--window-size=1100,800",
        "--virtual-time-budget=30000",
    ]);
    command.arg(format!("--user-data-dir={}", profile.path().display()));
    command.args(args).arg(url);
    match command.output() {
        Ok(output) => output,
        Err(e) => panic!("chromium could not be started ({e}): install it (`apt-get install chromium`, as .ci/run does)"),
    }
}

fn url(html: &Path, hash: &str) -> String {
    format!("file://{}#{hash}", html.canonicalize().unwrap().display())
}

/// The page's DOM once drawn: it says whether the scene was drawn and which pose it shows.
fn dom(html: &Path, hash: &str) -> String {
    let output = chromium(&url(html, hash), &["--dump-dom".to_string()]);
    String::from_utf8_lossy(&output.stdout).into_owned()
}

/// An RGB screenshot of the page at `hash`: (width, pixels).
fn screenshot(html: &Path, hash: &str) -> (usize, Vec<[u8; 3]>) {
    let dir = tempfile::tempdir().unwrap();
    let png = dir.path().join("shot.png");
    let output = chromium(
        &url(html, hash),
        &[format!("--screenshot={}", png.display())],
    );
    assert!(
        png.is_file(),
        "no screenshot: {}",
        String::from_utf8_lossy(&output.stderr)
    );
    let decoder = png::Decoder::new(std::fs::File::open(&png).unwrap());
    let mut reader = decoder.read_info().unwrap();
    let mut buffer = vec![0; reader.output_buffer_size()];
    let info = reader.next_frame(&mut buffer).unwrap();
    let channels = info.color_type.samples();
    let pixels = buffer[..info.buffer_size()]
        .chunks(channels)
        .map(|p| [p[0], p[1], p[2]])
        .collect();
    (info.width as usize, pixels)
}

/// The arm's orange, lit or shaded; not the red target, the grey floor or the background.
fn is_arm(p: [u8; 3]) -> bool {
    let [r, g, b] = p.map(i32::from);
    r > 90 && r > g + 40 && g > b + 15
}

fn pose(value: &Value) -> Isometry3<f64> {
    let v: Vec<f64> = value
        .as_array()
        .unwrap()
        .iter()
        .map(|x| x.as_f64().unwrap())
        .collect();
    Isometry3::from_parts(
        Translation3::new(v[0], v[1], v[2]),
        UnitQuaternion::from_quaternion(Quaternion::new(v[6], v[3], v[4], v[5])),
    )
}

fn point(value: &Value) -> Point3<f64> {
    let v: Vec<f64> = value
        .as_array()
        .unwrap()
        .iter()
        .map(|x| x.as_f64().unwrap())
        .collect();
    Point3::new(v[0], v[1], v[2])
}

/// Where the page's perspective camera (vertical field of view, z up) draws `p`, in page
/// pixels.
fn projected(view: &Value, p: &Point3<f64>) -> (f64, f64) {
    let (eye, target) = (point(&view["eye"]), point(&view["target"]));
    let forward = (target - eye).normalize();
    let right = forward.cross(&Vector3::z()).normalize();
    let up = right.cross(&forward);
    let d = p - eye;
    let half = (view["fov"].as_f64().unwrap().to_radians() / 2.0).tan();
    let (w, h) = (f64::from(VIEW_SIZE.0), f64::from(VIEW_SIZE.1));
    let x = d.dot(&right) / (d.dot(&forward) * half * w / h);
    let y = d.dot(&up) / (d.dot(&forward) * half);
    (
        f64::from(VIEW_ORIGIN.0) + (x + 1.0) / 2.0 * w,
        f64::from(VIEW_ORIGIN.1) + (1.0 - y) / 2.0 * h,
    )
}

/// True when a pixel within 2 px of (x, y) has the arm's colour.
fn arm_near(shot: &(usize, Vec<[u8; 3]>), (x, y): (f64, f64)) -> bool {
    let (width, pixels) = shot;
    (-2..=2).any(|dy: i64| {
        (-2..=2).any(|dx: i64| {
            let (px, py) = (x.round() as i64 + dx, y.round() as i64 + dy);
            px >= 0
                && py >= 0
                && (px as usize) < *width
                && pixels
                    .get(py as usize * width + px as usize)
                    .is_some_and(|p| is_arm(*p))
        })
    })
}

/// The centres of the arm's parts at pose `k` of `trial`, placed by the kinematic model
/// (whose body frames the page's must match).
fn part_centres(data: &Value, model: &ArmModel, trial: &Value, k: usize) -> Vec<Point3<f64>> {
    let look = &trial["poses"][k];
    let degrees: Vec<f64> = look["joints_deg"]
        .as_array()
        .unwrap()
        .iter()
        .map(|v| v.as_f64().unwrap())
        .collect();
    let q = Joints::from_fn(degrees.len(), |i| degrees[i].to_radians());
    let mut frames = vec![Isometry3::identity()];
    frames.extend(model.link_frames(&q).iter().copied());
    for (body, written) in look["bodies"].as_array().unwrap().iter().enumerate() {
        let written = pose(written);
        assert!((written.translation.vector - frames[body].translation.vector).norm() < 1e-5);
        assert!(written.rotation.angle_to(&frames[body].rotation) < 1e-5);
    }
    data["arm"]["parts"]
        .as_array()
        .unwrap()
        .iter()
        .map(|part| {
            let body = part["body"].as_u64().unwrap() as usize;
            frames[body] * (pose(&part["origin"]) * Point3::origin())
        })
        .collect()
}

#[test]
fn the_page_draws_the_arm_where_the_model_puts_it_and_the_slider_moves_it() {
    let data_dir = tempfile::tempdir().unwrap();
    let mut config = Config::default_config();
    config.trials = 30;
    config.seed = 3;
    let folder = run(&RunOptions::new(config, data_dir.path()))
        .unwrap()
        .folder;
    let status = Command::new(EYEHAND)
        .args(["report", folder.to_str().unwrap(), "--trial", "30"])
        .output()
        .unwrap();
    assert!(
        status.status.success(),
        "{}",
        String::from_utf8_lossy(&status.stderr)
    );
    let html = folder.join("report.html");
    let data = page_data(&html);
    let trial = &data["trials"][0];
    assert_eq!(trial["trial"], 30);
    let last = trial["poses"].as_array().unwrap().len() - 1;
    assert!(last >= 2, "trial 30 took steps");
    let model = ArmModel::oscar6();
    let mut shots = Vec::new();
    for k in [0, last] {
        let hash = format!("trial=30&pose={k}");
        let drawn = dom(&html, &hash);
        assert!(
            drawn.contains(r#"data-scene="drawn""#),
            "{}",
            &drawn[..drawn.len().min(300)]
        );
        assert!(drawn.contains(&format!(r#"data-pose="30:{k}""#)));
        let shot = screenshot(&html, &hash);
        let centres = part_centres(&data, &model, trial, k);
        let hits = centres
            .iter()
            .filter(|c| arm_near(&shot, projected(&data["view"], c)))
            .count();
        assert!(
            hits >= centres.len() - 1,
            "pose {k}: {hits} of {} part centres drawn in the arm's colour",
            centres.len()
        );
        shots.push(shot);
    }
    let changed = shots[0]
        .1
        .iter()
        .zip(&shots[1].1)
        .filter(|(a, b)| is_arm(**a) != is_arm(**b))
        .count();
    assert!(
        changed > 2000,
        "moving the slider changed {changed} arm pixels"
    );
}

/// A Panda run (`configs/arms/panda.conf`) with `run --report`.
fn panda_run(data: &Path) -> PathBuf {
    let output = Command::new(EYEHAND)
        .args([
            "run",
            "--config",
            "configs/arms/panda.conf",
            "--trials",
            "10",
            // A 10-trial run is judged by its last trial alone (the window is a tenth of
            // the trials): at seed 1 none fails (at seed 2 the last does, exit 1).
            "--seed",
            "1",
        ])
        .args([
            "--quiet",
            "--no-plot",
            "--report",
            "--data",
            data.to_str().unwrap(),
        ])
        .output()
        .unwrap();
    assert!(
        output.status.success(),
        "{}",
        String::from_utf8_lossy(&output.stderr)
    );
    let stdout = String::from_utf8(output.stdout).unwrap();
    let mut lines = stdout.lines();
    let folder = PathBuf::from(lines.next().unwrap());
    assert_eq!(
        lines.next().map(PathBuf::from),
        Some(folder.join("report.html"))
    );
    folder
}

#[test]
fn a_panda_runs_page_shows_the_pandas_meshes_and_show_draws_its_trials() {
    let data_dir = tempfile::tempdir().unwrap();
    let folder = panda_run(data_dir.path());
    let shown = show_trials(&folder, TrialRange::single(10)).unwrap();
    assert_eq!(shown.folders, vec![folder.join("show").join("10")]);
    assert!(shown.camera_images >= 2, "{shown:?}");
    let html = folder.join("report.html");
    let data = page_data(&html);
    let arm = &data["arm"];
    assert_eq!(arm["robot"], "panda");
    let mesh_links: Vec<&str> = arm["parts"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|p| p["shape"]["kind"] == "mesh")
        .map(|p| p["link"].as_str().unwrap())
        .collect();
    for link in [
        "panda_link0",
        "panda_link3",
        "panda_link7",
        "panda_hand",
        "panda_leftfinger",
    ] {
        assert!(
            mesh_links.contains(&link),
            "{link} is drawn from its mesh: {mesh_links:?}"
        );
    }
    let triangles: usize = arm["meshes"]
        .as_array()
        .unwrap()
        .iter()
        .map(|m| m["indices"].as_str().unwrap().len() * 3 / 4 / 12)
        .sum();
    assert!(triangles > 1000, "{triangles} triangles");
    let drawn = dom(&html, "");
    assert!(
        drawn.contains(r#"data-scene="drawn""#),
        "{}",
        &drawn[..drawn.len().min(300)]
    );
    let (width, pixels) = screenshot(&html, "");
    let in_view = pixels
        .iter()
        .enumerate()
        .filter(|(i, p)| {
            let (x, y) = ((i % width) as u32, (i / width) as u32);
            x < VIEW_ORIGIN.0 + VIEW_SIZE.0
                && y >= VIEW_ORIGIN.1
                && y < VIEW_ORIGIN.1 + VIEW_SIZE.1
                && is_arm(**p)
        })
        .count();
    assert!(in_view > 3000, "{in_view} arm pixels in the 3-D view");
}

#[test]
fn a_folder_that_is_no_run_is_refused_before_any_work() {
    let empty = tempfile::tempdir().unwrap();
    let output = Command::new(EYEHAND)
        .args(["report", empty.path().to_str().unwrap()])
        .output()
        .unwrap();
    assert_eq!(output.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&output.stderr).contains("neither a run folder"));
}
