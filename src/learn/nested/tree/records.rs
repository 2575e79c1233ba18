//! Where stored learning patterns live: in memory, or in the run's `pat_file`.
//!
//! Patterns are records numbered in the order they were first written. A record is
//! overwritten in place when its bin is full and drops its oldest pattern, so the file
//! grows only with new records. On disk a record is the input followed by the target, each
//! value a little-endian `f64`; the file has no header and is meant for this program only.

use crate::learn::LearnError;
use crate::learn::Pattern;
use nalgebra::{SVector, Vector3};
use std::fs::File;
use std::io::{Read, Seek, SeekFrom, Write};
use std::path::{Path, PathBuf};

/// The most values a record holds (8 inputs and 3 targets).
const MAX_VALUES: usize = 11;

/// The stored patterns, by record number.
#[derive(Debug)]
pub(crate) enum Records<const N: usize> {
    /// Kept in memory.
    Memory(Vec<Pattern<N>>),
    /// Kept in a file.
    File(PatFile),
}

/// A `pat_file`: the file and how many records it holds.
#[derive(Debug)]
pub(crate) struct PatFile {
    path: PathBuf,
    file: File,
    records: u32,
}

impl<const N: usize> Records<N> {
    const RECORD_BYTES: usize = 8 * (N + 3);
    const FITS: () = assert!(N + 3 <= MAX_VALUES, "a record holds at most 11 values");

    /// Patterns kept in memory.
    pub(crate) fn in_memory() -> Self {
        Records::Memory(Vec::new())
    }

    /// Patterns kept in the file at `path`, created (or emptied) now.
    pub(crate) fn in_file(path: &Path) -> Result<Self, LearnError> {
        let () = Self::FITS;
        let file = File::options()
            .read(true)
            .write(true)
            .create(true)
            .truncate(true)
            .open(path)
            .map_err(|source| pat_file_error(path, source))?;
        Ok(Records::File(PatFile {
            path: path.to_path_buf(),
            file,
            records: 0,
        }))
    }

    /// Records held.
    pub(crate) fn len(&self) -> usize {
        match self {
            Records::Memory(patterns) => patterns.len(),
            Records::File(f) => f.records as usize,
        }
    }

    /// Adds a record; returns its number.
    pub(crate) fn push(&mut self, pattern: &Pattern<N>) -> Result<u32, LearnError> {
        let id = self.len() as u32;
        match self {
            Records::Memory(patterns) => patterns.push(*pattern),
            Records::File(f) => {
                f.write_at(id, Self::RECORD_BYTES, &encode(pattern))?;
                f.records += 1;
            }
        }
        Ok(id)
    }

    /// Replaces record `id`.
    pub(crate) fn overwrite(&mut self, id: u32, pattern: &Pattern<N>) -> Result<(), LearnError> {
        match self {
            Records::Memory(patterns) => {
                patterns[id as usize] = *pattern;
                Ok(())
            }
            Records::File(f) => f.write_at(id, Self::RECORD_BYTES, &encode(pattern)),
        }
    }

    /// Record `id`.
    pub(crate) fn read(&mut self, id: u32) -> Result<Pattern<N>, LearnError> {
        match self {
            Records::Memory(patterns) => Ok(patterns[id as usize]),
            Records::File(f) => {
                let mut bytes = [0u8; 8 * MAX_VALUES];
                f.read_at(id, &mut bytes[..Self::RECORD_BYTES])?;
                Ok(decode(&bytes))
            }
        }
    }

    /// Drops every record (the file is emptied).
    pub(crate) fn clear(&mut self) -> Result<(), LearnError> {
        match self {
            Records::Memory(patterns) => patterns.clear(),
            Records::File(f) => {
                f.file.set_len(0).map_err(|e| pat_file_error(&f.path, e))?;
                f.records = 0;
            }
        }
        Ok(())
    }
}

impl PatFile {
    fn seek_to(&mut self, id: u32, record_bytes: usize) -> Result<(), LearnError> {
        let offset = u64::from(id) * record_bytes as u64;
        self.file
            .seek(SeekFrom::Start(offset))
            .map(drop)
            .map_err(|e| pat_file_error(&self.path, e))
    }

    fn write_at(&mut self, id: u32, record_bytes: usize, bytes: &[u8]) -> Result<(), LearnError> {
        self.seek_to(id, record_bytes)?;
        self.file
            .write_all(&bytes[..record_bytes])
            .map_err(|e| pat_file_error(&self.path, e))
    }

    fn read_at(&mut self, id: u32, bytes: &mut [u8]) -> Result<(), LearnError> {
        self.seek_to(id, bytes.len())?;
        self.file
            .read_exact(bytes)
            .map_err(|e| pat_file_error(&self.path, e))
    }
}

fn pat_file_error(path: &Path, source: std::io::Error) -> LearnError {
    LearnError::PatFile {
        path: path.to_path_buf(),
        source,
    }
}

fn encode<const N: usize>(pattern: &Pattern<N>) -> [u8; 8 * MAX_VALUES] {
    let mut bytes = [0u8; 8 * MAX_VALUES];
    let values = pattern.input.iter().chain(pattern.target.iter());
    for (chunk, value) in bytes.chunks_exact_mut(8).zip(values) {
        chunk.copy_from_slice(&value.to_le_bytes());
    }
    bytes
}

fn decode<const N: usize>(bytes: &[u8; 8 * MAX_VALUES]) -> Pattern<N> {
    let value = |i: usize| {
        let chunk: [u8; 8] = bytes[8 * i..8 * i + 8].try_into().expect("8 bytes");
        f64::from_le_bytes(chunk)
    };
    Pattern {
        input: SVector::from_fn(|i, _| value(i)),
        target: Vector3::from_fn(|i, _| value(N + i)),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn pattern(seed: f64) -> Pattern<5> {
        Pattern {
            input: SVector::from_fn(|i, _| seed * (i as f64 + 1.0) - 0.1),
            target: Vector3::new(seed, -seed, 1.0 / seed),
        }
    }

    #[test]
    fn file_records_read_back_exactly_after_overwrites() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("pat_file");
        let mut records = Records::<5>::in_file(&path).unwrap();
        for i in 0..10 {
            assert_eq!(records.push(&pattern(i as f64 + 0.3)).unwrap(), i);
        }
        records.overwrite(4, &pattern(99.7)).unwrap();
        assert_eq!(records.len(), 10);
        assert_eq!(records.read(4).unwrap(), pattern(99.7));
        assert_eq!(records.read(9).unwrap(), pattern(9.3));
        assert_eq!(std::fs::metadata(&path).unwrap().len(), 10 * 64);
        records.clear().unwrap();
        assert_eq!(std::fs::metadata(&path).unwrap().len(), 0);
    }

    #[test]
    fn an_unwritable_pat_file_is_a_clear_error() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("no such folder").join("pat_file");
        let err = Records::<5>::in_file(&path).unwrap_err();
        assert!(matches!(err, LearnError::PatFile { .. }));
        assert!(err.to_string().contains("no such folder"), "{err}");
    }

    #[test]
    fn reading_past_the_end_is_an_error_not_garbage() {
        let dir = tempfile::tempdir().unwrap();
        let mut records = Records::<5>::in_file(&dir.path().join("pat_file")).unwrap();
        records.push(&pattern(1.0)).unwrap();
        assert!(matches!(records.read(3), Err(LearnError::PatFile { .. })));
    }
}
