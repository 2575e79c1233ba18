//! Starting poses for the inverse kinematics of an arm without a closed-form guess: a
//! table of shoulder–elbow poses with where they put the camera, the nearest one turned
//! towards the target.

use super::{ArmModel, Controlled};
use nalgebra::Point3;
use std::f64::consts::TAU;

/// Poses per learned joint in the table.
const STEPS: usize = 16;

/// One tabled pose: the camera's distance from the base axis and height (m), its
/// bearing (rad), and the learned angles.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Seed {
    radius: f64,
    height: f64,
    bearing: f64,
    theta: Controlled,
}

/// The table of an arm as it is now.
#[derive(Debug, Clone, Default, PartialEq)]
pub(super) struct IkSeeds {
    seeds: Vec<Seed>,
}

impl IkSeeds {
    /// The elbow-up poses of a grid over the shoulder and elbow limits (base yaw at rest)
    /// whose wrist is solved inside its limits.
    pub(super) fn of(model: &ArmModel) -> IkSeeds {
        let [yaw, s, e] = model.learned();
        let at = |j: usize, n: usize| {
            let (lower, upper) = model.joints()[j].one_turn();
            lower + (upper - lower) * (n as f64 + 0.5) / STEPS as f64
        };
        let mut seeds = Vec::new();
        for i in 0..STEPS {
            for k in 0..STEPS {
                let theta = Controlled::new(model.rest()[yaw], at(s, i), at(e, k));
                let pose = model.pose_of(&theta);
                if model.wrist_fits(&pose) && model.is_elbow_up(&theta) {
                    let p = pose.camera.translation.vector;
                    seeds.push(Seed {
                        radius: p.x.hypot(p.y),
                        height: p.z,
                        bearing: p.y.atan2(p.x),
                        theta,
                    });
                }
            }
        }
        IkSeeds { seeds }
    }

    /// The tabled pose nearest `target` in distance from the base axis and height, its
    /// base turned so that the camera faces the target's bearing (inside the limits).
    pub(super) fn nearest(&self, model: &ArmModel, target: &Point3<f64>) -> Option<Controlled> {
        let radius = target.x.hypot(target.y);
        let seed = self.seeds.iter().min_by(|a, b| {
            let gap = |s: &Seed| (s.radius - radius).powi(2) + (s.height - target.z).powi(2);
            gap(a).total_cmp(&gap(b))
        })?;
        let yaw_joint = &model.joints()[model.learned()[0]];
        let mut yaw = seed.theta.x + target.y.atan2(target.x) - seed.bearing;
        for turn in [0.0, TAU, -TAU] {
            if yaw_joint.admits(yaw + turn) {
                yaw += turn;
                break;
            }
        }
        Some(Controlled::new(yaw, seed.theta.y, seed.theta.z))
    }
}
