//! Reading the arm from a URDF file with urdf-rs, and checking that it is an OSCAR-6:
//! a serial chain of six revolute joints from the root link, then a fixed joint to a
//! camera link (a link whose name contains `camera`).

use super::joint::{LinkBody, RevoluteJoint, Shape};
use super::model::ArmModel;
use super::UrdfError;
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
        reason: format!("cannot read: {e}"),
    })?;
    parse_urdf(&text, &name)
}

/// Parses and checks URDF text; `file` names it in errors.
pub fn parse_urdf(text: &str, file: &str) -> Result<ArmModel, UrdfError> {
    let fail = |reason: String| UrdfError {
        file: file.to_string(),
        reason,
    };
    let robot =
        urdf_rs::read_from_string(text).map_err(|e| fail(format!("not a valid URDF: {e}")))?;
    let chain = serial_chain(&robot).map_err(fail)?;
    build_model(&robot, &chain).map_err(fail)
}

/// The joints from the root link to the chain's end, in order.
fn serial_chain(robot: &urdf_rs::Robot) -> Result<Vec<&urdf_rs::Joint>, String> {
    for joint in &robot.joints {
        for link in [&joint.parent.link, &joint.child.link] {
            if !robot.links.iter().any(|l| &l.name == link) {
                return Err(format!(
                    "joint `{}` names link `{link}`, which does not exist",
                    joint.name
                ));
            }
        }
    }
    let mut roots = robot
        .links
        .iter()
        .filter(|l| !robot.joints.iter().any(|j| j.child.link == l.name));
    let Some(root) = roots.next() else {
        return Err("no root link: every link is some joint's child".to_string());
    };
    if let Some(loose) = roots.next() {
        return Err(format!(
            "link `{}` is not connected to `{}`: a joint is missing",
            loose.name, root.name
        ));
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
                    return Err(format!("the joints after link `{link}` form a loop"));
                }
                chain.push(*joint);
                link = joint.child.link.as_str();
            }
            many => {
                let names: Vec<_> = many.iter().map(|j| j.name.as_str()).collect();
                return Err(format!(
                    "link `{link}` has {} child joints ({}): the arm must be a serial chain",
                    many.len(),
                    names.join(", ")
                ));
            }
        }
    }
}

fn build_model(robot: &urdf_rs::Robot, chain: &[&urdf_rs::Joint]) -> Result<ArmModel, String> {
    let revolute_count = chain
        .iter()
        .take_while(|j| j.joint_type == urdf_rs::JointType::Revolute)
        .count();
    if revolute_count < 6 {
        return Err(match chain.get(revolute_count) {
            Some(j) if revolute_count < chain.len() - 1 || j.joint_type != urdf_rs::JointType::Fixed => format!(
                "joint `{}` has type {:?}; joint {} of the OSCAR-6 must be revolute",
                j.name,
                j.joint_type,
                revolute_count + 1
            ),
            _ => format!(
                "the chain has {revolute_count} revolute joints; the OSCAR-6 needs 6 (missing joint {})",
                revolute_count + 1
            ),
        });
    }
    let Some(camera_joint) = chain.get(6) else {
        return Err(format!(
            "missing the fixed camera joint after joint `{}`",
            chain[5].name
        ));
    };
    if camera_joint.joint_type != urdf_rs::JointType::Fixed {
        return Err(format!(
            "joint `{}` has type {:?}; the joint after the six revolute joints must be a fixed camera joint",
            camera_joint.name, camera_joint.joint_type
        ));
    }
    if !camera_joint.child.link.contains("camera") {
        return Err(format!(
            "link `{}` after the fixed joint `{}` is not a camera link (its name must contain `camera`)",
            camera_joint.child.link, camera_joint.name
        ));
    }
    if let Some(extra) = chain.get(7) {
        return Err(format!(
            "unexpected joint `{}` after the camera link",
            extra.name
        ));
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

fn finite(values: &[f64], what: &str) -> Result<(), String> {
    match values.iter().find(|v| !v.is_finite()) {
        Some(v) => Err(format!("{what} has a non-finite number ({v})")),
        None => Ok(()),
    }
}

fn pose(origin: &urdf_rs::Pose, what: &str) -> Result<Isometry3<f64>, String> {
    let [x, y, z] = origin.xyz.0;
    let [roll, pitch, yaw] = origin.rpy.0;
    finite(&[x, y, z, roll, pitch, yaw], what)?;
    Ok(Isometry3::from_parts(
        Translation3::new(x, y, z),
        UnitQuaternion::from_euler_angles(roll, pitch, yaw),
    ))
}

fn revolute(joint: &urdf_rs::Joint) -> Result<RevoluteJoint, String> {
    let name = &joint.name;
    let origin = pose(&joint.origin, &format!("joint `{name}` origin"))?;
    let axis = Vector3::from(joint.axis.xyz.0);
    finite(axis.as_slice(), &format!("joint `{name}` axis"))?;
    let axis =
        Unit::try_new(axis, 1e-9).ok_or_else(|| format!("joint `{name}` has a zero axis"))?;
    let limit = &joint.limit;
    if !(limit.lower.is_finite() && limit.upper.is_finite()) {
        return Err(format!(
            "joint `{name}` needs finite lower and upper limits"
        ));
    }
    if limit.lower >= limit.upper {
        return Err(format!(
            "joint `{name}` has lower limit {} not below its upper limit {}",
            limit.lower, limit.upper
        ));
    }
    finite(
        &[limit.effort, limit.velocity],
        &format!("joint `{name}` limit"),
    )?;
    if limit.effort <= 0.0 || limit.velocity <= 0.0 {
        return Err(format!(
            "joint `{name}` needs a positive effort and velocity limit"
        ));
    }
    Ok(RevoluteJoint {
        name: name.clone(),
        origin,
        axis,
        lower: limit.lower,
        upper: limit.upper,
        effort: limit.effort,
        velocity: limit.velocity,
    })
}

fn link_body(link: &urdf_rs::Link) -> Result<LinkBody, String> {
    let name = &link.name;
    let inertial = &link.inertial;
    let i = &inertial.inertia;
    let mass = inertial.mass.value;
    finite(
        &[mass, i.ixx, i.ixy, i.ixz, i.iyy, i.iyz, i.izz],
        &format!("link `{name}` inertial"),
    )?;
    if mass <= 0.0 {
        return Err(format!("link `{name}` needs a positive mass, has {mass}"));
    }
    let inertia = Matrix3::new(
        i.ixx, i.ixy, i.ixz, i.ixy, i.iyy, i.iyz, i.ixz, i.iyz, i.izz,
    );
    if inertia.symmetric_eigenvalues().iter().any(|&e| e <= 0.0) {
        return Err(format!(
            "link `{name}` has an inertia tensor that is not positive definite"
        ));
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
        .collect::<Result<_, String>>()?;
    Ok(LinkBody {
        name: name.clone(),
        mass,
        inertial_origin: pose(&inertial.origin, &format!("link `{name}` inertial origin"))?,
        inertia,
        collisions,
    })
}

fn shape(geometry: &urdf_rs::Geometry, link: &str) -> Result<Shape, String> {
    let positive = |values: &[f64]| values.iter().all(|v| v.is_finite() && *v > 0.0);
    let shape = match *geometry {
        urdf_rs::Geometry::Box { size } => Shape::Cuboid(Vector3::from(size.0)),
        urdf_rs::Geometry::Cylinder { radius, length } => Shape::Cylinder { radius, length },
        urdf_rs::Geometry::Capsule { radius, length } => Shape::Capsule { radius, length },
        urdf_rs::Geometry::Sphere { radius } => Shape::Sphere { radius },
        urdf_rs::Geometry::Mesh { ref filename, .. } => {
            return Err(format!("link `{link}` has a mesh collision (`{filename}`): only boxes, cylinders, capsules and spheres are supported"))
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
        Err(format!(
            "link `{link}` has a collision shape with a size that is not positive"
        ))
    }
}
