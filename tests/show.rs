//! `eyehand show`: a run's trials re-simulated from its folder reproduce the run, and the
//! pictures say what the simulation did (the camera image's blob is the reading, the arm
//! drawing puts the camera where the kinematic model does).

use eyehand::camera::{CameraModel, EmptyScene, NotSeen};
use eyehand::control::ServoMode;
use eyehand::experiment::show::{
    show_trials, write_camera_image, ArmView, Look, ShowError, TrialRange, BACKGROUND_GREY,
    CENTRE_MARK, LAST_CAMERA_CENTRE, OBJECT_GREY,
};
use eyehand::experiment::{run, CameraKind, Config, Event, RunOptions, SimKind};
use eyehand::robot::{ArmModel, Joints};
use nalgebra::{Isometry3, Point3, Translation3, UnitQuaternion, Vector3};
use std::path::{Path, PathBuf};
use std::process::Command;

/// A run of lin5 with `trials` trials, `edit` applied to the default config.
fn run_in(data: &Path, trials: usize, events: Vec<Event>, edit: impl Fn(&mut Config)) -> PathBuf {
    let mut config = Config::default_config();
    config.trials = trials;
    config.seed = 4;
    edit(&mut config);
    let options = RunOptions {
        events,
        ..RunOptions::new(config, data)
    };
    run(&options).unwrap().folder
}

/// The distance column of `<folder>/<k>step` at `trial`, as logged.
fn logged_distance(folder: &Path, step: usize, trial: usize) -> Option<String> {
    let text = std::fs::read_to_string(folder.join(format!("{step}step"))).unwrap();
    text.lines()
        .map(|l| l.split(' ').collect::<Vec<_>>())
        .find(|f| f[0] == trial.to_string())
        .map(|f| f[1].to_string())
}

fn trial_json(folder: &Path, trial: usize) -> serde_json::Value {
    let path = folder
        .join("show")
        .join(trial.to_string())
        .join("trial.json");
    serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap()
}

/// Checks that `show` of `trials` reproduces every distance the run logged for them.
fn assert_reproduces(folder: &Path, trials: TrialRange) {
    let report = show_trials(folder, trials).unwrap();
    assert_eq!(report.folders.len(), trials.last - trials.first + 1);
    for trial in trials.range() {
        let json = trial_json(folder, trial);
        let distances = json["distances_mm"].as_array().unwrap();
        assert!(!distances.is_empty(), "trial {trial} took steps");
        for step in 1..=5 {
            let shown = distances
                .get(step - 1)
                .map(|d| format!("{:.6}", d.as_f64().unwrap()));
            assert_eq!(
                shown,
                logged_distance(folder, step, trial),
                "trial {trial} step {step}"
            );
        }
    }
}

#[test]
fn show_reproduces_the_logged_distances_exactly() {
    let data = tempfile::tempdir().unwrap();
    let plain = run_in(data.path(), 40, vec![], |_| {});
    assert_reproduces(
        &plain,
        TrialRange {
            first: 37,
            last: 40,
        },
    );
    // Events, a pattern file and the ray-cast camera.
    let events = vec![
        "rotate:10:30".parse().unwrap(),
        "elongate:12:2:5".parse().unwrap(),
    ];
    let changed = run_in(data.path(), 14, events, |c| {
        c.use_pat_file = 0;
        c.camera = CameraKind::Raycast;
    });
    let run_patterns = std::fs::read(changed.join("pat_file")).unwrap();
    assert_reproduces(
        &changed,
        TrialRange {
            first: 13,
            last: 14,
        },
    );
    assert_eq!(
        std::fs::read(changed.join("pat_file")).unwrap(),
        run_patterns
    );
    let json = trial_json(&changed, 14);
    assert_eq!(
        json["events"],
        serde_json::json!(["rotate:10:30", "elongate:12:2:5"])
    );
    // The dynamic simulator.
    let dynamic = run_in(data.path(), 3, vec![], |c| c.sim = SimKind::Dynamic);
    assert_reproduces(&dynamic, TrialRange::single(3));
    // Continuous servoing with latency and noisy encoders.
    let continuous = run_in(data.path(), 3, vec![], |c| {
        c.sim = SimKind::Dynamic;
        c.servo_mode = ServoMode::Continuous;
        c.camera_fps = 30.0;
        c.camera_latency_ms = 50.0;
        c.feedback_steps = 60;
        c.joint_noise_deg = 0.01;
    });
    assert_reproduces(&continuous, TrialRange::single(3));
}

#[test]
fn a_trial_the_run_does_not_have_is_a_clear_error() {
    let data = tempfile::tempdir().unwrap();
    let folder = run_in(data.path(), 5, vec![], |_| {});
    let err = show_trials(&folder, TrialRange::single(6)).unwrap_err();
    assert!(
        matches!(
            err,
            ShowError::NoSuchTrial {
                trial: 6,
                trials: 5
            }
        ),
        "{err}"
    );
    let output = Command::new(env!("CARGO_BIN_EXE_eyehand"))
        .args(["show", folder.to_str().unwrap(), "--trials", "4..9"])
        .output()
        .unwrap();
    assert_eq!(output.status.code(), Some(2));
    let message = String::from_utf8_lossy(&output.stderr);
    assert!(
        message.contains("trial 9 is not in the run: it has trials 1..5"),
        "{message}"
    );
    let missing = Command::new(env!("CARGO_BIN_EXE_eyehand"))
        .args(["show", data.path().to_str().unwrap(), "--trial", "1"])
        .output()
        .unwrap();
    assert_eq!(missing.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&missing.stderr).contains("is not a run folder"));
    // A folder that lost its `nodes` file (a trial per line) says so, not "trials 1..0".
    std::fs::remove_file(folder.join("nodes")).unwrap();
    let err = show_trials(&folder, TrialRange::single(2)).unwrap_err();
    assert!(matches!(err, ShowError::NoTrialList { .. }), "{err}");
    assert!(
        err.to_string()
            .contains("cannot read the run's list of finished trials"),
        "{err}"
    );
}

/// `info` with its line starting `entry ` replaced by `line`.
fn edit_info(folder: &Path, entry: &str, line: &str) {
    let path = folder.join("info");
    let info = std::fs::read_to_string(&path).unwrap();
    let prefix = format!("{entry} ");
    assert!(
        info.lines().any(|l| l.starts_with(&prefix)),
        "{entry} in info"
    );
    let edited: Vec<&str> = info
        .lines()
        .map(|l| if l.starts_with(&prefix) { line } else { l })
        .collect();
    std::fs::write(&path, edited.join("\n") + "\n").unwrap();
}

#[test]
fn a_run_whose_info_was_edited_is_refused_naming_the_entry() {
    let data = tempfile::tempdir().unwrap();
    let folder = run_in(data.path(), 20, vec![], |_| {});
    let original = std::fs::read_to_string(folder.join("info")).unwrap();
    edit_info(&folder, "seed", "seed 5");
    let output = Command::new(env!("CARGO_BIN_EXE_eyehand"))
        .args(["show", folder.to_str().unwrap(), "--trial", "15"])
        .output()
        .unwrap();
    assert_eq!(output.status.code(), Some(2));
    let message = String::from_utf8_lossy(&output.stderr);
    assert!(
        message.contains("trial 1's distance after step 1 was ")
            && message
                .contains("no longer describes this run (its `seed` differs from summary.json's)"),
        "{message}"
    );
    assert!(!folder.join("show/15").exists(), "nothing drawn");
    std::fs::write(folder.join("info"), &original).unwrap();
    edit_info(&folder, "known_pattern_perc", "known_pattern_perc 0");
    let err = show_trials(&folder, TrialRange::single(15)).unwrap_err();
    assert!(
        matches!(err, ShowError::Diverged { entry: None, .. }),
        "an entry summary.json does not hold: {err}"
    );
    std::fs::write(folder.join("info"), &original).unwrap();
    assert!(show_trials(&folder, TrialRange::single(15)).is_ok());
}

/// An RGB image read back from a PNG: (width, height, pixels).
fn read_png(path: &Path) -> (usize, usize, Vec<[u8; 3]>) {
    let decoder = png::Decoder::new(std::io::BufReader::new(std::fs::File::open(path).unwrap()));
    let mut reader = decoder.read_info().unwrap();
    let mut buffer = vec![0; reader.output_buffer_size()];
    let info = reader.next_frame(&mut buffer).unwrap();
    let channels = info.color_type.samples();
    let pixels = buffer[..info.buffer_size()]
        .chunks(channels)
        .map(|p| [p[0], p[1], p[2]])
        .collect();
    (info.width as usize, info.height as usize, pixels)
}

/// The blob in the camera image part of a camera_K.png, from its grey levels (coverage):
/// the pixels at least half covered, and the coverage-weighted centroid relative to the
/// image centre (px).
fn blob(path: &Path) -> (usize, f64, f64) {
    let (width, _, pixels) = read_png(path);
    let (mut count, mut weight, mut sum_x, mut sum_y) = (0, 0.0, 0.0, 0.0);
    let full = f64::from(OBJECT_GREY - BACKGROUND_GREY);
    for y in 0..512 {
        for x in 0..512 {
            let [r, g, b] = pixels[y * width + x];
            if !(r == g && g == b && r > BACKGROUND_GREY) {
                continue;
            }
            let coverage = f64::from(r - BACKGROUND_GREY) / full;
            count += usize::from(coverage >= 0.5);
            weight += coverage;
            sum_x += coverage * (x as f64 + 0.5 - 256.0);
            sum_y += coverage * (y as f64 + 0.5 - 256.0);
        }
    }
    (count, sum_x / weight, sum_y / weight)
}

#[test]
fn the_camera_images_blob_is_the_reading() {
    let data = tempfile::tempdir().unwrap();
    let camera = CameraModel::default();
    for kind in [CameraKind::Raycast, CameraKind::Projection] {
        let folder = run_in(data.path(), 8, vec![], |c| c.camera = kind);
        show_trials(&folder, TrialRange { first: 7, last: 8 }).unwrap();
        for trial in [7, 8] {
            let json = trial_json(&folder, trial);
            for pose in json["poses"].as_array().unwrap() {
                let k = pose["pose"].as_u64().unwrap();
                let image = folder.join(format!("show/{trial}/camera_{k}.png"));
                let (count, x, y) = blob(&image);
                let c: Vec<f64> = pose["reading"]
                    .as_array()
                    .unwrap()
                    .iter()
                    .map(|v| v.as_f64().unwrap())
                    .collect();
                let area = camera.area_from_cz(c[2]);
                let what = format!("{kind} trial {trial} pose {k}: blob ({x}, {y}) {count} px, reading {c:?} ({area} px²)");
                assert!((x - c[0]).abs() <= 0.5 && (y - c[1]).abs() <= 0.5, "{what}");
                assert!((count as f64 - area).abs() <= 0.02 * area, "{what}");
            }
        }
    }
}

#[test]
fn the_image_is_blank_where_the_object_is_not_seen() {
    let dir = tempfile::tempdir().unwrap();
    let camera = CameraModel::default();
    // Looking down from 20 cm above a point 15 cm beside the sphere: its image is cut by
    // the frame's border, so the camera does not see it.
    let down = UnitQuaternion::from_axis_angle(&Vector3::x_axis(), std::f64::consts::PI);
    let look = Look {
        joints: Joints::zeros(6),
        camera_pose: Isometry3::from_parts(Translation3::new(0.7, 0.0, 0.2), down),
        object: Point3::new(0.88, 0.0, 0.0),
        reading: Err(NotSeen::OutsideFrame),
        sim_time: 0.0,
    };
    let path = dir.path().join("camera_0.png");
    write_camera_image(
        &path,
        &look,
        &camera,
        256,
        &EmptyScene,
        &["not seen".into()],
    )
    .unwrap();
    let (width, _, pixels) = read_png(&path);
    for y in 0..512 {
        for x in 0..512 {
            let p = pixels[y * width + x];
            let mark = [CENTRE_MARK.0, CENTRE_MARK.1, CENTRE_MARK.2];
            assert!(
                p == [BACKGROUND_GREY; 3] || p == mark,
                "({x}, {y}) is {p:?}"
            );
        }
    }
    // The same look, seen, does show the object.
    let seen = Look {
        object: Point3::new(0.75, 0.0, 0.0),
        reading: Ok(Vector3::zeros()),
        ..look
    };
    write_camera_image(&path, &seen, &camera, 256, &EmptyScene, &[]).unwrap();
    assert!(blob(&path).0 > 500);
}

/// The centroid of the pixels of `colour` within `radius` px of `near` in arm.png.
fn dot_near(pixels: &[[u8; 3]], width: usize, colour: [u8; 3], near: (f64, f64)) -> (f64, f64) {
    let (mut n, mut sx, mut sy) = (0.0, 0.0, 0.0);
    for (i, p) in pixels.iter().enumerate() {
        let (x, y) = ((i % width) as f64, (i / width) as f64);
        if *p == colour && (x - near.0).abs() < 12.0 && (y - near.1).abs() < 12.0 {
            n += 1.0;
            sx += x;
            sy += y;
        }
    }
    assert!(n > 0.0, "no dot of {colour:?} near {near:?}");
    (sx / n, sy / n)
}

#[test]
fn the_arm_drawing_puts_the_camera_where_the_kinematic_model_does() {
    let data = tempfile::tempdir().unwrap();
    for sim in [SimKind::Kinematic, SimKind::Dynamic] {
        let folder = run_in(data.path(), 2, vec![], |c| c.sim = sim);
        show_trials(&folder, TrialRange::single(2)).unwrap();
        let json = trial_json(&folder, 2);
        let last = json["poses"].as_array().unwrap().last().unwrap().clone();
        let joints: Vec<f64> = last["joints_deg"]
            .as_array()
            .unwrap()
            .iter()
            .map(|v| v.as_f64().unwrap().to_radians())
            .collect();
        let centre = ArmModel::oscar6().camera_position(&Joints::from_slice(&joints));
        let (width, _, pixels) = read_png(&folder.join("show/2/arm.png"));
        let magenta = [
            LAST_CAMERA_CENTRE.0,
            LAST_CAMERA_CENTRE.1,
            LAST_CAMERA_CENTRE.2,
        ];
        for view in [ArmView::Side, ArmView::Top] {
            let expected = view.pixel(&centre);
            let drawn = dot_near(&pixels, width, magenta, expected);
            let off = ((drawn.0 - expected.0).powi(2) + (drawn.1 - expected.1).powi(2)).sqrt();
            assert!(
                off <= 2.0,
                "{sim} {view:?}: drawn at {drawn:?}, model at {expected:?}"
            );
        }
    }
}

/// The Rerun recording, read back with the rerun crate's own decoder.
#[cfg(feature = "rerun")]
mod recording {
    use super::*;
    use eyehand::experiment::record::record_trials;
    use rerun::external::re_log_encoding::DecoderApp;
    use std::collections::BTreeMap;

    /// Rows logged per (entity, archetype) and the timelines seen.
    fn rows_by_entity(path: &Path) -> (BTreeMap<(String, String), usize>, Vec<String>) {
        let file = std::io::BufReader::new(std::fs::File::open(path).unwrap());
        let mut rows = BTreeMap::new();
        let mut timelines = Vec::new();
        for message in DecoderApp::decode_eager(file).unwrap() {
            let rerun::log::LogMsg::ArrowMsg(_, arrow) = message.unwrap() else {
                continue;
            };
            let chunk = rerun::log::Chunk::from_arrow_msg(&arrow).unwrap();
            let archetypes: std::collections::BTreeSet<String> = chunk
                .component_descriptors()
                .filter_map(|d| d.archetype.map(|a| a.short_name().to_string()))
                .collect();
            let entity = chunk.entity_path().to_string();
            let entity = entity.trim_start_matches('/').to_string();
            for archetype in archetypes {
                *rows.entry((entity.clone(), archetype)).or_insert(0) += chunk.num_rows();
            }
            for name in chunk.timelines().keys() {
                if !timelines.contains(&name.to_string()) {
                    timelines.push(name.to_string());
                }
            }
        }
        (rows, timelines)
    }

    #[test]
    fn the_recording_holds_the_links_the_camera_image_and_a_transform_per_move_or_tick() {
        let data = tempfile::tempdir().unwrap();
        for sim in [SimKind::Kinematic, SimKind::Dynamic] {
            let folder = run_in(data.path(), 3, vec![], |c| c.sim = sim);
            let trials = TrialRange { first: 2, last: 3 };
            show_trials(&folder, trials).unwrap();
            let out = folder.join("trials.rrd");
            let report = record_trials(&folder, trials, &out).unwrap();
            let (mut poses, mut steps, mut transforms) = (0, 0, 0);
            for trial in trials.range() {
                let json = trial_json(&folder, trial);
                let looks = json["poses"].as_array().unwrap();
                poses += looks.len();
                steps += json["distances_mm"].as_array().unwrap().len();
                transforms += match sim {
                    SimKind::Kinematic => looks.len(),
                    SimKind::Dynamic => {
                        let end = looks.last().unwrap()["sim_time_s"].as_f64().unwrap();
                        1 + (end / Config::default_config().dt).round() as usize
                    }
                };
            }
            let (rows, timelines) = rows_by_entity(&out);
            let count = |entity: &str, archetype: &str| {
                rows.get(&(entity.to_string(), archetype.to_string()))
                    .copied()
                    .unwrap_or(0)
            };
            for link in 1..=6 {
                let entity = format!("world/arm/link_{link}");
                assert_eq!(
                    count(&entity, "Transform3D"),
                    transforms,
                    "{sim} {entity}: {rows:?}"
                );
                assert_eq!(count(&entity, "Capsules3D"), 2, "{sim} {entity}");
            }
            assert_eq!(
                count("world/arm/camera", "Transform3D"),
                transforms,
                "{sim}"
            );
            assert_eq!(count("world/arm/camera", "Pinhole"), 2, "{sim}");
            assert_eq!(count("world/arm/camera/image", "Image"), poses, "{sim}");
            assert_eq!(count("world/target", "Ellipsoids3D"), 2, "{sim}");
            assert_eq!(count("plots/distance_mm", "Scalars"), steps, "{sim}");
            assert!(timelines.contains(&"sim_time".to_string()), "{timelines:?}");
            assert_eq!((report.trials, report.images), (2, poses));
            assert_eq!(report.arm_transforms, transforms);
        }
    }
}
