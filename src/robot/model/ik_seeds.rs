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
    /// The base yaw (rad) that turns the tabled poses, on average, to face the base's x
    /// axis, where reach spaces lie.
    yaw_middle: f64,
}

impl IkSeeds {
    /// The poses of a grid over the shoulder and elbow limits (base yaw at rest) whose
    /// wrist is solved inside its limits, on the branch the arm keeps to (none without one).
    pub(super) fn of(model: &ArmModel) -> IkSeeds {
        let Some(branch) = model.branch() else {
            return IkSeeds::default();
        };
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
                if model.wrist_fits(&pose) && branch.holds(theta.y, theta.z) {
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
        let (sin, cos) = seeds.iter().fold((0.0, 0.0), |(sin, cos), seed| {
            (sin + seed.bearing.sin(), cos + seed.bearing.cos())
        });
        let yaw_middle = model.rest()[yaw] - yaw_sense(model) * f64::atan2(sin, cos);
        IkSeeds { seeds, yaw_middle }
    }

    /// The base yaw (rad) that turns the tabled poses, on average, to face the base's x
    /// axis.
    pub(super) fn yaw_middle(&self) -> f64 {
        self.yaw_middle
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
        let turn = target.y.atan2(target.x) - seed.bearing;
        let mut yaw = seed.theta.x + turn * yaw_sense(model);
        for turn in [0.0, TAU, -TAU] {
            if yaw_joint.admits(yaw + turn) {
                yaw += turn;
                break;
            }
        }
        Some(Controlled::new(yaw, seed.theta.y, seed.theta.z))
    }
}

/// +1 when the base yaw turns the arm anticlockwise seen from above (its axis points up at
/// rest), −1 when its axis points down (a base frame upside down).
pub(super) fn yaw_sense(model: &ArmModel) -> f64 {
    let yaw = model.learned()[0];
    let frame = model.link_frames(&model.rest())[yaw];
    (frame.rotation * model.joints()[yaw].axis.into_inner())
        .z
        .signum()
}
