//! Reading the arm from a URDF file with urdf-rs, and checking that it is an OSCAR-6:
//! a serial chain of six revolute joints from the root link, then a fixed joint to a
//! camera link (a link whose name contains `camera`).

use super::joint::{LinkBody, RevoluteJoint, Shape};
use super::model::ArmModel;
use super::{UrdfError, UrdfErrorKind};
use nalgebra::{Isometry3, Matrix3, Translation3, Unit, UnitQuaternion, Vector3};
use std::path::Path;

/// The shipped OSCAR-6 URDF, built into the binary.
pub const DEFAULT_URDF: &str = include_str!("../../urdf/oscar6.urdf");
/// The name the built-in URDF is reported under.
pub const DEFAULT_URDF_NAME: &str = "urdf/oscar6.urdf";

/// Reads and checks a URDF file.
pub fn load_urdf(path: &Path) -> Result<ArmModel, UrdfError> {
    let name = path.display().to_string();
    let text = std::fs::read_to_string(path).map_err(|e| UrdfError {
        file: name.clone(),
        kind: UrdfErrorKind::Unreadable {
            reason: e.to_string(),
        },
    })?;
    parse_urdf(&text, &name)
}

/// Parses and checks URDF text; `file` names it in errors.
pub fn parse_urdf(text: &str, file: &str) -> Result<ArmModel, UrdfError> {
    let fail = |kind| UrdfError {
        file: file.to_string(),
        kind,
    };
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    let robot = urdf_rs::read_from_string(text).map_err(|e| {
        fail(UrdfErrorKind::NotUrdf {
            reason: e.to_string(),
        })
    })?;
    let chain = serial_chain(&robot).map_err(fail)?;
    build_model(&robot, &chain).map_err(fail)
}

/// The joints from the root link to the chain's end, in order.
fn serial_chain(robot: &urdf_rs::Robot) -> Result<Vec<&urdf_rs::Joint>, UrdfErrorKind> {
    for joint in &robot.joints {
        for link in [&joint.parent.link, &joint.child.link] {
            if !robot.links.iter().any(|l| &l.name == link) {
                return Err(UrdfErrorKind::MissingLink {
                    joint: joint.name.clone(),
                    link: link.clone(),
                });
            }
        }
    }
    let mut roots = robot
        .links
        .iter()
        .filter(|l| !robot.joints.iter().any(|j| j.child.link == l.name));
    let Some(root) = roots.next() else {
        return Err(UrdfErrorKind::NoRoot);
    };
    if let Some(loose) = roots.next() {
        return Err(UrdfErrorKind::NotConnected {
            link: loose.name.clone(),
            root: root.name.clone(),
        });
    }
    let mut chain = Vec::new();
    let mut link = root.name.as_str();
    loop {
        let children: Vec<_> = robot
            .joints
            .iter()
            .filter(|j| j.parent.link == link)
            .collect();
        match children.as_slice() {
            [] => return Ok(chain),
            [joint] => {
                if chain.len() > robot.joints.len() {
                    return Err(UrdfErrorKind::Loop {
                        link: link.to_string(),
                    });
                }
                chain.push(*joint);
                link = joint.child.link.as_str();
            }
            many => {
                return Err(UrdfErrorKind::Branch {
                    link: link.to_string(),
                    joints: many.iter().map(|j| j.name.clone()).collect(),
                });
            }
        }
    }
}

fn build_model(
    robot: &urdf_rs::Robot,
    chain: &[&urdf_rs::Joint],
) -> Result<ArmModel, UrdfErrorKind> {
    let revolute_count = chain
        .iter()
        .take_while(|j| j.joint_type == urdf_rs::JointType::Revolute)
        .count();
    if revolute_count < 6 {
        return Err(match chain.get(revolute_count) {
            Some(j)
                if revolute_count < chain.len() - 1
                    || j.joint_type != urdf_rs::JointType::Fixed =>
            {
                UrdfErrorKind::NotRevolute {
                    joint: j.name.clone(),
                    found: format!("{:?}", j.joint_type),
                    number: revolute_count + 1,
                }
            }
            _ => UrdfErrorKind::TooFewJoints {
                count: revolute_count,
            },
        });
    }
    let Some(camera_joint) = chain.get(6) else {
        return Err(UrdfErrorKind::NoCameraJoint {
            after: chain[5].name.clone(),
        });
    };
    if camera_joint.joint_type != urdf_rs::JointType::Fixed {
        return Err(UrdfErrorKind::CameraJointNotFixed {
            joint: camera_joint.name.clone(),
            found: format!("{:?}", camera_joint.joint_type),
        });
    }
    if !camera_joint.child.link.contains("camera") {
        return Err(UrdfErrorKind::NotCameraLink {
            link: camera_joint.child.link.clone(),
            joint: camera_joint.name.clone(),
        });
    }
    if let Some(extra) = chain.get(7) {
        return Err(UrdfErrorKind::AfterCamera {
            joint: extra.name.clone(),
        });
    }
    let joints: Vec<RevoluteJoint> = chain[..6]
        .iter()
        .map(|j| revolute(j))
        .collect::<Result<_, _>>()?;
    let mut link_names = vec![chain[0].parent.link.as_str()];
    link_names.extend(chain.iter().map(|j| j.child.link.as_str()));
    let links = link_names
        .iter()
        .map(|name| {
            let link = robot
                .links
                .iter()
                .find(|l| &l.name == name)
                .expect("checked above");
            link_body(link)
        })
        .collect::<Result<Vec<_>, _>>()?;
    let camera_origin = pose(
        &camera_joint.origin,
        &format!("joint `{}` origin", camera_joint.name),
    )?;
    Ok(ArmModel::new(
        robot.name.clone(),
        joints.try_into().expect("six joints"),
        camera_origin,
        links,
    ))
}

fn finite(values: &[f64], what: &str) -> Result<(), UrdfErrorKind> {
    match values.iter().find(|v| !v.is_finite()) {
        Some(&value) => Err(UrdfErrorKind::NonFinite {
            element: what.to_string(),
            value,
        }),
        None => Ok(()),
    }
}

fn pose(origin: &urdf_rs::Pose, what: &str) -> Result<Isometry3<f64>, UrdfErrorKind> {
    let [x, y, z] = origin.xyz.0;
    let [roll, pitch, yaw] = origin.rpy.0;
    finite(&[x, y, z, roll, pitch, yaw], what)?;
    Ok(Isometry3::from_parts(
        Translation3::new(x, y, z),
        UnitQuaternion::from_euler_angles(roll, pitch, yaw),
    ))
}

fn revolute(joint: &urdf_rs::Joint) -> Result<RevoluteJoint, UrdfErrorKind> {
    let name = &joint.name;
    let origin = pose(&joint.origin, &format!("joint `{name}` origin"))?;
    let axis = Vector3::from(joint.axis.xyz.0);
    finite(axis.as_slice(), &format!("joint `{name}` axis"))?;
    let axis = Unit::try_new(axis, 1e-9).ok_or_else(|| UrdfErrorKind::ZeroAxis {
        joint: name.clone(),
    })?;
    let limit = &joint.limit;
    if !(limit.lower.is_finite() && limit.upper.is_finite()) {
        return Err(UrdfErrorKind::NoLimits {
            joint: name.clone(),
        });
    }
    if limit.lower >= limit.upper {
        return Err(UrdfErrorKind::LimitsInverted {
            joint: name.clone(),
            lower: limit.lower,
            upper: limit.upper,
        });
    }
    finite(
        &[limit.effort, limit.velocity],
        &format!("joint `{name}` limit"),
    )?;
    if limit.effort <= 0.0 || limit.velocity <= 0.0 {
        return Err(UrdfErrorKind::NoEffort {
            joint: name.clone(),
            effort: limit.effort,
            velocity: limit.velocity,
        });
    }
    let (damping, friction) = joint
        .dynamics
        .as_ref()
        .map_or((0.0, 0.0), |d| (d.damping, d.friction));
    if !(damping.is_finite() && damping >= 0.0 && friction.is_finite() && friction >= 0.0) {
        return Err(UrdfErrorKind::BadDynamics {
            joint: name.clone(),
            damping,
            friction,
        });
    }
    Ok(RevoluteJoint {
        name: name.clone(),
        origin,
        axis,
        lower: limit.lower,
        upper: limit.upper,
        effort: limit.effort,
        velocity: limit.velocity,
        damping,
        friction,
    })
}

fn link_body(link: &urdf_rs::Link) -> Result<LinkBody, UrdfErrorKind> {
    let name = &link.name;
    let inertial = &link.inertial;
    let i = &inertial.inertia;
    let mass = inertial.mass.value;
    finite(
        &[mass, i.ixx, i.ixy, i.ixz, i.iyy, i.iyz, i.izz],
        &format!("link `{name}` inertial"),
    )?;
    if mass <= 0.0 {
        return Err(UrdfErrorKind::NoMass {
            link: name.clone(),
            mass,
        });
    }
    let inertia = Matrix3::new(
        i.ixx, i.ixy, i.ixz, i.ixy, i.iyy, i.iyz, i.ixz, i.iyz, i.izz,
    );
    if inertia.symmetric_eigenvalues().iter().any(|&e| e <= 0.0) {
        return Err(UrdfErrorKind::BadInertia { link: name.clone() });
    }
    let collisions = link
        .collision
        .iter()
        .map(|c| {
            Ok((
                pose(&c.origin, &format!("link `{name}` collision origin"))?,
                shape(&c.geometry, name)?,
            ))
        })
        .collect::<Result<_, UrdfErrorKind>>()?;
    Ok(LinkBody {
        name: name.clone(),
        mass,
        inertial_origin: pose(&inertial.origin, &format!("link `{name}` inertial origin"))?,
        inertia,
        collisions,
    })
}

fn shape(geometry: &urdf_rs::Geometry, link: &str) -> Result<Shape, UrdfErrorKind> {
    let positive = |values: &[f64]| values.iter().all(|v| v.is_finite() && *v > 0.0);
    let shape = match *geometry {
        urdf_rs::Geometry::Box { size } => Shape::Cuboid(Vector3::from(size.0)),
        urdf_rs::Geometry::Cylinder { radius, length } => Shape::Cylinder { radius, length },
        urdf_rs::Geometry::Capsule { radius, length } => Shape::Capsule { radius, length },
        urdf_rs::Geometry::Sphere { radius } => Shape::Sphere { radius },
        urdf_rs::Geometry::Mesh { ref filename, .. } => {
            return Err(UrdfErrorKind::MeshCollision {
                link: link.to_string(),
                filename: filename.clone(),
            })
        }
    };
    let dims: Vec<f64> = match shape {
        Shape::Cuboid(size) => size.as_slice().to_vec(),
        Shape::Cylinder { radius, length } | Shape::Capsule { radius, length } => {
            vec![radius, length]
        }
        Shape::Sphere { radius } => vec![radius],
    };
    if positive(&dims) {
        Ok(shape)
    } else {
        Err(UrdfErrorKind::BadShape {
            link: link.to_string(),
        })
    }
}
