//! urdf-rs values into nalgebra ones, checked: poses, inertials and joints.

use super::inertia::Inertial;
use super::joint::{Joint, JointDynamics, JointKind, JointLimits};
use super::ranges::{within, MAX_LENGTH_M, MAX_MASS_KG};
use super::DescriptionErrorKind as Kind;
use nalgebra::{Isometry3, Matrix3, Point3, Translation3, Unit, UnitQuaternion, Vector3};

/// An error unless every value is finite; `element` names where they come from.
pub(super) fn finite(values: &[f64], element: &str) -> Result<(), Kind> {
    match values.iter().find(|v| !v.is_finite()) {
        Some(&value) => Err(Kind::NonFinite {
            element: element.to_string(),
            value,
        }),
        None => Ok(()),
    }
}

/// An `<origin>`: translation xyz and rotation R = Rz(yaw)·Ry(pitch)·Rx(roll).
pub(super) fn pose(origin: &urdf_rs::Pose, element: &str) -> Result<Isometry3<f64>, Kind> {
    let [x, y, z] = origin.xyz.0;
    let [roll, pitch, yaw] = origin.rpy.0;
    finite(&[x, y, z, roll, pitch, yaw], element)?;
    within(&[x, y, z], (0.0, MAX_LENGTH_M), element, "m")?;
    Ok(Isometry3::from_parts(
        Translation3::new(x, y, z),
        UnitQuaternion::from_euler_angles(roll, pitch, yaw),
    ))
}

/// A link's `<inertial>` in the link frame's axes; a massless link's inertia is dropped.
pub(super) fn inertial(link: &urdf_rs::Link) -> Result<Inertial, Kind> {
    let name = &link.name;
    let given = &link.inertial;
    let i = &given.inertia;
    let mass = given.mass.value;
    finite(
        &[mass, i.ixx, i.ixy, i.ixz, i.iyy, i.iyz, i.izz],
        &format!("link `{name}` inertial"),
    )?;
    if mass < 0.0 {
        return Err(Kind::NegativeMass {
            link: name.clone(),
            mass,
        });
    }
    within(
        &[mass],
        (0.0, MAX_MASS_KG),
        &format!("link `{name}` mass"),
        "kg",
    )?;
    if mass == 0.0 {
        return Ok(Inertial::MASSLESS);
    }
    let inertia = Matrix3::new(
        i.ixx, i.ixy, i.ixz, i.ixy, i.iyy, i.iyz, i.ixz, i.iyz, i.izz,
    );
    let moment = inertia.symmetric_eigenvalues().min();
    if moment < -1e-12 * inertia.norm() {
        return Err(Kind::BadInertia {
            link: name.clone(),
            moment,
        });
    }
    let frame = pose(&given.origin, &format!("link `{name}` inertial origin"))?;
    Ok(Inertial {
        mass,
        com: Point3::origin(),
        inertia,
    }
    .transformed(&frame))
}

/// A joint with its links' indices; `link_index` finds a link by name (checked before).
pub(super) fn joint(
    joint: &urdf_rs::Joint,
    link_index: impl Fn(&str) -> usize,
) -> Result<Joint, Kind> {
    let name = &joint.name;
    let kind = match joint.joint_type {
        urdf_rs::JointType::Fixed => JointKind::Fixed,
        urdf_rs::JointType::Revolute => JointKind::Revolute,
        urdf_rs::JointType::Continuous => JointKind::Continuous,
        urdf_rs::JointType::Prismatic => JointKind::Prismatic,
        ref other => {
            return Err(Kind::UnsupportedJoint {
                joint: name.clone(),
                found: format!("{other:?}").to_lowercase(),
            })
        }
    };
    let origin = pose(&joint.origin, &format!("joint `{name}` origin"))?;
    let axis = if kind.moves() {
        let axis = Vector3::from(joint.axis.xyz.0);
        finite(axis.as_slice(), &format!("joint `{name}` axis"))?;
        Unit::try_new(axis, 1e-9).ok_or_else(|| Kind::ZeroAxis {
            joint: name.clone(),
        })?
    } else {
        Vector3::x_axis()
    };
    let dynamics = joint
        .dynamics
        .as_ref()
        .map_or(JointDynamics::default(), |d| JointDynamics {
            damping: d.damping,
            friction: d.friction,
        });
    finite(
        &[dynamics.damping, dynamics.friction],
        &format!("joint `{name}` dynamics"),
    )?;
    if dynamics.damping < 0.0 || dynamics.friction < 0.0 {
        return Err(Kind::BadDynamics {
            joint: name.clone(),
            damping: dynamics.damping,
            friction: dynamics.friction,
        });
    }
    Ok(Joint {
        name: name.clone(),
        kind,
        parent: link_index(&joint.parent.link),
        child: link_index(&joint.child.link),
        origin,
        axis,
        limits: limits(joint, kind)?,
        dynamics,
    })
}

fn limits(joint: &urdf_rs::Joint, kind: JointKind) -> Result<JointLimits, Kind> {
    let given = &joint.limit;
    let positive = |v: f64| (v.is_finite() && v > 0.0).then_some(v);
    let (lower, upper) = match kind {
        JointKind::Fixed => (0.0, 0.0),
        JointKind::Continuous => (f64::NEG_INFINITY, f64::INFINITY),
        JointKind::Revolute | JointKind::Prismatic => {
            if given.lower.is_nan() || given.upper.is_nan() || given.lower >= given.upper {
                return Err(Kind::BadLimits {
                    joint: joint.name.clone(),
                    lower: given.lower,
                    upper: given.upper,
                });
            }
            (given.lower, given.upper)
        }
    };
    Ok(JointLimits {
        lower,
        upper,
        effort: positive(given.effort),
        velocity: positive(given.velocity),
    })
}
