//! A broken or unsupported URDF is a clear error naming the element at fault.

use eyehand::robot::{load_urdf, parse_urdf, ArmModel};

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

fn error_of(text: &str) -> String {
    parse_urdf(text, "arm.urdf").unwrap_err().to_string()
}

fn assert_error(text: &str, expected: &[&str]) {
    let message = error_of(text);
    assert!(message.starts_with("arm.urdf: "), "{message}");
    for part in expected {
        assert!(
            message.contains(part),
            "`{message}` should contain `{part}`"
        );
    }
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
}

#[test]
fn a_missing_joint_is_named() {
    assert_error(
        &without_joint("joint_4"),
        &["link `link_4`", "a joint is missing"],
    );
    assert_error(
        &without_joint("camera_joint"),
        &["link `camera_link`", "a joint is missing"],
    );
}

#[test]
fn a_wrong_joint_type_is_named() {
    let text = shipped().replace(
        r#"<joint name="joint_3" type="revolute">"#,
        r#"<joint name="joint_3" type="prismatic">"#,
    );
    assert_error(&text, &["joint `joint_3`", "Prismatic", "must be revolute"]);
    let text = shipped().replace(
        r#"<joint name="camera_joint" type="fixed">"#,
        r#"<joint name="camera_joint" type="revolute">"#,
    );
    assert_error(&text, &["camera_joint", "fixed camera joint"]);
}

#[test]
fn bad_numbers_are_named() {
    let text = shipped().replace(
        r#"<origin xyz="0.60 0 0" rpy="0 0 0"/>"#,
        r#"<origin xyz="0.60 0 inf" rpy="0 0 0"/>"#,
    );
    assert_error(&text, &["joint `joint_3` origin", "non-finite"]);
    let text = shipped().replace(
        r#"<limit lower="-0.524" upper="1.745""#,
        r#"<limit lower="1.9" upper="1.745""#,
    );
    assert_error(&text, &["joint `joint_2`", "lower limit 1.9"]);
    let text = shipped().replace(r#"<mass value="17.0"/>"#, r#"<mass value="-17.0"/>"#);
    assert_error(&text, &["link `link_2`", "positive mass"]);
    let text = shipped().replace(r#"<axis xyz="0 1 0"/>"#, r#"<axis xyz="0 0 0"/>"#);
    assert_error(&text, &["joint `joint_3`", "zero axis"]);
    let text = shipped().replace(
        r#"<cylinder radius="0.08" length="0.60"/>"#,
        r#"<cylinder radius="0.08" length="-0.60"/>"#,
    );
    assert_error(&text, &["link `link_2`", "size that is not positive"]);
}

#[test]
fn unsupported_structures_are_named() {
    let text = shipped()
        .replace(
            r#"<child link="camera_link"/>"#,
            r#"<child link="eye_link"/>"#,
        )
        .replace(r#"<link name="camera_link">"#, r#"<link name="eye_link">"#);
    assert_error(&text, &["link `eye_link`", "not a camera link"]);
    let text = shipped().replace(
        r#"<geometry><sphere radius="0.045"/></geometry>"#,
        r#"<geometry><mesh filename="wrist.stl"/></geometry>"#,
    );
    assert_error(&text, &["link `link_5`", "mesh"]);
    let branch = shipped().replace(
        "</robot>",
        r#"<link name="tool"><inertial><mass value="1"/><inertia ixx="1" ixy="0" ixz="0" iyy="1" iyz="0" izz="1"/></inertial></link>
        <joint name="tool_joint" type="fixed"><parent link="link_3"/><child link="tool"/></joint></robot>"#,
    );
    assert_error(
        &branch,
        &["link `link_3` has 2 child joints", "serial chain"],
    );
}

#[test]
fn broken_xml_and_missing_files_are_errors() {
    assert_error("<robot name=\"x\"><link name=", &["not a valid URDF"]);
    let err = load_urdf(std::path::Path::new("/no/such/arm.urdf")).unwrap_err();
    assert!(
        err.to_string()
            .starts_with("/no/such/arm.urdf: cannot read"),
        "{err}"
    );
}
