//! The world around the arm as a camera sees it at one instant: the floor, obstacle boxes
//! and the arm's own bodies (parry shapes at their world poses), and what a ray meets first
//! among them. Both simulators lend one out: the kinematic one from its collision shapes
//! placed by forward kinematics, the dynamic one from its Rapier collider set as simulated.

use crate::robot::dynamic::{to_pose, to_vector};
use crate::robot::MAX_JOINTS;
use nalgebra::{Point3, Vector3};
use rapier3d_f64::math::Pose;
use rapier3d_f64::parry::bounding_volume::{Aabb, BoundingVolume};
use rapier3d_f64::parry::query::{Ray, RayCast};
use rapier3d_f64::parry::shape::{Cuboid, SharedShape};

/// The most bodies of an arm a camera can see: the base and every joint's body but the
/// last (the OSCAR-6's base and links 1–5). The last carries the camera, whose rays leave
/// from its front face, and lies behind it.
pub const SEEN_BODIES: usize = MAX_JOINTS;

/// A box standing in the world (m, world frame, sides along the axes).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Obstacle {
    /// The box's centre (m).
    pub centre: Point3<f64>,
    /// Its side lengths along x, y and z (m), each above zero.
    pub size: Vector3<f64>,
}

impl Obstacle {
    /// True when the ball of `radius` (m) centred at `centre` overlaps the box.
    pub fn overlaps_ball(&self, centre: &Point3<f64>, radius: f64) -> bool {
        let offset = centre - self.centre;
        let outside = (offset.abs() - self.size * 0.5).sup(&Vector3::zeros());
        outside.norm() < radius
    }

    /// The box as a parry shape and its pose.
    pub(crate) fn parts(&self) -> (Pose, Cuboid) {
        (
            Pose::from_translation(to_vector(&self.centre.coords)),
            Cuboid::new(to_vector(&(self.size * 0.5))),
        )
    }
}

/// What a ray met.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Surface {
    /// The floor.
    Floor,
    /// Obstacle `i` (0-based, in the config's order).
    Obstacle(usize),
    /// Body `k` of the arm (0 the base, then one per joint).
    Body(usize),
}

/// Where a ray met the world.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RayHit {
    /// Distance along the ray, in lengths of its direction vector.
    pub distance: f64,
    /// The point met (world, m).
    pub point: Point3<f64>,
    /// What it met.
    pub surface: Surface,
}

/// The world at one instant, borrowed from a simulator.
#[derive(Debug, Clone)]
pub struct WorldView<'a> {
    /// The floor's height (m); `-inf` for none.
    pub floor_z: f64,
    /// The obstacle boxes.
    pub obstacles: &'a [Obstacle],
    /// The bodies a camera can see (see [`SEEN_BODIES`]) at their world poses; `None` for
    /// a body without collision shapes.
    pub bodies: [Option<(Pose, &'a SharedShape)>; SEEN_BODIES],
}

impl WorldView<'_> {
    /// The bodies of an arm at `poses` (world, nalgebra) with `shapes`.
    pub fn place_bodies<'s>(
        shapes: &'s [Option<SharedShape>; SEEN_BODIES],
        poses: &[nalgebra::Isometry3<f64>; SEEN_BODIES],
    ) -> [Option<(Pose, &'s SharedShape)>; SEEN_BODIES] {
        std::array::from_fn(|k| shapes[k].as_ref().map(|s| (to_pose(&poses[k]), s)))
    }

    /// The first thing the ray from `origin` along `dir` (world) meets within `max`
    /// lengths of `dir`.
    pub fn cast(&self, origin: &Point3<f64>, dir: &Vector3<f64>, max: f64) -> Option<RayHit> {
        let ray = Ray::new(to_vector(&origin.coords), to_vector(dir));
        // Each shape is asked only for hits nearer than the nearest so far.
        let mut best: Option<(f64, Surface)> = None;
        let limit = |best: &Option<(f64, Surface)>| best.map_or(max, |(b, _)| b);
        if dir.z < 0.0 && origin.z > self.floor_z {
            let t = (self.floor_z - origin.z) / dir.z;
            best = (t <= max).then_some((t, Surface::Floor));
        }
        for (i, obstacle) in self.obstacles.iter().enumerate() {
            let (pose, cuboid) = obstacle.parts();
            if let Some(t) = cuboid.cast_ray(&pose, &ray, limit(&best), true) {
                best = Some((t, Surface::Obstacle(i)));
            }
        }
        for (k, body) in self.bodies.iter().enumerate() {
            let Some((pose, shape)) = body else { continue };
            if let Some(t) = shape.cast_ray(pose, &ray, limit(&best), true) {
                best = Some((t, Surface::Body(k)));
            }
        }
        best.map(|(distance, surface)| RayHit {
            distance,
            point: origin + dir * distance,
            surface,
        })
    }

    /// False when nothing of the world reaches into the box from `lower` to `upper`
    /// (world, m; a box resting on the floor is not entered by it); true may be said of a
    /// box that nothing enters (bounds are loose).
    pub fn may_enter(&self, lower: &Point3<f64>, upper: &Point3<f64>) -> bool {
        let region = Aabb::new(to_vector(&lower.coords), to_vector(&upper.coords));
        lower.z < self.floor_z
            || self.obstacles.iter().any(|o| {
                let (pose, cuboid) = o.parts();
                cuboid.aabb(&pose).intersects(&region)
            })
            || self
                .bodies
                .iter()
                .flatten()
                .any(|(pose, shape)| shape.compute_aabb(pose).intersects(&region))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rapier3d_f64::math::Vector;

    #[test]
    fn a_ray_meets_the_nearest_of_floor_obstacle_and_body() {
        let obstacles = [Obstacle {
            centre: Point3::new(0.0, 0.0, 0.1),
            size: Vector3::new(0.2, 0.2, 0.2),
        }];
        let ball = SharedShape::ball(0.05);
        let mut bodies = [None; SEEN_BODIES];
        bodies[3] = Some((Pose::from_translation(Vector::new(0.5, 0.0, 0.5)), &ball));
        let world = WorldView {
            floor_z: -0.2,
            obstacles: &obstacles,
            bodies,
        };
        let down = Vector3::new(0.0, 0.0, -1.0);
        let hit = world
            .cast(&Point3::new(0.0, 0.0, 1.0), &down, 10.0)
            .unwrap();
        assert_eq!(hit.surface, Surface::Obstacle(0));
        assert!((hit.distance - 0.8).abs() < 1e-12);
        let beside = world
            .cast(&Point3::new(0.3, 0.0, 1.0), &down, 10.0)
            .unwrap();
        assert_eq!(beside.surface, Surface::Floor);
        assert!((beside.point.z + 0.2).abs() < 1e-12);
        let body = world
            .cast(&Point3::new(0.5, 0.0, 1.0), &down, 10.0)
            .unwrap();
        assert_eq!(body.surface, Surface::Body(3));
        assert!(world
            .cast(&Point3::new(0.3, 0.0, 1.0), &down, 1.0)
            .is_none());
        assert!(world.may_enter(&Point3::new(0.05, 0.05, 0.15), &Point3::new(0.4, 0.4, 0.4)));
        assert!(!world.may_enter(&Point3::new(0.15, 0.15, 0.0), &Point3::new(0.4, 0.4, 0.4)));
        assert!(obstacles[0].overlaps_ball(&Point3::new(0.12, 0.0, 0.1), 0.03));
        assert!(!obstacles[0].overlaps_ball(&Point3::new(0.12, 0.12, 0.1), 0.025));
    }
}
