//! How far the arm is from touching itself or an obstacle, and where a move first would:
//! the self-collision and obstacle rule both simulators share (the dynamic one plans its
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
//! (parry; a hull first by its bounding box, then, under [`NEAR`] still, itself). A
//! move is marched in steps no pair can close its gap in, from the turns of the joints
//! between the two and how far the nearer end reaches: small moves far from contact cost
//! one look.

use super::collision::{body_elements, joint_turns, Elements, MoveStart};
use super::world::Obstacle;
use crate::robot::dynamic::{parts, to_pose};
use crate::robot::kinematic::motion::last_holding;
use crate::robot::{ArmModel, Controlled, Frames, Joints, Shape, MAX_JOINTS};
use nalgebra::{Isometry3, Point3, Translation3, Vector3};
use rapier3d_f64::math::Pose;
use rapier3d_f64::parry::query::{distance, intersection_test};
use rapier3d_f64::parry::shape::SharedShape;

/// A pair whose distance bound is under this (m) is measured exactly.
const NEAR: f64 = 0.01;
/// The shortest step of the march (a fraction of the move).
const MIN_MARCH: f64 = 1e-3;
/// The room (m) a known distance bound must leave over what a move can close for the
/// move to go unmeasured.
const KNOWN_GAP_MARGIN: f64 = 1e-9;
/// The most bodies an arm has: the base and one per joint (the camera on the last).
const MAX_BODIES: usize = MAX_JOINTS + 1;

/// A collision element: its parry shape at its pose in the body frame, the box around it
/// when it is a mesh's hull (pose and shape), and the capsule that holds it (segment ends
/// in the body frame, radius).
#[derive(Debug, Clone)]
struct Part {
    pose: Pose,
    shape: SharedShape,
    boxed: Option<(Pose, SharedShape)>,
    capsule: Capsule,
}

impl Part {
    /// The distance (m) from this part placed at `at` to `other`'s `shape` at `pose`: exact
    /// for a primitive and for a hull under [`NEAR`], the hull's box's distance above it.
    fn distance_to(
        &self,
        at: &Pose,
        pose: &Pose,
        shape: &dyn rapier3d_f64::parry::shape::Shape,
    ) -> f64 {
        if let Some((box_pose, cuboid)) = &self.boxed {
            let bound = exact(&(at * box_pose), cuboid.as_ref(), pose, shape);
            if bound >= NEAR {
                return bound;
            }
        }
        exact(&(at * self.pose), self.shape.as_ref(), pose, shape)
    }
}

/// The arm's bodies as parts, the pairs of bodies that may touch, and how far each body
/// reaches from each joint's axis.
#[derive(Debug, Clone, Default)]
pub(crate) struct ArmGeometry {
    /// Each body's parts: the base's, then one body per joint.
    bodies: Vec<Vec<Part>>,
    /// Each body's capsule holding all its parts (none for a body without any, or past
    /// the arm's last body).
    hulls: [Option<Capsule>; MAX_BODIES],
    pairs: Vec<(usize, usize)>,
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
    fn allowance_at(
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
    fn pair_speed(&self, rates: &[f64; MAX_BODIES], i: usize, j: usize) -> f64 {
        (i + 1..=j).map(|k| rates[k] * self.reach[k][j]).sum()
    }

    /// The most the move by `delta` can bring any pair of bodies together (m): what the
    /// bodies' distance bound at the start, less this, still bounds at its end.
    pub(crate) fn closing(&self, model: &ArmModel, delta: &Controlled) -> f64 {
        self.closing_at(&body_rates(model, delta))
    }

    /// [`closing`](Self::closing) with the bodies' joints turning at `rates`.
    fn closing_at(&self, rates: &[f64; MAX_BODIES]) -> f64 {
        self.pairs
            .iter()
            .map(|&(i, j)| self.pair_speed(rates, i, j))
            .fold(0.0, f64::max)
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

    /// How far along the controlled move from every joint at `start` by `delta` (fractions
    /// up to `up_to`) the arm gets before two of its bodies or a link and an obstacle touch: `up_to` when
    /// none do, or when they already touch at the start. Marches in steps no pair can close
    /// in, then bisects the contact. A point of body j moves, relative to body i, no faster
    /// than the turns of the joints between them times its reach from their axes; the
    /// learned joints turn by their share of the move, a wrist joint by at most θ2's and
    /// θ3's turns together (θ5 on the OSCAR-6), the other joints stay.
    ///
    /// `nearest` is a lower bound (m) on every pair's distance at the start, 0 when none is
    /// known: where it exceeds what the whole move can close and there are no obstacles,
    /// nothing is measured (the march would return `up_to` at its first look). Otherwise it
    /// becomes the smallest distance measured there.
    pub(crate) fn contact_stop(
        &self,
        model: &ArmModel,
        start: &MoveStart,
        delta: &Controlled,
        up_to: f64,
        obstacles: &[Obstacle],
        nearest: &mut f64,
    ) -> f64 {
        let theta = &start.theta;
        // A numerical wrist starts from the last pose looked at.
        let near = std::cell::Cell::new(start.pose.joints);
        let rates = body_rates(model, delta);
        if obstacles.is_empty()
            && *nearest > 0.0
            && *nearest > self.closing_at(&rates) * up_to + KNOWN_GAP_MARGIN
        {
            return up_to;
        }
        let allowance = |s: f64| {
            let pose = model.pose_near(&(theta + delta * s), &near.get());
            near.set(pose.joints);
            self.allowance_at(&pose.frames, &rates, obstacles).0
        };
        let (mut s, (mut now, measured)) = (
            0.0,
            self.allowance_at(&start.pose.frames, &rates, obstacles),
        );
        *nearest = measured.max(0.0);
        if now <= 0.0 {
            return up_to;
        }
        while s < up_to {
            if now >= up_to - s {
                return up_to; // the rest of the move cannot close any gap
            }
            let next = (s + now.max(MIN_MARCH)).min(up_to);
            let then = allowance(next);
            if then <= 0.0 {
                return last_holding(s, next, |middle| {
                    let allow = allowance(middle);
                    allow > 0.0 || allow.is_nan()
                });
            }
            (s, now) = (next, then);
        }
        up_to
    }
}

/// How fast (rad per move) each body's own joint turns in the move by `delta` (see
/// [`joint_turns`]): body k hangs from joint k - 1; the base (body 0) stays.
fn body_rates(model: &ArmModel, delta: &Controlled) -> [f64; MAX_BODIES] {
    let turns = joint_turns(model, delta);
    std::array::from_fn(|body| body.checked_sub(1).map_or(0.0, |joint| turns[joint]))
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

/// An element as a part: its parry shape and the capsule that holds it.
fn part((pose, shape): &(Isometry3<f64>, Shape)) -> Part {
    let along = |half: f64, axis: Vector3<f64>| {
        [
            pose * Point3::from(axis * -half),
            pose * Point3::from(axis * half),
        ]
    };
    let (ends, radius) = match *shape {
        Shape::Sphere { radius } => (along(0.0, Vector3::z()), radius),
        Shape::Cylinder { radius, length } | Shape::Capsule { radius, length } => {
            (along(0.5 * length, Vector3::z()), radius)
        }
        Shape::Cuboid(size) => box_capsule(pose, &Vector3::zeros(), &size),
        Shape::Mesh { centre, size, .. } => box_capsule(pose, &centre, &size),
    };
    let boxed = match shape {
        Shape::Mesh { centre, size, .. } => Some(parts(
            &(pose * Translation3::from(*centre)),
            &Shape::Cuboid(*size),
        )),
        _ => None,
    };
    let (pose, shape) = parts(pose, shape);
    Part {
        pose,
        shape,
        boxed,
        capsule: Capsule { ends, radius },
    }
}

/// The capsule holding a box of sides `size` centred at `centre` in the frame at `pose`:
/// its longest axis, as wide as the box's other two sides' diagonal.
fn box_capsule(
    pose: &Isometry3<f64>,
    centre: &Vector3<f64>,
    size: &Vector3<f64>,
) -> ([Point3<f64>; 2], f64) {
    let long = size.imax();
    let across = (size.norm_squared() - size[long] * size[long]).sqrt();
    let half = Vector3::ith(long, 0.5 * size[long]);
    (
        [
            pose * Point3::from(centre - half),
            pose * Point3::from(centre + half),
        ],
        0.5 * across,
    )
}

/// The distance between parts `a` and `b` of bodies at `at_a` and `at_b`: exact under
/// [`NEAR`], a lower bound above it (a hull's box's distance).
fn parts_distance(a: &Part, at_a: &Isometry3<f64>, b: &Part, at_b: &Isometry3<f64>) -> f64 {
    let (at_a, at_b) = (to_pose(at_a), to_pose(at_b));
    if let Some((box_pose, cuboid)) = &b.boxed {
        let bound = a.distance_to(&at_a, &(at_b * box_pose), cuboid.as_ref());
        if bound >= NEAR {
            return bound;
        }
    }
    a.distance_to(&at_a, &(at_b * b.pose), b.shape.as_ref())
}

/// A capsule: the points within `radius` of the segment between `ends`.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Capsule {
    ends: [Point3<f64>; 2],
    radius: f64,
}

impl Capsule {
    /// This capsule moved by `at`.
    fn placed(&self, at: &Isometry3<f64>) -> Capsule {
        Capsule {
            ends: self.ends.map(|e| at * e),
            radius: self.radius,
        }
    }

    /// The distance between the two capsules (negative when they overlap).
    fn distance(&self, other: &Capsule) -> f64 {
        let ([p, q], [r, s]) = (&self.ends, &other.ends);
        segment_distance(p, q, r, s) - self.radius - other.radius
    }

    /// The distance between this capsule's bounding box and `obstacle`'s.
    fn box_gap(&self, obstacle: &Obstacle) -> f64 {
        let [p, q] = &self.ends;
        let reach = Vector3::repeat(self.radius);
        let (low, high) = (p.inf(q) - reach, p.sup(q) + reach);
        let half = obstacle.size * 0.5;
        ((obstacle.centre - half) - high)
            .sup(&(low - (obstacle.centre + half)))
            .sup(&Vector3::zeros())
            .norm()
    }
}

/// The capsule that holds all of a body's parts: the longest part's segment, wide enough
/// to reach every part's farthest point (distance to a segment is convex, so a part's
/// farthest point lies at one of its own segment's ends, plus its radius).
fn hull(parts: &[Part]) -> Option<Capsule> {
    let longest = parts.iter().max_by(|a, b| {
        let length = |p: &Part| (p.capsule.ends[1] - p.capsule.ends[0]).norm();
        length(a).total_cmp(&length(b))
    })?;
    let [p, q] = &longest.capsule.ends;
    let radius = parts
        .iter()
        .flat_map(|part| {
            part.capsule
                .ends
                .iter()
                .map(move |e| segment_distance(p, q, e, e) + part.capsule.radius)
        })
        .fold(0.0, f64::max);
    Some(Capsule {
        ends: [*p, *q],
        radius,
    })
}

/// The exact distance between two shapes (0 when they touch; the bound 0 when parry cannot
/// measure the pair).
fn exact(
    a: &Pose,
    shape_a: &dyn rapier3d_f64::parry::shape::Shape,
    b: &Pose,
    shape_b: &dyn rapier3d_f64::parry::shape::Shape,
) -> f64 {
    distance(a, shape_a, b, shape_b).map_or(0.0, |d| d.distance)
}

/// The distance between segments `p`–`q` and `r`–`s`: the closest points' parameters are
/// found on the segments' lines, clamped to the segments, and the other re-found.
fn segment_distance(p: &Point3<f64>, q: &Point3<f64>, r: &Point3<f64>, s: &Point3<f64>) -> f64 {
    let (d1, d2, w) = (q - p, s - r, p - r);
    let (a, e, f) = (d1.norm_squared(), d2.norm_squared(), d2.dot(&w));
    let tiny = 1e-18;
    let (t1, t2) = if a <= tiny && e <= tiny {
        (0.0, 0.0)
    } else if a <= tiny {
        (0.0, (f / e).clamp(0.0, 1.0))
    } else {
        let c = d1.dot(&w);
        if e <= tiny {
            ((-c / a).clamp(0.0, 1.0), 0.0)
        } else {
            let b = d1.dot(&d2);
            let denominator = a * e - b * b;
            let mut t1 = if denominator > tiny {
                ((b * f - c * e) / denominator).clamp(0.0, 1.0)
            } else {
                0.0
            };
            let mut t2 = (b * t1 + f) / e;
            if t2 < 0.0 {
                t2 = 0.0;
                t1 = (-c / a).clamp(0.0, 1.0);
            } else if t2 > 1.0 {
                t2 = 1.0;
                t1 = ((b - c) / a).clamp(0.0, 1.0);
            }
            (t1, t2)
        }
    };
    ((p + d1 * t1) - (r + d2 * t2)).norm()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_carried_distance_bound_gives_the_stops_a_fresh_look_gives() {
        use crate::robot::contact::collision::MoveStart;
        use rand::{Rng, SeedableRng};
        let model = ArmModel::oscar6();
        let geometry = ArmGeometry::new(&model);
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(3);
        let (lower, upper): (Vec<f64>, Vec<f64>) = model
            .learned()
            .iter()
            .map(|&j| (model.joints()[j].lower, model.joints()[j].upper))
            .unzip();
        let mut theta = Controlled::from_fn(|i, _| 0.5 * (lower[i] + upper[i]));
        let (mut carried, mut skipped, mut stops) = (0.0, 0, 0);
        for _ in 0..400 {
            let goal = Controlled::from_fn(|i, _| rng.random_range(lower[i]..upper[i]));
            // Large moves and small corrections, as a trial makes them.
            let delta = (goal - theta) * [1.0, 0.01, 0.001][rng.random_range(0..3)];
            let start = MoveStart::at(&model, model.pose_of(&theta));
            skipped += usize::from(carried > geometry.closing(&model, &delta) + KNOWN_GAP_MARGIN);
            let fresh = geometry.contact_stop(&model, &start, &delta, 1.0, &[], &mut 0.0);
            let kept = geometry.contact_stop(&model, &start, &delta, 1.0, &[], &mut carried);
            assert_eq!(
                fresh.to_bits(),
                kept.to_bits(),
                "from {theta:?} by {delta:?}"
            );
            stops += usize::from(fresh < 1.0);
            let executed = delta * fresh;
            theta += executed;
            carried = (carried - geometry.closing(&model, &executed)).max(0.0);
        }
        assert!(
            skipped > 100 && stops > 0,
            "{skipped} moves skipped, {stops} stopped"
        );
    }

    #[test]
    fn segment_distances() {
        let o = Point3::origin();
        let x = Point3::new(1.0, 0.0, 0.0);
        let across = |z: f64| (Point3::new(0.5, -1.0, z), Point3::new(0.5, 1.0, z));
        let (r, s) = across(0.3);
        assert!((segment_distance(&o, &x, &r, &s) - 0.3).abs() < 1e-15);
        // Parallel, overlapping along x, 0.2 apart.
        let (r, s) = (Point3::new(0.5, 0.2, 0.0), Point3::new(2.0, 0.2, 0.0));
        assert!((segment_distance(&o, &x, &r, &s) - 0.2).abs() < 1e-15);
        // End to end.
        let (r, s) = (Point3::new(2.0, 0.0, 0.0), Point3::new(3.0, 0.0, 0.0));
        assert!((segment_distance(&o, &x, &r, &s) - 1.0).abs() < 1e-15);
        // A point against a segment.
        assert!((segment_distance(&o, &o, &r, &s) - 2.0).abs() < 1e-15);
    }

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
