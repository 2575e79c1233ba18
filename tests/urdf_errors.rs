//! A broken or unsupported OSCAR-6 URDF, read as a robot description at the default arm
//! settings, is a clear error naming the element at fault; tests match on the error's kind.

use eyehand::robot::description::{
    DescriptionErrorKind as Kind, DescriptionOptions, RobotDescription,
};
use eyehand::robot::{load_urdf, parse_urdf, ArmModel, ArmSettings, Shape};
use std::path::Path;

fn shipped() -> String {
    std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/urdf/oscar6.urdf")).unwrap()
}

/// The shipped URDF with the joint element named `name` removed.
fn without_joint(name: &str) -> String {
    let text = shipped();
    let start = text.find(&format!("<joint name=\"{name}\"")).unwrap();
    let end = start + text[start..].find("</joint>").unwrap() + "</joint>".len();
    format!("{}{}", &text[..start], &text[end..])
}

fn kind_of(text: &str) -> Kind {
    let err = parse_urdf(text, "arm.urdf").unwrap_err();
    assert_eq!(err.file, "arm.urdf");
    assert!(err.to_string().starts_with("arm.urdf: "), "{err}");
    err.kind
}

#[test]
fn the_shipped_urdf_loads_with_its_masses() {
    let model = load_urdf(std::path::Path::new(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/urdf/oscar6.urdf"
    )))
    .unwrap();
    assert_eq!(model, ArmModel::oscar6());
    assert_eq!(model.name(), "oscar6");
    assert_eq!(model.links().len(), 8);
    let arm_mass: f64 = model.links()[1..4].iter().map(|l| l.mass).sum();
    assert!(arm_mass > 40.0, "tens of kg in the big links: {arm_mass}");
    let with_bom = format!("\u{feff}{}", shipped());
    assert_eq!(parse_urdf(&with_bom, "bom.urdf").unwrap(), model);
}

#[test]
fn a_missing_joint_is_named() {
    for (joint, link) in [("joint_4", "link_4"), ("camera_joint", "camera_link")] {
        assert_eq!(
            kind_of(&without_joint(joint)),
            Kind::TwoRoots {
                roots: vec!["base_link".into(), link.into()]
            }
        );
    }
}

#[test]
fn a_wrong_joint_type_is_named() {
    let text = shipped().replace(
        r#"<joint name="joint_3" type="revolute">"#,
        r#"<joint name="joint_3" type="prismatic">"#,
    );
    assert_eq!(
        kind_of(&text),
        Kind::PrismaticOnChain {
            joint: "joint_3".into()
        }
    );
    let text = shipped().replace(
        r#"<joint name="camera_joint" type="fixed">"#,
        r#"<joint name="camera_joint" type="revolute">"#,
    );
    // A camera joint that turns without limits.
    assert!(matches!(
        kind_of(&text),
        Kind::BadLimits { joint, .. } if joint == "camera_joint"
    ));
}

#[test]
fn bad_numbers_are_named() {
    let text = shipped().replace(
        r#"<origin xyz="0.60 0 0" rpy="0 0 0"/>"#,
        r#"<origin xyz="0.60 0 inf" rpy="0 0 0"/>"#,
    );
    assert!(matches!(
        kind_of(&text),
        Kind::NonFinite { element, value } if element == "joint `joint_3` origin" && value.is_infinite()
    ));
    let text = shipped().replace(
        r#"<limit lower="-0.524" upper="1.745""#,
        r#"<limit lower="1.9" upper="1.745""#,
    );
    assert_eq!(
        kind_of(&text),
        Kind::BadLimits {
            joint: "joint_2".into(),
            lower: 1.9,
            upper: 1.745
        }
    );
    let text = shipped().replace(r#"<mass value="17.0"/>"#, r#"<mass value="-17.0"/>"#);
    assert_eq!(
        kind_of(&text),
        Kind::NegativeMass {
            link: "link_2".into(),
            mass: -17.0
        }
    );
    let text = shipped().replace(r#"<axis xyz="0 1 0"/>"#, r#"<axis xyz="0 0 0"/>"#);
    assert!(matches!(kind_of(&text), Kind::ZeroAxis { joint } if joint == "joint_3"));
    let text = shipped().replace(
        r#"<cylinder radius="0.08" length="0.60"/>"#,
        r#"<cylinder radius="0.08" length="-0.60"/>"#,
    );
    assert!(matches!(
        kind_of(&text),
        Kind::BadShape { link, shape } if link == "link_2" && shape == "cylinder"
    ));
    let text = shipped().replace(
        r#"<limit lower="-0.524" upper="1.745" effort="600" velocity="1.6"/>"#,
        r#"<limit lower="-0.524" upper="1.745" effort="600" velocity="1.6"/><dynamics damping="-2"/>"#,
    );
    assert!(matches!(
        kind_of(&text),
        Kind::BadDynamics { joint, damping, .. } if joint == "joint_2" && damping == -2.0
    ));
}

#[test]
fn a_camera_link_that_is_not_there_is_named_and_auto_finds_the_chain_end() {
    let text = shipped()
        .replace(
            r#"<child link="camera_link"/>"#,
            r#"<child link="eye_link"/>"#,
        )
        .replace(r#"<link name="camera_link">"#, r#"<link name="eye_link">"#);
    let options = DescriptionOptions::default();
    let description = RobotDescription::parse(&text, "arm.urdf", Path::new("."), &options).unwrap();
    let named = ArmSettings {
        camera_link: "camera_link".into(),
        ..ArmSettings::default()
    };
    let err = ArmModel::from_description(&description, &named).unwrap_err();
    assert_eq!(
        err.kind,
        Kind::UnknownLink {
            link: "camera_link".into()
        }
    );
    let auto = parse_urdf(&text, "arm.urdf").unwrap();
    assert_eq!(auto.links().last().unwrap().name, "eye_link");
}

#[test]
fn meshes_and_branches_are_read_as_any_arm_reads_them() {
    // A collision mesh that is not there: a capsule stands in (a warning of the description).
    let text = shipped().replace(
        r#"<geometry><sphere radius="0.045"/></geometry>"#,
        r#"<geometry><mesh filename="no_such_wrist.stl"/></geometry>"#,
    );
    let model = parse_urdf(&text, "arm.urdf").unwrap();
    assert!(matches!(
        model.links()[5].collisions.as_slice(),
        [(_, Shape::Capsule { .. })]
    ));
    // A tool fixed to link 3 becomes part of link 3's body.
    let branch = shipped().replace(
        "</robot>",
        r#"<link name="tool"><inertial><mass value="1"/><inertia ixx="1" ixy="0" ixz="0" iyy="1" iyz="0" izz="1"/></inertial></link>
        <joint name="tool_joint" type="fixed"><parent link="link_3"/><child link="tool"/></joint></robot>"#,
    );
    let model = parse_urdf(&branch, "arm.urdf").unwrap();
    let oscar = ArmModel::oscar6();
    assert_eq!(model.links()[3].mass, oscar.links()[3].mass + 1.0);
    assert_eq!(model.links()[4], oscar.links()[4]);
}

#[test]
fn broken_xml_and_missing_files_are_errors() {
    assert!(matches!(
        kind_of("<robot name=\"x\"><link name="),
        Kind::NotUrdf { .. }
    ));
    let err = load_urdf(std::path::Path::new("/no/such/arm.urdf")).unwrap_err();
    assert!(matches!(err.kind, Kind::Unreadable { .. }));
    assert!(
        err.to_string()
            .starts_with("/no/such/arm.urdf: cannot read"),
        "{err}"
    );
}
