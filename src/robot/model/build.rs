//! An [`ArmModel`] from any robot description: the chain to the camera link, the camera
//! mounted where the settings say, the three learned joints named by the settings.

use super::{ArmModel, Wrist};
use crate::robot::description::{
    camera_choice, Chain, ChainBody, DescriptionError, DescriptionErrorKind as Kind,
    GeometryElement, Inertial, JointKind, RobotDescription,
};
use crate::robot::Shape;
use crate::robot::MAX_JOINTS;
use crate::robot::{LinkBody, RevoluteJoint};
use nalgebra::{Isometry3, Translation3, UnitQuaternion, Vector3};

/// Which part of a robot description is the arm, and where its camera sits.
#[derive(Debug, Clone, PartialEq)]
pub struct ArmSettings {
    /// The link the arm stands on, its frame the world's. Default [`BaseLink::Root`].
    pub base_link: BaseLink,
    /// The link the camera is fixed to; the chain from the root to it is the arm.
    /// Default [`CameraLink::Auto`] (the OSCAR-6's `camera_link`).
    pub camera_link: CameraLink,
    /// The camera centre in the camera link's frame (m), its axes the link's (z the
    /// optical axis). Default 0, 0, 0.
    pub camera_offset: Vector3<f64>,
    /// The camera's turn in the camera link's frame, about the camera centre: its z axis
    /// the optical axis. Default none (looking along the link's z axis).
    pub camera_turn: UnitQuaternion<f64>,
    /// The three learned joints: the study's base yaw, shoulder and elbow. Default
    /// [`LearnedJoints::Auto`] (the OSCAR-6's `joint_1`, `joint_2`, `joint_3`).
    pub learned_joints: LearnedJoints,
}

impl Default for ArmSettings {
    fn default() -> ArmSettings {
        ArmSettings {
            base_link: BaseLink::Root,
            camera_link: CameraLink::Auto,
            camera_offset: Vector3::zeros(),
            camera_turn: UnitQuaternion::identity(),
            learned_joints: LearnedJoints::Auto,
        }
    }
}

impl ArmSettings {
    /// The camera's pose in the camera link's frame: `camera_offset`, then `camera_turn`.
    pub fn mount(&self) -> Isometry3<f64> {
        Isometry3::from_parts(Translation3::from(self.camera_offset), self.camera_turn)
    }

    /// The base link's index in `description`.
    pub fn base(&self, description: &RobotDescription) -> Result<usize, DescriptionError> {
        match &self.base_link {
            BaseLink::Root => Ok(description.root),
            BaseLink::Named(name) => description
                .link_index(name)
                .ok_or_else(|| DescriptionError {
                    file: description.file.clone(),
                    kind: Kind::UnknownBaseLink { link: name.clone() },
                }),
        }
    }

    /// The chain these settings cut from `description`: from the base link to the camera
    /// link.
    pub fn chain(&self, description: &RobotDescription) -> Result<Chain, DescriptionError> {
        let base = self.base(description)?;
        match &self.camera_link {
            CameraLink::Auto => {
                let link = camera_choice(description, base).link;
                Chain::below(description, base, &description.links[link].name)
            }
            CameraLink::Named(name) => Chain::below(description, base, name),
        }
    }
}

/// The link the arm stands on.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum BaseLink {
    /// The root of the description's tree.
    Root,
    /// The link of this name (one arm of a bigger robot).
    Named(String),
}

/// The link the camera is fixed to.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum CameraLink {
    /// The link named `camera_link`, or the end of the chain ([`camera_choice`] from the base link).
    Auto,
    /// The link of this name.
    Named(String),
}

impl From<&str> for CameraLink {
    fn from(name: &str) -> CameraLink {
        CameraLink::Named(name.to_string())
    }
}

/// The three learned joints.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum LearnedJoints {
    /// The base yaw and the two joints that move the camera's reach and height most
    /// ([`Chain::auto_learned_joints`]).
    Auto,
    /// The joints of these names: base yaw, shoulder, elbow.
    Named([String; 3]),
}

impl From<[&str; 3]> for LearnedJoints {
    fn from(names: [&str; 3]) -> LearnedJoints {
        LearnedJoints::Named(names.map(String::from))
    }
}

impl ArmModel {
    /// The arm `settings` pick out of `description`: every moving joint on the chain to the
    /// camera link (revolute or continuous, at most [`MAX_JOINTS`]), each body's links
    /// merged, the camera link and the links fixed below it a body of their own at the
    /// camera mount (last in the link list), the links held off the chain (fingers) in the
    /// body they hang from, collision meshes with their convex hulls.
    pub fn from_description(
        description: &RobotDescription,
        settings: &ArmSettings,
    ) -> Result<ArmModel, DescriptionError> {
        let chain = settings.chain(description)?;
        let learned = match &settings.learned_joints {
            LearnedJoints::Auto => chain.auto_learned_joints(description)?,
            LearnedJoints::Named(names) => {
                chain.learned_joints(description, &names.each_ref().map(String::as_str))?
            }
        };
        let fail = |kind| DescriptionError {
            file: description.file.clone(),
            kind,
        };
        if chain.joints.len() > MAX_JOINTS {
            return Err(fail(Kind::TooManyJoints {
                found: chain.joints.len(),
                max: MAX_JOINTS,
            }));
        }
        let mut joints = Vec::with_capacity(chain.joints.len());
        for joint in &chain.joints {
            if joint.kind == JointKind::Prismatic {
                return Err(fail(Kind::PrismaticOnChain {
                    joint: joint.name.clone(),
                }));
            }
            joints.push(RevoluteJoint {
                name: joint.name.clone(),
                origin: joint.origin,
                axis: joint.axis,
                lower: joint.limits.lower,
                upper: joint.limits.upper,
                effort: joint.limits.effort.unwrap_or(f64::INFINITY),
                velocity: joint.limits.velocity.unwrap_or(f64::INFINITY),
                damping: joint.dynamics.damping,
                friction: joint.dynamics.friction,
            });
        }
        let camera_part = with_held_links(
            description,
            &chain,
            camera_part(description, &chain, &settings.mount()),
        );
        let last = chain.bodies.len() - 1;
        let mut links: Vec<LinkBody> = chain
            .bodies
            .iter()
            .enumerate()
            .map(|(k, body)| {
                let on_camera =
                    |link: usize| k == last && camera_part.iter().any(|(l, _)| *l == link);
                let merged = with_held_links(description, &chain, body.links.clone());
                let kept = merged.iter().filter(|(link, _)| !on_camera(*link));
                link_body(description, body.links[0].0, kept)
            })
            .collect();
        links.push(link_body(
            description,
            chain.camera_link,
            camera_part.iter(),
        ));
        let mount = if settings.mount() == Isometry3::identity() {
            chain.camera_in_body
        } else {
            chain.camera_in_body * settings.mount()
        };
        let model = ArmModel::from_parts(description.name.clone(), joints, learned, mount, links)
            .map_err(|_| {
            fail(Kind::TooManyJoints {
                found: chain.joints.len(),
                max: MAX_JOINTS,
            })
        })?;
        if !Wrist::looks_down_somewhere(&model) {
            return Err(fail(Kind::CannotLookDown {
                camera_link: description.links[chain.camera_link].name.clone(),
                wrist: (0..model.dof())
                    .filter(|j| !learned.contains(j))
                    .map(|j| model.joints[j].name.clone())
                    .collect(),
                tried: Wrist::POSES_TRIED,
            }));
        }
        if let Some((joint, distance)) = joint_in_front(&model) {
            return Err(fail(Kind::CameraFacesArm {
                camera_link: description.links[chain.camera_link].name.clone(),
                joint: model.joints[joint].name.clone(),
                distance_cm: distance * 100.0,
            }));
        }
        Ok(model)
    }
}

/// The links that ride with the camera (turned with it), posed in the camera's frame (at
/// `mount` in the camera link's): the camera link and every link fixed below it, unless the
/// camera link is the last body's own link (then nothing rides apart from the body).
fn camera_part(
    description: &RobotDescription,
    chain: &Chain,
    mount: &Isometry3<f64>,
) -> Vec<(usize, Isometry3<f64>)> {
    let last = chain.bodies.last().expect("a body per moving joint");
    if last.links[0].0 == chain.camera_link {
        return Vec::new();
    }
    let to_camera = mount.inverse();
    ChainBody::rooted_at(description, chain.camera_link)
        .links
        .into_iter()
        .map(|(link, pose)| (link, to_camera * pose))
        .collect()
}

/// A body of the arm named after description link `name`: the `links` at their poses in
/// its frame, their mass properties joined, their collision elements.
fn link_body<'a>(
    description: &RobotDescription,
    name: usize,
    links: impl Iterator<Item = &'a (usize, Isometry3<f64>)> + Clone,
) -> LinkBody {
    let inertial = links.clone().fold(Inertial::MASSLESS, |sum, (link, pose)| {
        sum.combined(&description.links[*link].inertial.transformed(pose))
    });
    LinkBody {
        name: description.links[name].name.clone(),
        mass: inertial.mass,
        inertial_origin: Isometry3::from(Translation3::from(inertial.com.coords)),
        inertia: inertial.inertia,
        collisions: links
            .flat_map(|(link, pose)| {
                description.links[*link]
                    .collisions
                    .iter()
                    .map(move |element| collision_shape(pose, element))
            })
            .collect(),
    }
}

/// `links` (with their poses in one frame), followed by every link that hangs from them
/// through joints off the chain held at their positions (the Panda's fingers) and the links
/// fixed to those: all ride together.
fn with_held_links(
    description: &RobotDescription,
    chain: &Chain,
    mut links: Vec<(usize, Isometry3<f64>)>,
) -> Vec<(usize, Isometry3<f64>)> {
    let mut next = 0;
    while let Some(&(link, pose)) = links.get(next) {
        for &j in &description.links[link].child_joints {
            let joint = &description.joints[j];
            let position = match chain.held.iter().find(|held| held.joint == j) {
                Some(held) => held.position,
                None if joint.kind == JointKind::Fixed => 0.0,
                None => continue,
            };
            if links.iter().all(|(l, _)| *l != joint.child) {
                links.push((joint.child, pose * joint.transform(position)));
            }
        }
        next += 1;
    }
    links
}

/// A joint (0-based) whose origin lies in front of the camera, within 0.05 rad of its
/// optical axis and 30 cm of it, with the learned joints in the middle of their limits
/// and the camera looking down, and how far (m); `None` when none does (or the wrist does
/// not look down there).
fn joint_in_front(model: &ArmModel) -> Option<(usize, f64)> {
    let theta = crate::robot::Controlled::from_fn(|i, _| model.joints[model.learned[i]].middle());
    let pose = model.pose_of(&theta);
    if !pose.wrist_found {
        return None;
    }
    let centre = pose.camera.translation.vector;
    let optical = pose.camera.rotation * Vector3::z();
    (0..model.dof()).find_map(|k| {
        let to = pose.frames[k].translation.vector - centre;
        let along = to.dot(&optical);
        let off = to.cross(&optical).norm();
        (along > 1e-3 && along < 0.3 && off < 0.05 * along).then_some((k, along))
    })
}

/// A collision element posed in its body.
fn collision_shape(pose: &Isometry3<f64>, element: &GeometryElement) -> (Isometry3<f64>, Shape) {
    (pose * element.origin, element.geometry.clone())
}
