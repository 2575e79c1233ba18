//! Seeing the arm: a run's trials re-simulated from its folder (config, seed, URDF and
//! events) and drawn — the camera image at every pose (`camera_K.png`), the arm in 3-D
//! (`arm.png`) and the poses as numbers (`trial.json`) in `RUN_DIR/show/N/` — and, with the
//! `rerun` feature, a Rerun recording of them.

mod arm_view;
mod camera_image;
mod recorded_run;
mod replay;
mod trial_files;
mod trial_range;
mod watch;

pub use arm_view::{
    write_arm_image, ArmView, ARM_IMAGE_SIZE, LAST_CAMERA_CENTRE, PIXELS_PER_METRE,
};
#[cfg(feature = "rerun")]
pub(crate) use camera_image::blob_mask;
pub use camera_image::{
    write_camera_image, BACKGROUND_GREY, CAPTION_HEIGHT, CENTRE_MARK, OBJECT_GREY,
};
pub use recorded_run::RecordedRun;
pub use replay::{replay, TrialTrace};
#[cfg(feature = "rerun")]
pub(crate) use trial_files::{remove_scratch_patterns, show_folder};
pub use trial_files::{show_trials, ShowReport};
pub use trial_range::TrialRange;
pub use watch::Look;

use std::path::PathBuf;

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
        source: std::io::Error,
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
    #[error("trial {trial} is not in the run: it has trials 1..{trials}")]
    NoSuchTrial {
        /// The trial asked for.
        trial: usize,
        /// Trials the run finished.
        trials: usize,
    },
    /// The replay failed as the run would have (learner storage, an event).
    #[error("replaying the run: {0}")]
    Replay(#[from] crate::experiment::RunError),
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
