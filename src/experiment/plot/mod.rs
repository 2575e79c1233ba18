//! PNG plots (plotters): a run's panels as the study's result figures, and the 4-step
//! curves of several runs overlaid.

mod canvas;
mod compare_plot;
mod run_plot;
mod series;

pub(crate) use canvas::{register_font, FAMILY};
pub use compare_plot::{plot_curves, Curve};
pub use run_plot::{plot_run, PANELS, PLOT_SIZE};
pub use series::{event_marks, event_trials, moving_average, time_in_unit, time_unit, Series};

/// Why a plot could not be drawn.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum PlotError {
    /// A data file could not be read.
    #[error("reading {path}: {source}")]
    Read {
        /// The file.
        path: std::path::PathBuf,
        /// Why.
        source: std::io::Error,
    },
    /// Drawing or writing the PNG failed.
    #[error("drawing {path}: {reason}")]
    Draw {
        /// The PNG.
        path: std::path::PathBuf,
        /// Why.
        reason: String,
    },
}
