//! Comparisons and sweeps: a plan of cells (one typed run each) in a study folder, run
//! side by side as separate processes or as a Slurm job array, and gathered into a table.

mod cell_progress;
mod cells;
mod compare;
mod error;
mod gather;
mod plan;
mod signals;
mod slurm;
mod sweep;
mod table;

pub use cells::{run_cell, run_locally, shell_quote, CellLauncher, CellRunError, LocalRunEnd};
pub use compare::{compare_plan, CompareRequest, DEFAULT_CONFIGS};
pub use error::StudyError;
pub use gather::{gather, GatherReport, Unfinished};
pub use plan::{Cell, StudyFolder, StudyKind, StudyPlan, MAX_CELLS};
pub use slurm::{
    check_slurm_folder, memory_class_mb, resubmit_line, slurm_script, write_slurm_script,
    SlurmOptions,
};
pub use sweep::{combinations, parse_seeds, sweep_plan, Setting};
pub use table::{
    compare_table, four_step_curves, study_table, sweep_table, CellResult, TRIALS_TO_LEVELS_MM,
    TRIALS_TO_WINDOW,
};
