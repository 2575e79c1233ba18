//! Run folders: `data/<method>/<id>/` with id the first free of 0–9, a–z, or a fixed folder
//! (a sweep's cell) that a run empties and fills again.

use std::io;
use std::path::{Path, PathBuf};

/// The 36 run ids, in the order they are used.
pub const RUN_IDS: &str = "0123456789abcdefghijklmnopqrstuvwxyz";

/// Why no run folder could be made.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum RunFolderError {
    /// All 36 ids are in use.
    #[error("all 36 run folders {0}/0 … {0}/z are in use: delete or rename some to make room")]
    Full(PathBuf),
    /// The file system refused.
    #[error("cannot create a run folder in {path}: {source}")]
    Io {
        /// Where.
        path: PathBuf,
        /// Why.
        source: io::Error,
    },
}

/// Creates and returns the first free `<data>/<method>/<id>` folder. Creating the folder is
/// the claim, so runs started side by side never share one.
pub fn allocate_run_folder(data: &Path, method: &str) -> Result<PathBuf, RunFolderError> {
    let parent = data.join(method);
    std::fs::create_dir_all(&parent).map_err(|source| RunFolderError::Io {
        path: parent.clone(),
        source,
    })?;
    for id in RUN_IDS.chars() {
        let folder = parent.join(id.to_string());
        match std::fs::create_dir(&folder) {
            Ok(()) => return Ok(folder),
            Err(e) if e.kind() == io::ErrorKind::AlreadyExists => continue,
            Err(source) => {
                return Err(RunFolderError::Io {
                    path: folder,
                    source,
                })
            }
        }
    }
    Err(RunFolderError::Full(parent))
}

/// Makes `folder` an empty run folder: whatever an earlier (possibly cancelled) run left
/// there is removed first, so a rerun overwrites its own folder.
pub fn fresh_run_folder(folder: &Path) -> Result<PathBuf, RunFolderError> {
    let io_error = |source| RunFolderError::Io {
        path: folder.to_path_buf(),
        source,
    };
    match std::fs::remove_dir_all(folder) {
        Ok(()) => {}
        Err(e) if e.kind() == io::ErrorKind::NotFound => {}
        Err(e) => return Err(io_error(e)),
    }
    std::fs::create_dir_all(folder).map_err(io_error)?;
    Ok(folder.to_path_buf())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn folders_are_used_in_order_until_all_36_are_taken() {
        let data = tempfile::tempdir().unwrap();
        let first = allocate_run_folder(data.path(), "lin5").unwrap();
        assert_eq!(first, data.path().join("lin5").join("0"));
        std::fs::remove_dir(&first).unwrap();
        std::fs::create_dir(data.path().join("lin5").join("1")).unwrap();
        assert_eq!(allocate_run_folder(data.path(), "lin5").unwrap(), first);
        let ids: Vec<_> = (0..34)
            .map(|_| allocate_run_folder(data.path(), "lin5").unwrap())
            .collect();
        assert_eq!(ids[0], data.path().join("lin5").join("2"));
        assert_eq!(ids[33], data.path().join("lin5").join("z"));
        let err = allocate_run_folder(data.path(), "lin5").unwrap_err();
        assert!(matches!(err, RunFolderError::Full(_)));
        assert!(err.to_string().contains("all 36 run folders"), "{err}");
    }

    #[test]
    fn a_fixed_folder_is_emptied_before_it_is_used_again() {
        let data = tempfile::tempdir().unwrap();
        let cell = data.path().join("sweep/0/cells/3");
        assert_eq!(fresh_run_folder(&cell).unwrap(), cell);
        std::fs::write(cell.join("1step"), "1 2.5 0.0\n").unwrap();
        fresh_run_folder(&cell).unwrap();
        assert_eq!(std::fs::read_dir(&cell).unwrap().count(), 0);
    }
}
