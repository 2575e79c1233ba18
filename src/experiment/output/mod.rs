//! Writing a run: its folder, the data files written line by line, the numbers in them,
//! `summary.json` and the process's memory figures.

pub(super) mod data_files;
pub(super) mod number_text;
pub(super) mod process_memory;
pub(super) mod run_folder;
pub(super) mod summary;
