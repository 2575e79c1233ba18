//! Reading a file a user named (a config, a URDF, a mesh, a run's `info` or data file):
//! only a regular file of bounded size is read, so a FIFO, a device or a folder is a clear
//! error before any read could block, and `/dev/zero` cannot fill the memory.

use std::fs::File;
use std::io::{self, Read};
use std::os::unix::fs::OpenOptionsExt;
use std::path::Path;
use thiserror::Error;

/// The longest config file read (bytes): the complete default config is about 20 kB.
pub const MAX_CONFIG_BYTES: u64 = 1 << 20;
/// The longest URDF read (bytes): the shipped arms' are under 30 kB, large robots' a few MB.
pub const MAX_URDF_BYTES: u64 = 64 << 20;
/// The longest mesh file read (bytes): 10⁶ vertices as OBJ text are about 40 MB.
pub const MAX_MESH_BYTES: u64 = 256 << 20;
/// The longest file of a run folder read (`info`, `summary.json`, a data file): a run of
/// 10⁷ trials writes about 300 MB per data file.
pub const MAX_RUN_FILE_BYTES: u64 = 1 << 30;

/// Why a file was not read.
#[derive(Debug, Error)]
pub enum ReadError {
    /// The operating system refused it (missing, no permission, …).
    #[error("{0}")]
    Io(#[from] io::Error),
    /// Something is there, but not a regular file.
    #[error("not a regular file (a folder, a FIFO or a device)")]
    NotRegular,
    /// Longer than a file of its kind may be.
    #[error("{bytes} bytes, more than the {limit} bytes such a file may have")]
    TooLong {
        /// Its length (bytes), as far as it was read.
        bytes: u64,
        /// The most it may have.
        limit: u64,
    },
    /// Not UTF-8 text.
    #[error("not UTF-8 text")]
    NotText,
}

impl From<ReadError> for io::Error {
    fn from(error: ReadError) -> io::Error {
        match error {
            ReadError::Io(e) => e,
            other => io::Error::new(io::ErrorKind::InvalidData, other.to_string()),
        }
    }
}

/// Opens `path` without blocking (a FIFO with no writer would block a plain open) and
/// refuses anything but a regular file of at most `limit` bytes.
pub fn open_regular(path: &Path, limit: u64) -> Result<File, ReadError> {
    let file = std::fs::OpenOptions::new()
        .read(true)
        .custom_flags(libc::O_NONBLOCK)
        .open(path)?;
    let meta = file.metadata()?;
    if !meta.is_file() {
        return Err(ReadError::NotRegular);
    }
    if meta.len() > limit {
        return Err(ReadError::TooLong {
            bytes: meta.len(),
            limit,
        });
    }
    Ok(file)
}

/// The bytes of the regular file `path`, at most `limit` of them.
pub fn read_bytes(path: &Path, limit: u64) -> Result<Vec<u8>, ReadError> {
    let file = open_regular(path, limit)?;
    let mut bytes = Vec::new();
    file.take(limit + 1).read_to_end(&mut bytes)?;
    if bytes.len() as u64 > limit {
        return Err(ReadError::TooLong {
            bytes: bytes.len() as u64,
            limit,
        });
    }
    Ok(bytes)
}

/// The UTF-8 text of the regular file `path`, at most `limit` bytes of it.
pub fn read_text(path: &Path, limit: u64) -> Result<String, ReadError> {
    String::from_utf8(read_bytes(path, limit)?).map_err(|_| ReadError::NotText)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_fifo_a_device_and_a_folder_are_refused_without_blocking() {
        let dir = tempfile::tempdir().unwrap();
        let fifo = dir.path().join("f.conf");
        let c_path = std::ffi::CString::new(fifo.to_str().unwrap()).unwrap();
        // SAFETY: a valid NUL-terminated path and a plain mode.
        assert_eq!(unsafe { libc::mkfifo(c_path.as_ptr(), 0o600) }, 0);
        for path in [fifo.as_path(), Path::new("/dev/zero"), dir.path()] {
            let error = read_text(path, MAX_CONFIG_BYTES).unwrap_err();
            assert!(matches!(error, ReadError::NotRegular), "{path:?}: {error}");
        }
    }

    #[test]
    fn a_file_is_read_up_to_its_limit_and_refused_past_it() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("a.txt");
        std::fs::write(&path, "12345").unwrap();
        assert_eq!(read_text(&path, 5).unwrap(), "12345");
        let error = read_text(&path, 4).unwrap_err();
        assert_eq!(
            error.to_string(),
            "5 bytes, more than the 4 bytes such a file may have"
        );
        std::fs::write(&path, [0xff, 0xfe]).unwrap();
        assert!(matches!(read_text(&path, 5), Err(ReadError::NotText)));
        assert!(matches!(
            read_text(&dir.path().join("missing"), 5),
            Err(ReadError::Io(_))
        ));
    }
}
