//! Whether a pose keeps its links clear of the floor and of each other by a margin: the
//! rule the reach space is fitted by, and `reach` reports its target poses by.

use super::clearance::ArmGeometry;
use super::collision::{body_elements, Elements};
use super::floor::lowest_point;
use crate::robot::{ArmModel, ArmPose};

/// How far (m) every link must stay from the floor and from the links it may touch for a
/// pose to count as free of contact.
pub const CONTACT_MARGIN: f64 = 0.01;

/// What a pose comes within [`CONTACT_MARGIN`] of.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Touch {
    /// A link or the camera is below the floor or less than the margin above it.
    Floor,
    /// Two links that may touch are less than the margin apart.
    Links,
}

/// An arm's collision geometry, ready to tell which of its poses are free of contact.
#[derive(Debug, Clone)]
pub struct ContactRule {
    bodies: Vec<Elements>,
    geometry: ArmGeometry,
    floor_z: f64,
}

impl ContactRule {
    /// The rule for `model` as it is now over a floor at `floor_z` (m, world frame).
    pub fn new(model: &ArmModel, floor_z: f64) -> ContactRule {
        ContactRule {
            bodies: (1..=model.dof()).map(|k| body_elements(model, k)).collect(),
            geometry: ArmGeometry::new(model),
            floor_z,
        }
    }

    /// What `pose` of `model` comes within [`CONTACT_MARGIN`] of, if anything (the floor
    /// looked at first).
    pub fn touch(&self, model: &ArmModel, pose: &ArmPose) -> Option<Touch> {
        if lowest_point(model, &self.bodies, &pose.joints) < self.floor_z + CONTACT_MARGIN {
            Some(Touch::Floor)
        } else if self.geometry.nearest_gap(&pose.frames) < CONTACT_MARGIN {
            Some(Touch::Links)
        } else {
            None
        }
    }
}
