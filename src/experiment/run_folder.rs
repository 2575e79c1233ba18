//! Run folders: `data/<method>/<id>/` with id the first free of 0–9, a–z.

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
}
