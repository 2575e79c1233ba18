//! The `urdf` config entry: the arm's URDF file, or the shipped OSCAR-6.

use super::values::ConfigValue;
use super::ValueError;
use std::path::{Path, PathBuf};

/// The arm's URDF: a file, or `shipped` (the default) for the OSCAR-6 built into the
/// program (`urdf/oscar6.urdf`).
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct UrdfFile(pub Option<PathBuf>);

impl UrdfFile {
    /// The file, `None` for the shipped OSCAR-6.
    pub fn path(&self) -> Option<&Path> {
        self.0.as_deref()
    }

    /// A relative file taken from `base` (a config file's folder) instead of the working
    /// folder, made absolute when it exists (so a run folder's copy of the config finds it
    /// from anywhere).
    pub fn relative_to(&mut self, base: &Path) {
        if let Some(path) = self.0.as_mut().filter(|p| p.is_relative()) {
            let joined = base.join(&*path);
            *path = std::fs::canonicalize(&joined).unwrap_or(joined);
        }
    }
}

/// `shipped`, or a file's path (the config format allows no spaces).
impl ConfigValue for UrdfFile {
    const KIND: &'static str = "shipped or a file";
    fn parse_value(raw: &str) -> Result<Self, ValueError> {
        Ok(UrdfFile((raw != "shipped").then(|| PathBuf::from(raw))))
    }

    fn render(&self) -> String {
        self.path()
            .map_or("shipped".to_string(), |p| p.display().to_string())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_file_parses_renders_and_resolves_from_the_config_folder() {
        assert_eq!(UrdfFile::parse_value("shipped").unwrap(), UrdfFile(None));
        assert_eq!(UrdfFile::default().render(), "shipped");
        let mut file = UrdfFile::parse_value("arms/ur5.urdf").unwrap();
        file.relative_to(Path::new("configs/lab"));
        assert_eq!(file.render(), "configs/lab/arms/ur5.urdf");
        let mut absolute = UrdfFile::parse_value("/opt/arm.urdf").unwrap();
        absolute.relative_to(Path::new("configs"));
        assert_eq!(absolute.path(), Some(Path::new("/opt/arm.urdf")));
    }
}
