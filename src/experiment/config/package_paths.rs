//! The `package_paths` config entry: folders searched for a URDF's `package://` meshes.

use super::values::ConfigValue;
use super::ValueError;
use std::path::{Path, PathBuf};

/// Folders searched, in order, for a URDF's `package://NAME/rest` meshes; empty for
/// `none` (the default).
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct PackagePaths(pub Vec<PathBuf>);

impl PackagePaths {
    /// Every relative folder taken from `base` (a config file's folder) instead of the
    /// working folder, made absolute when it exists (so a run folder's copy of the config
    /// finds it from anywhere).
    pub fn relative_to(&mut self, base: &Path) {
        for path in &mut self.0 {
            if path.is_relative() {
                let joined = base.join(&*path);
                *path = std::fs::canonicalize(&joined).unwrap_or(joined);
            }
        }
    }

    /// The first folder that is not a folder on disk.
    pub fn missing_folder(&self) -> Option<&Path> {
        self.0.iter().map(PathBuf::as_path).find(|p| !p.is_dir())
    }
}

/// `none`, or folders `a,b,c` (no empty item; the config format allows no spaces).
impl ConfigValue for PackagePaths {
    const KIND: &'static str = "none or folders a,b";
    fn parse_value(raw: &str) -> Result<Self, ValueError> {
        if raw == "none" {
            return Ok(PackagePaths::default());
        }
        let folders: Vec<PathBuf> = raw
            .split(',')
            .map(|part| (!part.is_empty()).then(|| PathBuf::from(part)))
            .collect::<Option<_>>()
            .ok_or_else(|| ValueError::BadList {
                text: raw.to_string(),
                expected: "`none` or comma-separated folders",
            })?;
        Ok(PackagePaths(folders))
    }

    fn render(&self) -> String {
        if self.0.is_empty() {
            return "none".to_string();
        }
        let folders: Vec<String> = self.0.iter().map(|p| p.display().to_string()).collect();
        folders.join(",")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn folders_parse_render_and_resolve_from_the_config_folder() {
        assert_eq!(PackagePaths::parse_value("none").unwrap().0.len(), 0);
        assert_eq!(PackagePaths::default().render(), "none");
        let mut paths = PackagePaths::parse_value("robots,/opt/ros/share").unwrap();
        assert_eq!(paths.render(), "robots,/opt/ros/share");
        paths.relative_to(Path::new("configs/lab"));
        assert_eq!(paths.render(), "configs/lab/robots,/opt/ros/share");
        for bad in ["a,,b", ",a", "a,", ""] {
            assert!(PackagePaths::parse_value(bad).is_err(), "{bad}");
        }
        assert_eq!(
            paths.missing_folder(),
            Some(Path::new("configs/lab/robots"))
        );
        assert_eq!(PackagePaths(vec![".".into()]).missing_folder(), None);
    }
}
