//! Seeing the arm: a run's trials re-simulated from its folder (config, seed, URDF and
//! events) and drawn — the camera image at every pose (`camera_K.png`), the arm in 3-D
//! (`arm.png`) and the poses as numbers (`trial.json`) in `RUN_DIR/show/N/` — and, with the
//! `rerun` feature, a Rerun recording of them.

mod arm_view;
mod camera_image;
mod divergence;
mod frame;
mod recorded_run;
mod replay;
mod replay_bar;
mod tracer;
mod trial_files;
mod trial_range;

pub use arm_view::{
    write_arm_image, ArmView, ARM_IMAGE_SIZE, LAST_CAMERA_CENTRE, PIXELS_PER_METRE,
};
#[cfg(feature = "rerun")]
pub(crate) use camera_image::blob_mask;
pub use camera_image::{
    camera_greys, camera_image_png, write_camera_image, BACKGROUND_GREY, CAPTION_HEIGHT,
    CENTRE_MARK, OBJECT_GREY,
};
pub use frame::{draw_frame, frame_size, FrameView, RgbFrame};
pub use recorded_run::RecordedRun;
pub use replay::{replay, TrialTrace};
pub use tracer::Look;
pub(crate) use trial_files::{remove_scratch_patterns, show_folder};
pub use trial_files::{show_trials, CameraPictures, ShowReport};
pub use trial_range::TrialRange;

use std::path::PathBuf;

/// A distance as a `Diverged` error shows it.
fn mm(distance: &Option<f64>) -> String {
    distance.map_or("none (no step 1)".to_string(), |d| format!("{d:.6} mm"))
}

/// Why a run could not be shown or recorded.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum ShowError {
    /// The folder has no readable `info` file.
    #[error("{folder} is not a run folder (no readable info file: {source})")]
    NotARun {
        /// The folder given.
        folder: PathBuf,
        /// Why `info` could not be read.
        source: crate::files::ReadError,
    },
    /// The run's `nodes` file, one line per finished trial, cannot be read.
    #[error("{path}: cannot read the run's list of finished trials ({source}): the run folder is incomplete")]
    NoTrialList {
        /// The `nodes` file.
        path: PathBuf,
        /// Why it could not be read.
        source: crate::files::ReadError,
    },
    /// The `info` file lacks what a replay needs.
    #[error("{path}: {reason}")]
    BadInfo {
        /// The `info` file.
        path: PathBuf,
        /// What is missing or wrong.
        reason: String,
    },
    /// The config recorded in `info` does not parse.
    #[error(transparent)]
    Config(#[from] crate::experiment::ConfigError),
    /// The run's URDF is gone or broken.
    #[error(transparent)]
    Urdf(#[from] crate::robot::DescriptionError),
    /// A trial the run does not have.
    #[error("trial {trial} is not in the run: {}", match .trials {
        0 => "it finished no trial".to_string(),
        n => format!("it has trials 1..{n}"),
    })]
    NoSuchTrial {
        /// The trial asked for.
        trial: usize,
        /// Trials the run finished.
        trials: usize,
    },
    /// The replay failed as the run would have (learner storage, an event).
    #[error("replaying the run: {0}")]
    Replay(#[from] crate::experiment::RunError),
    /// The replay does not reproduce the run: a trial's distance after step 1 is not the
    /// one its `1step` file holds (its `info` was edited, or its learner is not the
    /// config's).
    #[error(
        "{path}: trial {trial}'s distance after step 1 was {} in the run but is {} in the replay: the folder's info no longer describes this run{}",
        mm(.recorded), mm(.replayed),
        .entry.map_or(String::new(), |e| format!(" (its `{e}` differs from summary.json's)"))
    )]
    Diverged {
        /// The run's `1step` file.
        path: PathBuf,
        /// The first trial that differs.
        trial: usize,
        /// Its distance in the run (mm; `None`: no step 1).
        recorded: Option<f64>,
        /// Its distance in the replay (mm).
        replayed: Option<f64>,
        /// The `info` entry `summary.json` contradicts, where one does.
        entry: Option<&'static str>,
    },
    /// Writing a file failed.
    #[error("writing {path}: {reason}")]
    Write {
        /// The file.
        path: PathBuf,
        /// Why.
        reason: String,
    },
    /// This eyehand was built without the Rerun recorder.
    #[error("--record needs the `rerun` feature: build eyehand with `cargo build --release --features rerun`")]
    NoRecorder,
}
