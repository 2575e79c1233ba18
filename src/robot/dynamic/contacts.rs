//! The world around the arm: a floor, and contacts between links that are not neighbours
//! in the chain and do not already touch at the zero pose (the wrist's three links share
//! its centre). A link that digs into the floor or another link stops a move, as a joint
//! limit does.

use super::builder::Arm;
use super::convert::to_pose;
use crate::robot::{ArmModel, Obstacle};
use nalgebra::Isometry3;
use rapier3d_f64::math::Vector;
use rapier3d_f64::parry::query::intersection_test;
use rapier3d_f64::prelude::nalgebra::Unit;
use rapier3d_f64::prelude::{
    ColliderBuilder, Group, InteractionGroups, InteractionTestMode, RigidBodyBuilder,
};

/// A contact deeper than this (m) stops a move; shallower ones are the servo's error
/// around a pose that just touches.
pub(super) const CONTACT_DEPTH: f64 = 5e-4;
/// The floor's interaction group (bodies take groups 0–6).
const FLOOR: u32 = 7;

impl Arm {
    /// Adds the floor at height `floor_z` (m; none when not finite) and turns on contacts
    /// between the links that may meet.
    pub(super) fn add_world(&mut self, model: &ArmModel, floor_z: f64) {
        let mut filters = [Group::ALL; 8];
        let poses = model.link_frames(&crate::robot::Joints::zeros());
        let pose_of = |k: usize| {
            if k == 0 {
                Isometry3::identity()
            } else {
                poses[k - 1]
            }
        };
        for i in 0..7 {
            for j in i + 1..7 {
                if j == i + 1 || self.touch(i, j, &pose_of(i), &pose_of(j)) {
                    filters[i].remove(Group::from_bits_retain(1 << j));
                    filters[j].remove(Group::from_bits_retain(1 << i));
                }
            }
        }
        // The base stands on its pedestal above the floor.
        filters[0].remove(Group::from_bits_retain(1 << FLOOR));
        filters[FLOOR as usize].remove(Group::from_bits_retain(1));
        for (k, handle) in self.colliders.iter().enumerate() {
            if let Some(collider) = handle.and_then(|h| self.world.colliders.get_mut(h)) {
                collider.set_collision_groups(groups(k as u32, filters[k]));
            }
        }
        if floor_z.is_finite() {
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
            self.world.insert_collider(collider, Some(ground));
        }
    }

    /// Turns every contact off: the floor's and between links.
    pub(super) fn remove_contacts(&mut self) {
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

    /// True when bodies `i` and `j`, at these world poses, overlap.
    fn touch(&self, i: usize, j: usize, at_i: &Isometry3<f64>, at_j: &Isometry3<f64>) -> bool {
        let shape = |k: usize| {
            self.colliders[k]
                .and_then(|h| self.world.colliders.get(h))
                .map(|c| c.shared_shape().clone())
        };
        match (shape(i), shape(j)) {
            (Some(a), Some(b)) => {
                intersection_test(&to_pose(at_i), a.as_ref(), &to_pose(at_j), b.as_ref())
                    .map_or(true, |hit| hit.intersecting)
            }
            _ => false,
        }
    }

    /// True when a link digs deeper than [`CONTACT_DEPTH`] into the floor or another link.
    pub(super) fn in_contact(&self) -> bool {
        self.world.contact_pairs().any(|pair| {
            pair.find_deepest_contact()
                .is_some_and(|(_, contact)| contact.dist < -CONTACT_DEPTH)
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
