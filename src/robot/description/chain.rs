//! The serial chain from the root to a camera link: fixed joints merged (their links'
//! mass properties joined into one rigid body, frames composed), moving joints in order,
//! and the moving joints off the chain (fingers) listed to be held at their defaults.

use super::inertia::Inertial;
use super::joint::{Joint, JointDynamics, JointKind, JointLimits};
use super::{DescriptionError, DescriptionErrorKind as Kind, RobotDescription};
use nalgebra::{Isometry3, Unit, Vector3};

/// A moving joint of the chain.
#[derive(Debug, Clone, PartialEq)]
pub struct ChainJoint {
    /// Index of the joint in the description.
    pub joint: usize,
    /// The joint's URDF name.
    pub name: String,
    /// Revolute, continuous or prismatic.
    pub kind: JointKind,
    /// Pose of the joint frame in the previous body's frame (fixed joints before it composed).
    pub origin: Isometry3<f64>,
    /// Unit axis in the joint frame.
    pub axis: Unit<Vector3<f64>>,
    /// Position, effort and speed limits.
    pub limits: JointLimits,
    /// Damping and friction.
    pub dynamics: JointDynamics,
}

/// A rigid body of the chain: a link and every link fixed to it, in that link's frame.
#[derive(Debug, Clone, PartialEq)]
pub struct ChainBody {
    /// The links merged into the body with their poses in its frame; the body's own link
    /// (identity pose) first.
    pub links: Vec<(usize, Isometry3<f64>)>,
    /// The links' mass properties joined (parallel-axis theorem) in the body frame; massless
    /// when every merged link is.
    pub inertial: Inertial,
}

/// A moving joint off the chain, held at a fixed position.
#[derive(Debug, Clone, PartialEq)]
pub struct HeldJoint {
    /// Index of the joint in the description.
    pub joint: usize,
    /// The joint's URDF name.
    pub name: String,
    /// Where it is held: 0 clamped into its limits, or where its `<mimic>` puts it from
    /// its held leader (rad or m).
    pub position: f64,
    /// The chain body it hangs from (`None` when it hangs below another held joint).
    pub body: Option<usize>,
}

/// The arm: the serial chain of moving joints from the root to the camera link.
#[derive(Debug, Clone, PartialEq)]
pub struct Chain {
    pub(super) file: String,
    /// The moving joints from the root outwards.
    pub joints: Vec<ChainJoint>,
    /// The bodies: the root's first, then the one each moving joint moves.
    pub bodies: Vec<ChainBody>,
    /// The camera link's index in the description.
    pub camera_link: usize,
    /// The camera link's pose in the last body's frame.
    pub camera_in_body: Isometry3<f64>,
    /// The moving joints off the chain, held at their defaults.
    pub held: Vec<HeldJoint>,
}

impl Chain {
    /// The chain from the root of `description` to the link named `camera_link`.
    pub fn new(
        description: &RobotDescription,
        camera_link: &str,
    ) -> Result<Chain, DescriptionError> {
        Chain::below(description, description.root, camera_link)
    }

    /// The chain from link `base` (an index; its frame the world's) to the link named
    /// `camera_link`, which must lie below it; the moving joints off the chain below `base`
    /// are held.
    pub fn below(
        description: &RobotDescription,
        base: usize,
        camera_link: &str,
    ) -> Result<Chain, DescriptionError> {
        let camera = description.link_index(camera_link).ok_or_else(|| {
            description.error(Kind::UnknownLink {
                link: camera_link.to_string(),
            })
        })?;
        let path = path_to(description, base, camera).ok_or_else(|| {
            description.error(Kind::CameraNotBelowBase {
                camera_link: camera_link.to_string(),
                base_link: description.links[base].name.clone(),
            })
        })?;
        let moving: Vec<usize> = path
            .into_iter()
            .filter(|&j| description.joints[j].kind.moves())
            .collect();
        if moving.is_empty() {
            return Err(description.error(Kind::NoMovingJoint {
                link: camera_link.to_string(),
            }));
        }
        if let Some((joint, mimic)) = moving.iter().find_map(|&j| {
            let joint = &description.joints[j];
            joint.mimic.as_ref().map(|m| (joint, m))
        }) {
            return Err(description.error(Kind::MimicOnChain {
                joint: joint.name.clone(),
                leader: mimic.joint.clone(),
            }));
        }
        let seeds =
            std::iter::once(base).chain(moving.iter().map(|&j| description.joints[j].child));
        let bodies: Vec<ChainBody> = seeds
            .map(|seed| ChainBody::rooted_at(description, seed))
            .collect();
        let pose_in = |body: &ChainBody, link: usize| {
            body.links.iter().find(|(l, _)| *l == link).map(|(_, p)| *p)
        };
        let joints = moving
            .iter()
            .zip(&bodies)
            .map(|(&j, body)| {
                let joint = &description.joints[j];
                let parent = pose_in(body, joint.parent)
                    .expect("fixed joints lead from the body to its next joint");
                ChainJoint {
                    joint: j,
                    name: joint.name.clone(),
                    kind: joint.kind,
                    origin: parent * joint.origin,
                    axis: joint.axis,
                    limits: joint.limits,
                    dynamics: joint.dynamics,
                }
            })
            .collect();
        let last = bodies
            .last()
            .expect("a body per moving joint and the root's");
        let camera_in_body =
            pose_in(last, camera).expect("no moving joint after the last one on the path");
        let below = links_below(description, base);
        let held = description
            .joints
            .iter()
            .enumerate()
            .filter(|(j, joint)| {
                joint.kind.moves() && !moving.contains(j) && below.contains(&joint.parent)
            })
            .map(|(j, joint)| {
                Ok(HeldJoint {
                    joint: j,
                    name: joint.name.clone(),
                    position: held_position(description, joint, &moving)?,
                    body: bodies
                        .iter()
                        .position(|b| pose_in(b, joint.parent).is_some()),
                })
            })
            .collect::<Result<Vec<_>, DescriptionError>>()?;
        Ok(Chain {
            file: description.file.clone(),
            joints,
            bodies,
            camera_link: camera,
            camera_in_body,
            held,
        })
    }

    /// The indices into `joints` of the three learned joints, checked: each must be a
    /// moving joint of this chain, named once.
    pub fn learned_joints(
        &self,
        description: &RobotDescription,
        names: &[&str; 3],
    ) -> Result<[usize; 3], DescriptionError> {
        let mut found = [0; 3];
        for (slot, name) in names.iter().enumerate() {
            let joint = name.to_string();
            let kind = match description.joint_index(name) {
                None => Some(Kind::UnknownJoint { joint }),
                Some(j) if !description.joints[j].kind.moves() => {
                    Some(Kind::LearnedJointFixed { joint })
                }
                Some(_) if names[..slot].contains(name) => {
                    Some(Kind::LearnedJointRepeated { joint })
                }
                Some(j) => match self.joints.iter().position(|c| c.joint == j) {
                    Some(index) => {
                        found[slot] = index;
                        None
                    }
                    None => Some(Kind::LearnedJointOffChain {
                        joint,
                        camera_link: description.links[self.camera_link].name.clone(),
                    }),
                },
            };
            if let Some(kind) = kind {
                return Err(description.error(kind));
            }
        }
        Ok(found)
    }
}

/// The joints from `base` down to `link`, nearest `base` first; `None` when `link` does
/// not lie below `base` (or is it: then there are no joints).
fn path_to(description: &RobotDescription, base: usize, link: usize) -> Option<Vec<usize>> {
    let mut path = Vec::new();
    let mut at = link;
    while at != base {
        let j = description.links[at].parent_joint?;
        path.push(j);
        at = description.joints[j].parent;
    }
    path.reverse();
    Some(path)
}

/// Link `base` and every link below it.
fn links_below(description: &RobotDescription, base: usize) -> Vec<usize> {
    let mut links = vec![base];
    let mut next = 0;
    while let Some(&link) = links.get(next) {
        links.extend(
            description.links[link]
                .child_joints
                .iter()
                .map(|&j| description.joints[j].child),
        );
        next += 1;
    }
    links
}

impl ChainBody {
    /// The rigid body of link `seed` and every link fixed to it below, with their poses in
    /// `seed`'s frame.
    pub fn rooted_at(description: &RobotDescription, seed: usize) -> ChainBody {
        let mut links = vec![(seed, Isometry3::identity())];
        let mut next = 0;
        while let Some(&(link, pose)) = links.get(next) {
            for &j in &description.links[link].child_joints {
                let joint = &description.joints[j];
                if joint.kind == JointKind::Fixed {
                    links.push((joint.child, pose * joint.origin));
                }
            }
            next += 1;
        }
        let inertial = links.iter().fold(Inertial::MASSLESS, |sum, (link, pose)| {
            sum.combined(&description.links[*link].inertial.transformed(pose))
        });
        ChainBody { links, inertial }
    }
}

/// Where a joint off the chain is held: 0 clamped into its limits, or, for a joint that
/// mimics another held joint, the leader's position times the multiplier plus the offset.
/// A mimic of a chain joint, or of no joint, is an error naming both.
fn held_position(
    description: &RobotDescription,
    joint: &Joint,
    moving: &[usize],
) -> Result<f64, DescriptionError> {
    let Some(mimic) = &joint.mimic else {
        return Ok(joint.limits.default_position());
    };
    let names = || (joint.name.clone(), mimic.joint.clone());
    let Some(leader) = description.joint_index(&mimic.joint) else {
        let (joint, leader) = names();
        return Err(description.error(Kind::UnknownMimicLeader { joint, leader }));
    };
    if moving.contains(&leader) {
        let (joint, leader) = names();
        return Err(description.error(Kind::MimicsChainJoint { joint, leader }));
    }
    let leader = &description.joints[leader];
    Ok(mimic.multiplier * leader.limits.default_position() + mimic.offset)
}
