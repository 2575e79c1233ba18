//! Forward kinematics of a chain for any joint vector: every body's frame and the camera's,
//! without allocating.

use super::chain::Chain;
use super::joint::motion;
use super::{DescriptionError, DescriptionErrorKind as Kind};
use nalgebra::Isometry3;

impl Chain {
    /// Writes the pose of every body's frame in the root frame into `frames` (one per body:
    /// the root's, then one per moving joint) for joint positions `q` (rad or m).
    pub fn body_frames(
        &self,
        q: &[f64],
        frames: &mut [Isometry3<f64>],
    ) -> Result<(), DescriptionError> {
        self.check_length(q.len(), self.joints.len())?;
        self.check_length(frames.len(), self.bodies.len())?;
        let mut pose = Isometry3::identity();
        frames[0] = pose;
        for ((joint, &position), frame) in self.joints.iter().zip(q).zip(&mut frames[1..]) {
            pose = pose * joint.origin * motion(joint.kind, &joint.axis, position);
            *frame = pose;
        }
        Ok(())
    }

    /// The camera's pose in the root frame for joint positions `q`, the camera sitting at
    /// `mount` in the camera link's frame.
    pub fn camera_pose(
        &self,
        q: &[f64],
        mount: &Isometry3<f64>,
    ) -> Result<Isometry3<f64>, DescriptionError> {
        self.check_length(q.len(), self.joints.len())?;
        let mut pose = Isometry3::identity();
        for (joint, &position) in self.joints.iter().zip(q) {
            pose = pose * joint.origin * motion(joint.kind, &joint.axis, position);
        }
        Ok(pose * self.camera_in_body * mount)
    }

    /// The pose of description link `link` in the root frame, given the body frames
    /// `body_frames` wrote; `None` for a link that is in no body of the chain.
    pub fn link_pose(&self, frames: &[Isometry3<f64>], link: usize) -> Option<Isometry3<f64>> {
        self.bodies.iter().zip(frames).find_map(|(body, frame)| {
            body.links
                .iter()
                .find(|(l, _)| *l == link)
                .map(|(_, pose)| frame * pose)
        })
    }

    fn check_length(&self, found: usize, expected: usize) -> Result<(), DescriptionError> {
        if found == expected {
            return Ok(());
        }
        Err(DescriptionError {
            file: self.file.clone(),
            kind: Kind::JointCount { expected, found },
        })
    }
}
