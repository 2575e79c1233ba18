//! A `.xacro` description expanded to URDF by the `xacro` program (PyPI's `xacro`, or
//! ROS's), found on the PATH.

use super::DescriptionErrorKind as Kind;
use std::path::Path;
use std::process::{Command, Stdio};

/// The program that expands xacro files.
const XACRO: &str = "xacro";
/// At most this many bytes of the program's error output are kept for the message.
const MAX_REASON_BYTES: usize = 2000;

/// True when `path` names a xacro file (`.xacro`, `.urdf.xacro`).
pub(super) fn is_xacro(path: &Path) -> bool {
    path.extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("xacro"))
}

/// The URDF text `xacro FILE` writes (at most `limit` bytes), or why there is none: the
/// program is not installed, or it failed (its exit status and what it said).
pub(super) fn expand(path: &Path, limit: u64) -> Result<String, Kind> {
    let output = Command::new(XACRO)
        .arg(path)
        .stdin(Stdio::null())
        .output()
        .map_err(|e| match e.kind() {
            std::io::ErrorKind::NotFound => Kind::XacroMissing,
            _ => Kind::XacroFailed {
                status: None,
                reason: e.to_string(),
            },
        })?;
    if !output.status.success() {
        let said = String::from_utf8_lossy(&output.stderr);
        let said = said.trim();
        let start = said.len().saturating_sub(MAX_REASON_BYTES);
        let start = (start..said.len())
            .find(|&i| said.is_char_boundary(i))
            .unwrap_or(said.len());
        return Err(Kind::XacroFailed {
            status: output.status.code(),
            reason: said[start..].to_string(),
        });
    }
    if output.stdout.len() as u64 > limit {
        return Err(Kind::XacroFailed {
            status: Some(0),
            reason: format!("it wrote more than {limit} bytes"),
        });
    }
    String::from_utf8(output.stdout).map_err(|_| Kind::XacroFailed {
        status: Some(0),
        reason: "it wrote text that is not UTF-8".to_string(),
    })
}
