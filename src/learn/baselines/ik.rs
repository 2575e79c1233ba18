//! The `ik` learner: not a learner at all but the model-based reference. It knows the
//! nominal URDF geometry and the camera, locates the object from the reading, and inverts
//! the arm's kinematics to command the move that puts the camera at the target. It is the
//! ceiling while the robot is as modelled, and shows what a fixed model does once a link is
//! stretched or the camera turned.

use crate::camera::{Camera, CameraModel, ProjectionCamera};
use crate::learn::MethodFacts;
use crate::learn::{LearnError, Learner, LearnerStats, Method};
use crate::learn::{Observation, Query};
use crate::robot::{ArmModel, Controlled};
use nalgebra::Vector3;

/// Inverse kinematics on the nominal model.
#[derive(Debug, Clone)]
pub struct IkLearner {
    model: ArmModel,
    camera: ProjectionCamera,
}

impl IkLearner {
    /// A controller that believes the robot is `model` and the camera `camera`.
    pub fn new(model: ArmModel, camera: CameraModel) -> IkLearner {
        IkLearner {
            model,
            camera: ProjectionCamera::new(camera),
        }
    }

    /// The move (rad) that puts the camera at the target, as the model sees it.
    fn model_move(&self, query: &Query) -> Option<Controlled> {
        let here = Controlled::new(
            0.0,
            query.theta2_deg.to_radians(),
            query.theta3_deg.to_radians(),
        );
        let object_local = self.camera.locate(&query.c)?;
        let pose = self.model.camera_pose(&self.model.full_pose(&here));
        let object = pose * nalgebra::Point3::from(object_local);
        let goal = self.camera.model().goal_point(&object);
        let there = self.model.solve_camera_position(&goal).ok()?;
        Some(there - here)
    }
}

impl Learner for IkLearner {
    fn name(&self) -> &str {
        Method::Ik.name()
    }

    fn propose(&mut self, query: &Query) -> Vector3<f64> {
        self.model_move(query)
            .map(|delta| delta.map(f64::to_degrees))
            .unwrap_or_else(Vector3::zeros)
    }

    fn learn(&mut self, _path: &[Observation]) -> Result<(), LearnError> {
        Ok(())
    }

    fn stats(&self) -> LearnerStats {
        LearnerStats::default()
    }
}

/// What the program knows of `ik` besides its learner (see [`Method::facts`](crate::learn::Method::facts)).
pub(crate) const IK_FACTS: MethodFacts = MethodFacts {
    name: "ik",
    size: |_| String::new(),
    counts_nodes: false,
    kb_per_trial: 0.0,
    bounded: false,
    watches_changes: false,
    slow_entries: "feedback_steps, bin_size, max_stored_patterns",
    // It learns nothing: 1,000 trials measure it.
    shared_defaults: &[("trials", "1000")],
};
