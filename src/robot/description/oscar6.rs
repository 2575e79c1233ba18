//! The arm of a URDF at the default arm settings (the OSCAR-6's camera link and learned
//! joints), read as a robot description; the shipped OSCAR-6 built into the binary.

use super::{DescriptionError, DescriptionOptions, RobotDescription};
use crate::robot::{ArmModel, ArmSettings};
use std::path::Path;

/// The shipped OSCAR-6 URDF, built into the binary.
pub const DEFAULT_URDF: &str = include_str!("../../../urdf/oscar6.urdf");
/// The name the built-in URDF is reported under.
pub const DEFAULT_URDF_NAME: &str = "urdf/oscar6.urdf";

/// Reads the URDF file at `path` (meshes relative to its folder) and cuts the arm the
/// default [`ArmSettings`] pick out of it.
pub fn load_urdf(path: &Path) -> Result<ArmModel, DescriptionError> {
    let description = RobotDescription::load(path, &DescriptionOptions::default())?;
    ArmModel::from_description(&description, &ArmSettings::default())
}

/// Reads URDF text (`file` names it in errors, meshes are looked up relative to the
/// working folder) and cuts the arm the default [`ArmSettings`] pick out of it.
pub fn parse_urdf(text: &str, file: &str) -> Result<ArmModel, DescriptionError> {
    let options = DescriptionOptions::default();
    let description = RobotDescription::parse(text, file, Path::new("."), &options)?;
    ArmModel::from_description(&description, &ArmSettings::default())
}
