//! The world around the arm: a floor, obstacle boxes, and contacts between the links the
//! shared rule lets touch (not neighbours in the chain, apart at the zero pose:
//! robot/clearance.rs). The plan already stops a move where the kinematic rule finds
//! contact; a link that still digs into the floor, an obstacle or another link stops a
//! move, as a joint limit does, and so does a contact that holds the arm back from its
//! set-point.

use super::builder::Arm;
use crate::robot::contact::clearance::contact_pairs;
use crate::robot::contact::collision::body_elements;
use crate::robot::contact::reaches::{reaches, Reaches};
use crate::robot::{ArmModel, Joints, Obstacle, MAX_JOINTS};
use rapier3d_f64::math::Vector;
use rapier3d_f64::parry::bounding_volume::{Aabb, BoundingVolume};
use rapier3d_f64::prelude::nalgebra::Unit;
use rapier3d_f64::prelude::{
    ColliderBuilder, Group, InteractionGroups, InteractionTestMode, RigidBodyBuilder,
};

/// A contact deeper than this (m) stops a move; shallower ones are the servo's error
/// around a pose that just touches.
pub(super) const CONTACT_DEPTH: f64 = 5e-4;
/// A link this close (m) to something touches it (Rapier's contacts may stop a struck link
/// short of the surface by a fraction of a millimetre).
const TOUCH: f64 = 1e-3;
/// How far (rad) a joint may lag its set-point while a link touches something before the
/// contact counts as holding the arm back: far above the servos' lag on a free path
/// (under 0.02° on either engine), below one tick of a move's top speed.
const HELD_BACK: f64 = 0.1 * std::f64::consts::PI / 180.0;
/// The floor's interaction group (bodies take groups 0 to [`MAX_JOINTS`]).
const FLOOR: u32 = MAX_JOINTS as u32 + 1;
/// Room (m) around each body's bounding box within which Rapier looks for contacts, so a
/// contact about to form is seen forming.
const LOOK_WITHIN: f64 = 0.005;
/// A contact Rapier finds closer than this (m), beyond how far the next tick could close it,
/// puts the arm near it: that tick is stepped by Rapier in sub-ticks, its contact
/// constraints acting. Rapier reports contacts up to its prediction distance (2 cm) away;
/// counting them all would step in sub-ticks every tick of an arm whose links pass each
/// other at a steady gap of a centimetre or two (the UR arms' wrist links two apart, their
/// base and upper arm).
const NEAR: f64 = LOOK_WITHIN;

/// What the links may touch: the pairs of bodies the shared rule lets meet, the floor and
/// the obstacles' bounding boxes.
#[derive(Debug, Clone)]
pub(super) struct ContactScope {
    /// Whether contacts are on at all.
    on: bool,
    /// Bodies (0 the base) that may touch each other.
    pairs: Vec<(usize, usize)>,
    /// How far each body reaches from each joint's axis, to bound how fast a gap closes.
    reaches: Reaches,
    /// The floor's height (m; negative infinity for none).
    floor_z: f64,
    /// The obstacles' boxes in the world.
    obstacles: Vec<Aabb>,
}

impl Default for ContactScope {
    fn default() -> Self {
        ContactScope {
            on: true,
            pairs: Vec::new(),
            reaches: Reaches::default(),
            floor_z: f64::NEG_INFINITY,
            obstacles: Vec::new(),
        }
    }
}

impl Arm {
    /// Adds the floor at height `floor_z` (m; none when not finite) and turns on contacts
    /// between the links that may meet.
    pub(super) fn add_world(&mut self, model: &ArmModel, floor_z: f64) {
        // Links meet the floor and obstacles (group FLOOR), and the bodies the shared rule
        // lets touch (robot/clearance.rs).
        let mut filters = [Group::from_bits_retain(1 << FLOOR); FLOOR as usize + 1];
        filters[FLOOR as usize] = Group::ALL;
        filters[0] = Group::empty();
        let elements: Vec<_> = (0..=model.dof()).map(|k| body_elements(model, k)).collect();
        self.scope.pairs = contact_pairs(model, &elements);
        self.scope.reaches = reaches(model, &elements[1..]);
        for &(i, j) in &self.scope.pairs {
            filters[i].insert(Group::from_bits_retain(1 << j));
            filters[j].insert(Group::from_bits_retain(1 << i));
        }
        // The base stands on its pedestal above the floor.
        filters[FLOOR as usize].remove(Group::from_bits_retain(1));
        for (k, handle) in self.colliders.iter().enumerate() {
            if let Some(collider) = handle.and_then(|h| self.world.colliders.get_mut(h)) {
                collider.set_collision_groups(groups(k as u32, filters[k]));
            }
        }
        if floor_z.is_finite() {
            self.scope.floor_z = floor_z;
            let ground = self
                .world
                .insert_body(RigidBodyBuilder::fixed().translation(Vector::new(0.0, 0.0, floor_z)));
            let floor = ColliderBuilder::halfspace(Unit::new_unchecked(Vector::Z))
                .collision_groups(groups(FLOOR, filters[FLOOR as usize]));
            self.world.insert_collider(floor, Some(ground));
        }
        if let Some(mb) = self
            .world
            .multibody_joints
            .get_multibody_mut(self.multibody)
        {
            mb.set_self_contacts_enabled(true);
        }
    }

    /// Adds `obstacles` as fixed boxes the links (not the base) collide with, as with the
    /// floor.
    pub(super) fn add_obstacles(&mut self, obstacles: &[Obstacle]) {
        let ground = self.world.insert_body(RigidBodyBuilder::fixed());
        let mut filter = Group::ALL;
        filter.remove(Group::from_bits_retain(1));
        for obstacle in obstacles {
            let (pose, cuboid) = obstacle.parts();
            let collider = ColliderBuilder::cuboid(
                cuboid.half_extents.x,
                cuboid.half_extents.y,
                cuboid.half_extents.z,
            )
            .position(pose)
            .collision_groups(groups(FLOOR, filter));
            let handle = self.world.insert_collider(collider, Some(ground));
            self.scope
                .obstacles
                .push(self.world.colliders[handle].compute_aabb());
        }
    }

    /// Turns every contact off: the floor's and between links.
    pub(super) fn remove_contacts(&mut self) {
        self.scope.on = false;
        for handle in self.colliders.iter().flatten() {
            if let Some(collider) = self.world.colliders.get_mut(*handle) {
                collider.set_collision_groups(InteractionGroups::none());
            }
        }
        if let Some(mb) = self
            .world
            .multibody_joints
            .get_multibody_mut(self.multibody)
        {
            mb.set_self_contacts_enabled(false);
        }
    }

    /// True when a contact stops a move whose servos are sent to `set_point` (rad): a
    /// link digs deeper than [`CONTACT_DEPTH`] into something, or touches something while
    /// a joint lags its set-point by more than [`HELD_BACK`] — the contact holds the arm
    /// back, and servos pushing on toward a set-point beyond it would press the arm into
    /// it with their whole effort, the strongest joints turning the weakest about the
    /// point of contact (a camera struck against the base whips the wrist).
    pub(super) fn stopped_by_contact(&self, set_point: &Joints) -> bool {
        self.depth > CONTACT_DEPTH || self.held_back(set_point)
    }

    /// True when a link touches something (by the last contacts Rapier found) while a
    /// joint lags `set_point` (rad) by more than [`HELD_BACK`].
    pub(super) fn held_back(&self, set_point: &Joints) -> bool {
        self.depth > -TOUCH && (*set_point - self.joints()).amax() > HELD_BACK
    }

    /// True when a contact Rapier found at the last look is within [`NEAR`] of closing, on
    /// top of how far the joints' speeds could close it in a tick of `dt` (s).
    pub(super) fn near_contact(&self, dt: f64) -> bool {
        if self.depth == f64::NEG_INFINITY {
            return false;
        }
        let speeds = self.speeds();
        let body = |handle| self.colliders.iter().position(|c| *c == Some(handle));
        self.world.contact_pairs().any(|pair| {
            let Some((_, contact)) = pair.find_deepest_contact() else {
                return false;
            };
            let (i, j) = match (body(pair.collider1), body(pair.collider2)) {
                (Some(a), Some(b)) => (a.min(b), a.max(b)),
                (Some(k), None) | (None, Some(k)) => (0, k),
                (None, None) => return false,
            };
            contact.dist < NEAR + dt * self.scope.reaches.closing_speed(&speeds, i, j)
        })
    }

    /// Takes how far each body reaches from each joint's axis from `model` as it is now (a
    /// stretched link reaches further).
    pub(super) fn refresh_reaches(&mut self, model: &ArmModel) {
        let elements: Vec<_> = (1..=model.dof()).map(|k| body_elements(model, k)).collect();
        self.scope.reaches = reaches(model, &elements);
    }

    /// How deep (m) the deepest contact Rapier found last is; negative infinity for none.
    pub(super) fn deepest_contact(&self) -> f64 {
        self.world
            .contact_pairs()
            .filter_map(|pair| pair.find_deepest_contact())
            .map(|(_, contact)| -contact.dist)
            .fold(f64::NEG_INFINITY, f64::max)
    }

    /// False when no two things that may touch come within [`LOOK_WITHIN`] of each other
    /// by their bounding boxes (so surely do not touch), the colliders where they are now.
    pub(super) fn may_touch(&self) -> bool {
        let scope = &self.scope;
        if !scope.on {
            return false;
        }
        let boxes: [Option<Aabb>; MAX_JOINTS + 1] = std::array::from_fn(|k| {
            let collider = self.world.colliders.get((*self.colliders.get(k)?)?)?;
            Some(collider.compute_aabb().loosened(LOOK_WITHIN))
        });
        let links = || boxes.iter().skip(1).flatten();
        links().any(|b| b.mins.z < scope.floor_z)
            || links().any(|b| scope.obstacles.iter().any(|o| b.intersects(o)))
            || scope
                .pairs
                .iter()
                .any(|&(i, j)| match (&boxes[i], &boxes[j]) {
                    (Some(a), Some(b)) => a.intersects(b),
                    _ => false,
                })
    }
}

/// Body (or floor) `k`'s interaction groups: its own bit, and the bits it meets.
fn groups(k: u32, filter: Group) -> InteractionGroups {
    InteractionGroups::new(
        Group::from_bits_retain(1 << k),
        filter,
        InteractionTestMode::And,
    )
}
