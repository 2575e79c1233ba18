//! What a description had to do without: warnings collected while reading (a run prints
//! them).

use std::fmt;

/// Something missing from a URDF that the description went on without.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum DescriptionWarning {
    /// A visual mesh whose file is not there: the visual element is left out.
    MissingVisualMesh {
        /// The link.
        link: String,
        /// The mesh as the URDF names it.
        filename: String,
    },
    /// A visual mesh in a format other than OBJ, STL and COLLADA: the visual element is left out.
    UnreadVisualMesh {
        /// The link.
        link: String,
        /// The mesh as the URDF names it.
        filename: String,
    },
    /// A collision mesh whose file is not there: a capsule between the link's origin and
    /// its farthest child joint takes its place.
    MissingCollisionMesh {
        /// The link.
        link: String,
        /// The mesh as the URDF names it.
        filename: String,
        /// The capsule's radius (m).
        radius: f64,
        /// The length of the capsule's segment (m); 0 for a ball at the link's origin.
        length: f64,
    },
}

impl DescriptionWarning {
    /// The mesh the warning is about, as the URDF names it.
    pub fn filename(&self) -> &str {
        match self {
            DescriptionWarning::MissingVisualMesh { filename, .. }
            | DescriptionWarning::UnreadVisualMesh { filename, .. }
            | DescriptionWarning::MissingCollisionMesh { filename, .. } => filename,
        }
    }
}

impl fmt::Display for DescriptionWarning {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            DescriptionWarning::MissingVisualMesh { link, filename } => {
                write!(
                    f,
                    "link `{link}`: visual mesh `{filename}` not found, left out"
                )
            }
            DescriptionWarning::UnreadVisualMesh { link, filename } => write!(
                f,
                "link `{link}`: visual mesh `{filename}` is not OBJ, STL or COLLADA, left out"
            ),
            DescriptionWarning::MissingCollisionMesh {
                link,
                filename,
                radius,
                length,
            } => write!(
                f,
                "link `{link}`: collision mesh `{filename}` not found, replaced by a capsule \
                 ({:.1} cm long, radius {:.1} cm)",
                length * 100.0,
                radius * 100.0
            ),
        }
    }
}
