//! A robot description read from any URDF whose links form a tree.

use super::convert;
use super::geometry::GeometryReader;
use super::joint::Joint;
use super::link::Link;
use super::tree::tree_shape;
use super::xacro;
use super::{DescriptionError, DescriptionErrorKind as Kind, DescriptionWarning};
use nalgebra::Point3;
use std::path::{Path, PathBuf};

/// Where to look for what a URDF refers to.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct DescriptionOptions {
    /// Folders searched for `package://NAME/...` meshes, in order: `FOLDER/NAME/...`, or
    /// `FOLDER/...` when FOLDER is itself named NAME. Default: none (such meshes are missing).
    pub package_paths: Vec<PathBuf>,
}

/// A robot's links and joints as a tree, with the warnings met while reading it.
#[derive(Debug, Clone, PartialEq)]
pub struct RobotDescription {
    /// The robot's name in the URDF.
    pub name: String,
    /// The URDF file as the user named it (errors name it).
    pub file: String,
    /// The links in URDF order.
    pub links: Vec<Link>,
    /// The joints in URDF order.
    pub joints: Vec<Joint>,
    /// The index of the root link (the world frame).
    pub root: usize,
    /// What was missing and what stands in for it.
    pub warnings: Vec<DescriptionWarning>,
}

impl RobotDescription {
    /// Reads a URDF file, or a xacro file (`.xacro`) expanded by the `xacro` program;
    /// meshes are looked up relative to its folder.
    pub fn load(path: &Path, options: &DescriptionOptions) -> Result<Self, DescriptionError> {
        let file = path.display().to_string();
        let limit = crate::files::MAX_URDF_BYTES;
        let fail = |kind| DescriptionError {
            file: file.clone(),
            kind,
        };
        let text = crate::files::read_text(path, limit).map_err(|e| {
            fail(Kind::Unreadable {
                reason: e.to_string(),
            })
        })?;
        let text = if xacro::is_xacro(path) {
            xacro::expand(path, limit).map_err(fail)?
        } else {
            text
        };
        let folder = path.parent().unwrap_or(Path::new("."));
        Self::parse(&text, &file, folder, options)
    }

    /// Reads URDF text; `file` names it in errors, relative meshes are looked up in `folder`.
    pub fn parse(
        text: &str,
        file: &str,
        folder: &Path,
        options: &DescriptionOptions,
    ) -> Result<Self, DescriptionError> {
        read(text, file, folder, options).map_err(|kind| DescriptionError {
            file: file.to_string(),
            kind,
        })
    }

    /// The index of the link named `name`.
    pub fn link_index(&self, name: &str) -> Option<usize> {
        self.links.iter().position(|l| l.name == name)
    }

    /// The index of the joint named `name`.
    pub fn joint_index(&self, name: &str) -> Option<usize> {
        self.joints.iter().position(|j| j.name == name)
    }

    /// An error of this description's file.
    pub(super) fn error(&self, kind: Kind) -> DescriptionError {
        DescriptionError {
            file: self.file.clone(),
            kind,
        }
    }
}

fn read(
    text: &str,
    file: &str,
    folder: &Path,
    options: &DescriptionOptions,
) -> Result<RobotDescription, Kind> {
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    let robot = urdf_rs::read_from_string(text).map_err(|e| Kind::NotUrdf {
        reason: e.to_string(),
    })?;
    let shape = tree_shape(&robot)?;
    let link_index = |name: &str| {
        robot
            .links
            .iter()
            .position(|l| l.name == name)
            .expect("checked by tree_shape")
    };
    let joints = robot
        .joints
        .iter()
        .map(|j| convert::joint(j, link_index))
        .collect::<Result<Vec<_>, _>>()?;
    let mut geometry = GeometryReader::new(folder, &options.package_paths);
    let mut links = Vec::with_capacity(robot.links.len());
    for (i, link) in robot.links.iter().enumerate() {
        let child_joints: Vec<usize> = (0..joints.len())
            .filter(|&j| joints[j].parent == i)
            .collect();
        let child_origins: Vec<Point3<f64>> = child_joints
            .iter()
            .map(|&j| Point3::from(joints[j].origin.translation.vector))
            .collect();
        links.push(Link {
            name: link.name.clone(),
            inertial: convert::inertial(link)?,
            visuals: geometry.visuals(link)?,
            collisions: geometry.collisions(link, &child_origins)?,
            parent_joint: shape.parent_joint[i],
            child_joints,
        });
    }
    Ok(RobotDescription {
        name: robot.name.clone(),
        file: file.to_string(),
        links,
        joints,
        root: shape.root,
        warnings: geometry.warnings,
    })
}
