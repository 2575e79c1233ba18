//! The public robot collection the arm tests read: PyPI's `example-robot-data`, its
//! `share/example-robot-data` folder named by `EYEHAND_ROBOT_DATA` (scripts/test-all.sh
//! installs the package and sets it). A test that needs it fails when it is not set.

use std::path::PathBuf;

/// The variable naming the collection's `share/example-robot-data` folder.
pub const ROBOT_DATA: &str = "EYEHAND_ROBOT_DATA";

/// The collection's `share/example-robot-data` folder.
pub fn robot_data() -> PathBuf {
    let folder = std::env::var_os(ROBOT_DATA).unwrap_or_else(|| {
        panic!(
            "{ROBOT_DATA} is not set: install the collection (`pip install --no-deps \
             example-robot-data==6.0.0`, as scripts/test-all.sh does) and set it to its \
             share/example-robot-data folder"
        )
    });
    PathBuf::from(folder)
}
