//! How far the arm is from touching itself or an obstacle: the self-collision and
//! obstacle rule both simulators share (the dynamic one plans its
//! moves with it, then its own contacts are the backstop).
//!
//! Which links may touch: those that are not neighbours in the chain and do not already
//! touch at the zero pose (the wrist's three links share its centre). Every link but the
//! base may touch an obstacle.
//!
//! A collision mesh is measured as its convex hull. Cheap first: each collision
//! element is held by a capsule (a cylinder or capsule by its own segment, a box by its
//! longest axis, a ball by its centre, a hull by its bounding box's), and the distance
//! between capsules, or between a link's and an obstacle's bounding boxes, bounds the true
//! distance from below. Only a pair whose bound is under [`NEAR`] is measured exactly
//! (parry; a hull first by its bounding box, then, under [`NEAR`] still, itself).

use super::capsule::Capsule;
use super::collision::{body_elements, Elements};
use super::part::{hull, part, parts_distance, Part, NEAR};
use super::world::Obstacle;
use crate::robot::dynamic::{parts, to_pose};
use crate::robot::{ArmModel, Frames, Joints, MAX_JOINTS};
use nalgebra::Isometry3;
use rapier3d_f64::parry::query::intersection_test;

/// The most bodies an arm has: the base and one per joint (the camera on the last).
pub(super) const MAX_BODIES: usize = MAX_JOINTS + 1;

/// The arm's bodies as parts, the pairs of bodies that may touch, and how far each body
/// reaches from each joint's axis.
#[derive(Debug, Clone, Default)]
pub(crate) struct ArmGeometry {
    /// Each body's parts: the base's, then one body per joint.
    pub(super) bodies: Vec<Vec<Part>>,
    /// Each body's capsule holding all its parts (none for a body without any, or past
    /// the arm's last body).
    pub(super) hulls: [Option<Capsule>; MAX_BODIES],
    pub(super) pairs: Vec<(usize, usize)>,
    /// `reach[k][j]` (j ≥ k ≥ 1): the farthest a point of body j can be from the axis of
    /// joint k (m): the joint origins from body k to body j, and body j's own extent.
    reach: [[f64; MAX_BODIES]; MAX_BODIES],
}

impl ArmGeometry {
    /// The geometry of `model` as it is now.
    pub(crate) fn new(model: &ArmModel) -> ArmGeometry {
        let elements: Vec<Elements> = (0..=model.dof()).map(|k| body_elements(model, k)).collect();
        let bodies: Vec<Vec<Part>> = elements
            .iter()
            .map(|body| body.iter().map(part).collect())
            .collect();
        let extent = |parts: &[Part]| {
            parts
                .iter()
                .map(|p| {
                    let [a, b] = p.capsule.ends;
                    a.coords.norm().max(b.coords.norm()) + p.capsule.radius
                })
                .fold(0.0, f64::max)
        };
        let origins: Vec<f64> = model
            .joints()
            .iter()
            .map(|j| j.origin.translation.vector.norm())
            .collect();
        let mut reach = [[0.0; MAX_BODIES]; MAX_BODIES];
        for k in 1..bodies.len() {
            for j in k..bodies.len() {
                reach[k][j] = origins[k..j].iter().sum::<f64>() + extent(&bodies[j]);
            }
        }
        ArmGeometry {
            pairs: contact_pairs(model, &elements),
            hulls: std::array::from_fn(|k| bodies.get(k).and_then(|parts| hull(parts))),
            bodies,
            reach,
        }
    }

    /// The fraction of a move, turning the joints at `rates` (rad per move), that surely
    /// passes before anything touches, from the arm with its links placed at `links`: each
    /// pair's distance over how fast the joints between them can close it (distances exact
    /// under [`NEAR`], lower bounds above it); 0 when something touches. And the smallest
    /// distance measured between two bodies (m; infinite without pairs).
    pub(super) fn allowance_at(
        &self,
        links: &Frames,
        rates: &[f64; MAX_BODIES],
        obstacles: &[Obstacle],
    ) -> (f64, f64) {
        let frame = |k: usize| match k {
            0 => Isometry3::identity(),
            _ => links[k - 1],
        };
        let placed: [Option<Capsule>; MAX_BODIES] =
            std::array::from_fn(|k| self.hulls[k].map(|h| h.placed(&frame(k))));
        let mut allow = f64::INFINITY;
        let mut nearest = f64::INFINITY;
        let mut take = |gap: f64, speed: f64| {
            if gap.is_nan() || gap <= 0.0 {
                allow = 0.0;
            } else if speed > 0.0 {
                allow = allow.min(gap / speed);
            }
        };
        for &(i, j) in &self.pairs {
            let (Some(hull_i), Some(hull_j)) = (placed[i], placed[j]) else {
                continue;
            };
            let bound = hull_i.distance(&hull_j);
            let gap = if bound >= NEAR {
                bound
            } else {
                let (at_i, at_j) = (frame(i), frame(j));
                let parts = self.bodies[i].iter().flat_map(|a| {
                    self.bodies[j]
                        .iter()
                        .map(move |b| parts_distance(a, &at_i, b, &at_j))
                });
                parts.fold(f64::INFINITY, f64::min)
            };
            nearest = nearest.min(gap);
            take(gap, self.pair_speed(rates, i, j));
        }
        if !obstacles.is_empty() {
            for (k, at) in links.iter().enumerate() {
                take(self.allowance_of(k + 1, at, obstacles, rates), 1.0);
            }
        }
        (allow, nearest)
    }

    /// The smallest distance (m) between two bodies that may touch, with the links placed
    /// at `links`: exact under [`NEAR`], a lower bound above it; 0 or less when they touch.
    pub(crate) fn nearest_gap(&self, links: &Frames) -> f64 {
        self.allowance_at(links, &[0.0; MAX_BODIES], &[]).1
    }

    /// How fast (m per move) the joints turning at `rates` can bring bodies `i` < `j`
    /// together: the turns of the joints between them times how far body j reaches from
    /// their axes.
    pub(super) fn pair_speed(&self, rates: &[f64; MAX_BODIES], i: usize, j: usize) -> f64 {
        (i + 1..=j).map(|k| rates[k] * self.reach[k][j]).sum()
    }

    /// What [`allowance_at`](Self::allowance_at) gives for body `k` placed at `at` against
    /// `obstacles` alone.
    fn allowance_of(
        &self,
        k: usize,
        at: &Isometry3<f64>,
        obstacles: &[Obstacle],
        rates: &[f64; MAX_BODIES],
    ) -> f64 {
        let Some(hull) = self.hulls[k].map(|h| h.placed(at)) else {
            return f64::INFINITY;
        };
        let closing: f64 = (1..=k).map(|j| rates[j] * self.reach[j][k]).sum();
        let mut allow = f64::INFINITY;
        for obstacle in obstacles {
            let bound = hull.box_gap(obstacle);
            let gap = if bound >= NEAR {
                bound
            } else {
                let (pose, cuboid) = obstacle.parts();
                let shapes = self.bodies[k]
                    .iter()
                    .map(|a| a.distance_to(&to_pose(at), &pose, &cuboid));
                shapes.fold(f64::INFINITY, f64::min)
            };
            if gap.is_nan() || gap <= 0.0 {
                return 0.0;
            }
            if closing > 0.0 {
                allow = allow.min(gap / closing);
            }
        }
        allow
    }

    /// The first link (1 for joint 1's body) and obstacle (1-based) that touch with the arm
    /// at `q`, if any.
    pub(crate) fn inside_obstacle(
        &self,
        model: &ArmModel,
        q: &Joints,
        obstacles: &[Obstacle],
    ) -> Option<(usize, usize)> {
        if obstacles.is_empty() {
            return None;
        }
        let links = model.link_frames(q);
        let rates = [0.0; MAX_BODIES];
        for (i, obstacle) in obstacles.iter().enumerate() {
            let one = std::slice::from_ref(obstacle);
            for (k, at) in links.iter().enumerate() {
                if self.allowance_of(k + 1, at, one, &rates) <= 0.0 {
                    return Some((k + 1, i + 1));
                }
            }
        }
        None
    }
}

/// The pairs of bodies (0 the base, then one per joint; `bodies` their elements) that may
/// touch: not neighbours in the chain, and apart at the zero pose.
pub(crate) fn contact_pairs(model: &ArmModel, bodies: &[Elements]) -> Vec<(usize, usize)> {
    let links = model.link_frames(&Joints::zeros(model.dof()));
    let frame = |k: usize| match k {
        0 => Isometry3::identity(),
        _ => links[k - 1],
    };
    let touch = |i: usize, j: usize| {
        bodies[i].iter().any(|(p, s)| {
            bodies[j].iter().any(|(q, t)| {
                let (a, shape_a) = parts(&(frame(i) * p), s);
                let (b, shape_b) = parts(&(frame(j) * q), t);
                intersection_test(&a, shape_a.as_ref(), &b, shape_b.as_ref())
                    .map_or(true, |hit| hit.intersecting)
            })
        })
    };
    let mut pairs = Vec::new();
    for i in 0..bodies.len() {
        for j in i + 2..bodies.len() {
            if !bodies[i].is_empty() && !bodies[j].is_empty() && !touch(i, j) {
                pairs.push((i, j));
            }
        }
    }
    pairs
}
#[cfg(test)]
mod tests {
    use super::super::part::exact;
    use super::*;
    use crate::robot::Controlled;
    use nalgebra::Vector3;

    #[test]
    fn a_bodys_hull_holds_its_parts() {
        let model = ArmModel::oscar6();
        let geometry = ArmGeometry::new(&model);
        // Link 6: the flange cylinder and the camera box; the hull reaches both.
        let hull = geometry.hulls[6].unwrap();
        for part in &geometry.bodies[6] {
            let reach = Capsule {
                ends: hull.ends,
                radius: hull.radius + 1e-12,
            };
            for end in part.capsule.ends {
                let point = Capsule {
                    ends: [end, end],
                    radius: part.capsule.radius,
                };
                assert!(reach.distance(&point) <= -2.0 * part.capsule.radius + 1e-9);
            }
        }
    }

    #[test]
    fn capsules_hold_their_shapes_and_bound_the_distance_from_below() {
        let model = ArmModel::oscar6();
        let geometry = ArmGeometry::new(&model);
        // The upper arm and the wrist, the column and the forearm may meet; neighbours and
        // the wrist's links, which share its centre, may not.
        for pair in [(2, 4), (1, 3), (2, 6)] {
            assert!(
                geometry.pairs.contains(&pair),
                "{pair:?}: {:?}",
                geometry.pairs
            );
        }
        for pair in [(1, 2), (4, 6), (4, 5)] {
            assert!(!geometry.pairs.contains(&pair), "{pair:?}");
        }
        let q = model.full_pose(&Controlled::new(0.2, 0.4, 1.9));
        let rates = [1.0; MAX_BODIES];
        assert!(geometry.allowance_at(&model.link_frames(&q), &rates, &[]).0 > 0.0);
        let at = |k: usize| model.link_frames(&q)[k - 1];
        for &(i, j) in geometry.pairs.iter().filter(|(i, _)| *i > 0) {
            for a in &geometry.bodies[i] {
                for b in &geometry.bodies[j] {
                    let capsules = a.capsule.placed(&at(i)).distance(&b.capsule.placed(&at(j)));
                    let true_gap = exact(
                        &(to_pose(&at(i)) * a.pose),
                        a.shape.as_ref(),
                        &(to_pose(&at(j)) * b.pose),
                        b.shape.as_ref(),
                    );
                    assert!(
                        capsules <= true_gap + 1e-12,
                        "{i}-{j}: {capsules} > {true_gap}"
                    );
                }
            }
        }
    }

    /// The exact distance between bodies `i` and `j` with the links placed at `links`.
    fn body_gap(geometry: &ArmGeometry, links: &Frames, i: usize, j: usize) -> f64 {
        let frame = |k: usize| match k {
            0 => Isometry3::identity(),
            _ => links[k - 1],
        };
        let (at_i, at_j) = (frame(i), frame(j));
        geometry.bodies[i]
            .iter()
            .flat_map(|a| {
                geometry.bodies[j]
                    .iter()
                    .map(move |b| parts_distance(a, &at_i, b, &at_j))
            })
            .fold(f64::INFINITY, f64::min)
    }

    #[test]
    fn the_pandas_hand_touching_its_own_arm_is_a_contact() {
        use crate::robot::{ArmSettings, DescriptionOptions, RobotDescription};
        use rand::{Rng, SeedableRng};
        let path =
            std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/panda/panda.urdf");
        let description = RobotDescription::load(&path, &DescriptionOptions::default()).unwrap();
        let settings = ArmSettings {
            camera_link: "panda_hand".into(),
            camera_offset: Vector3::zeros(),
            learned_joints: ["panda_joint1", "panda_joint2", "panda_joint4"].into(),
            ..ArmSettings::default()
        };
        let model = ArmModel::from_description(&description, &settings).unwrap();
        let geometry = ArmGeometry::new(&model);
        // The hand (with the camera and the held fingers) is the seventh link, body 7: it
        // may meet the base and links 1–4.
        let hand = model.dof();
        assert_eq!(hand, 7);
        for i in 0..=4 {
            assert!(geometry.pairs.contains(&(i, hand)), "{:?}", geometry.pairs);
        }
        // No move that keeps the camera looking down folds the hand onto the arm within
        // the Panda's limits, so any pose will do: the first of seeded random poses where
        // the hand, and only the hand, touches another link.
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(1);
        let touching = (0..20_000).find_map(|_| {
            let q = Joints::from_fn(model.dof(), |i| {
                let (low, high) = model.joints()[i].one_turn();
                rng.random_range(low..high)
            });
            let links = model.link_frames(&q);
            let touches = |&&(i, j): &&(usize, usize)| body_gap(&geometry, &links, i, j) <= 0.0;
            let (with_hand, others): (Vec<_>, Vec<_>) =
                geometry.pairs.iter().partition(|(_, j)| *j == hand);
            (with_hand.iter().any(touches) && !others.iter().any(touches)).then_some(q)
        });
        let q = touching.expect("a pose where the hand touches the arm");
        let still = [0.0; MAX_BODIES];
        assert_eq!(
            geometry.allowance_at(&model.link_frames(&q), &still, &[]).0,
            0.0
        );
    }
}
