//! What can be wrong with a robot description or a chain asked of it, as data: kinds with
//! the names and numbers of the elements at fault.

/// A URDF that cannot be read as a robot description, or a chain that cannot be cut from it:
/// the file and what is wrong.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("{file}: {kind}")]
pub struct DescriptionError {
    /// The URDF file as the user named it.
    pub file: String,
    /// What is wrong.
    pub kind: DescriptionErrorKind,
}

/// What is wrong, naming the element.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum DescriptionErrorKind {
    /// The file cannot be read.
    #[error("cannot read: {reason}")]
    Unreadable {
        /// The operating system's reason.
        reason: String,
    },
    /// A `.xacro` file, and no `xacro` program on the PATH to expand it.
    #[error(
        "is a xacro file and the `xacro` program that expands it is not on the PATH: install \
         it (`pip install xacro`, or ROS's xacro package) or expand the file yourself \
         (`xacro FILE > FILE.urdf`) and name the URDF"
    )]
    XacroMissing,
    /// The `xacro` program failed on the file.
    #[error("`xacro` could not expand it (exit status {}): {reason}",
        .status.map_or("none".to_string(), |s| s.to_string()))]
    XacroFailed {
        /// Its exit status (`None`: it was not run, or a signal ended it).
        status: Option<i32>,
        /// What it said (the end of its error output).
        reason: String,
    },
    /// Not XML, or not a URDF urdf-rs can read.
    #[error("not a valid URDF: {reason}")]
    NotUrdf {
        /// The reader's reason.
        reason: String,
    },
    /// A robot without links.
    #[error("the robot has no links")]
    NoLinks,
    /// Two links with one name.
    #[error("two links are named `{link}`")]
    DuplicateLink {
        /// The name.
        link: String,
    },
    /// Two joints with one name.
    #[error("two joints are named `{joint}`")]
    DuplicateJoint {
        /// The name.
        joint: String,
    },
    /// A joint names a link that does not exist.
    #[error("joint `{joint}` names {role} link `{link}`, which does not exist")]
    MissingLink {
        /// The joint.
        joint: String,
        /// `parent` or `child`.
        role: String,
        /// The link it names.
        link: String,
    },
    /// A link that is the child of more than one joint.
    #[error("link `{link}` has two parents: it is the child of joints {}", .joints.join(", "))]
    TwoParents {
        /// The link.
        link: String,
        /// The joints that name it as their child.
        joints: Vec<String>,
    },
    /// Joints that lead in a circle.
    #[error("the links {} form a cycle", .links.join(" → "))]
    Cycle {
        /// The links of the cycle, in parent order, the first repeated at the end.
        links: Vec<String>,
    },
    /// More than one link without a parent joint.
    #[error("the links form no single tree: {} have no parent joint", .roots.join(", "))]
    TwoRoots {
        /// Every link without a parent joint.
        roots: Vec<String>,
    },
    /// A floating, planar or spherical joint.
    #[error("joint `{joint}` has type {found}: only fixed, revolute, continuous and prismatic joints are read")]
    UnsupportedJoint {
        /// The joint.
        joint: String,
        /// Its type.
        found: String,
    },
    /// A number that is NaN or infinite where it must be finite.
    #[error("{element} has a non-finite number ({value})")]
    NonFinite {
        /// The element (`joint `j` origin`, `link `l` inertial`, …).
        element: String,
        /// The number.
        value: f64,
    },
    /// A number beyond the physical range of its kind (see `ranges.rs`).
    #[error("{element}: {} is outside the physical range ({})",
        super::ranges::with_unit(*.value, .unit), super::ranges::range_text(*.low, *.high, .unit))]
    OutOfPhysicalRange {
        /// The element (`joint `j` origin`, `link `l` inertial`, …).
        element: String,
        /// The number.
        value: f64,
        /// The least size it may have (0: none).
        low: f64,
        /// The largest size it may have.
        high: f64,
        /// Its unit ("" for none).
        unit: &'static str,
    },
    /// A moving joint's axis of length zero.
    #[error("joint `{joint}` has a zero axis")]
    ZeroAxis {
        /// The joint.
        joint: String,
    },
    /// A revolute or prismatic joint whose lower limit is not below its upper one.
    #[error("joint `{joint}` has lower limit {lower} not below its upper limit {upper}")]
    BadLimits {
        /// The joint.
        joint: String,
        /// Lower limit (rad or m).
        lower: f64,
        /// Upper limit (rad or m).
        upper: f64,
    },
    /// A `<dynamics>` damping or friction that is negative.
    #[error("joint `{joint}` needs a non-negative dynamics damping and friction (has {damping} N·m·s/rad, {friction} N·m)")]
    BadDynamics {
        /// The joint.
        joint: String,
        /// Viscous damping (N·m·s/rad or N·s/m).
        damping: f64,
        /// Dry friction (N·m or N).
        friction: f64,
    },
    /// A negative mass.
    #[error("link `{link}` has a negative mass ({mass} kg)")]
    NegativeMass {
        /// The link.
        link: String,
        /// Its mass (kg).
        mass: f64,
    },
    /// An inertia tensor with a negative eigenvalue.
    #[error(
        "link `{link}` has an inertia tensor with a negative principal moment ({moment} kg·m²)"
    )]
    BadInertia {
        /// The link.
        link: String,
        /// The smallest principal moment (kg·m²).
        moment: f64,
    },
    /// A box, cylinder, capsule or sphere with a size that is not positive and finite.
    #[error("link `{link}` has a {shape} with a size that is not positive")]
    BadShape {
        /// The link.
        link: String,
        /// `box`, `cylinder`, `capsule` or `sphere`.
        shape: String,
    },
    /// A mesh scale with a zero or non-finite factor.
    #[error("link `{link}` scales mesh `{filename}` by a zero or non-finite factor")]
    BadScale {
        /// The link.
        link: String,
        /// The mesh as the URDF names it.
        filename: String,
    },
    /// A mesh file that is there but is not a usable OBJ or STL mesh.
    #[error("link `{link}`: mesh `{filename}` is not a mesh: {reason}")]
    NotAMesh {
        /// The link.
        link: String,
        /// The mesh as the URDF names it.
        filename: String,
        /// What is wrong with it.
        reason: String,
    },
    /// A `package://` mesh that would be read from outside its `package_paths` folder.
    #[error(
        "link `{link}`: mesh `{filename}` leads outside its package folder (`..`, a root or an \
         empty part, or a symbolic link out of it); only files inside a package_paths folder \
         are read"
    )]
    MeshOutsidePackage {
        /// The link.
        link: String,
        /// The mesh as the URDF names it.
        filename: String,
    },
    /// A relative, absolute or `file://` mesh outside the URDF's folder and every
    /// `package_paths` folder.
    #[error(
        "link `{link}`: mesh `{filename}` lies outside the URDF's folder and every \
         package_paths folder (after resolving `..` and symbolic links); add its folder to \
         package_paths to read it"
    )]
    MeshOutsideFolders {
        /// The link.
        link: String,
        /// The mesh as the URDF names it.
        filename: String,
    },
    /// A collision mesh in a format other than OBJ, STL and COLLADA.
    #[error("link `{link}`: collision mesh `{filename}` is not OBJ, STL or COLLADA")]
    UnsupportedMesh {
        /// The link.
        link: String,
        /// The mesh as the URDF names it.
        filename: String,
    },
    /// A camera link that is not a link of the robot.
    #[error("camera link `{link}` is not a link of the robot")]
    UnknownLink {
        /// The name asked for.
        link: String,
    },
    /// A base link that is not a link of the robot.
    #[error("base link `{link}` is not a link of the robot")]
    UnknownBaseLink {
        /// The name asked for.
        link: String,
    },
    /// A camera link that does not hang below the base link.
    #[error("camera link `{camera_link}` does not lie below base link `{base_link}`: the arm is the chain from the base link down to the camera link")]
    CameraNotBelowBase {
        /// The camera link.
        camera_link: String,
        /// The base link.
        base_link: String,
    },
    /// A moving joint on the chain that follows another (`<mimic>`): the arm's joints
    /// are moved one by one.
    #[error(
        "joint `{joint}` on the chain to the camera link follows `{leader}` (<mimic>): a chain \
         joint that mimics another is not supported; choose a camera_link before it"
    )]
    MimicOnChain {
        /// The follower.
        joint: String,
        /// The joint it mimics.
        leader: String,
    },
    /// A joint off the chain that follows a joint on it (`<mimic>`): it would move with
    /// the arm, which holds every joint off the chain.
    #[error(
        "joint `{joint}` off the chain follows `{leader}` on it (<mimic>): a held joint that \
         moves with the arm is not supported; choose a camera_link that leaves `{leader}` off \
         the chain"
    )]
    MimicsChainJoint {
        /// The follower.
        joint: String,
        /// The chain joint it mimics.
        leader: String,
    },
    /// A `<mimic>` naming a joint the robot does not have.
    #[error("joint `{joint}` mimics `{leader}`, which is not a joint of the robot")]
    UnknownMimicLeader {
        /// The follower.
        joint: String,
        /// The name it gives.
        leader: String,
    },
    /// A camera link with no moving joint between it and the root.
    #[error("camera link `{link}` does not move: no moving joint lies between it and the root")]
    NoMovingJoint {
        /// The camera link.
        link: String,
    },
    /// A learned joint that is not a joint of the robot.
    #[error("learned joint `{joint}` is not a joint of the robot")]
    UnknownJoint {
        /// The name asked for.
        joint: String,
    },
    /// A learned joint that is fixed.
    #[error("learned joint `{joint}` is a fixed joint")]
    LearnedJointFixed {
        /// The joint.
        joint: String,
    },
    /// A learned joint that does not lie between the root and the camera link.
    #[error(
        "learned joint `{joint}` is not on the chain from the root to camera link `{camera_link}`"
    )]
    LearnedJointOffChain {
        /// The joint.
        joint: String,
        /// The camera link.
        camera_link: String,
    },
    /// A learned joint named twice.
    #[error("learned joint `{joint}` is named twice")]
    LearnedJointRepeated {
        /// The joint.
        joint: String,
    },
    /// `learned_joints auto` on a chain with no joint turning about the vertical at rest.
    #[error("learned_joints auto: no joint on the chain turns about the vertical at the rest pose (a base yaw); name the learned joints")]
    NoBaseYaw,
    /// `learned_joints auto` on a chain with fewer than two joints after its base yaw.
    #[error("learned_joints auto: the chain has {after_base} moving joints after its base yaw, and a shoulder and an elbow are needed")]
    TooFewJointsToLearn {
        /// Moving joints after the base yaw.
        after_base: usize,
    },
    /// A camera that no pose of the wrist turns to look straight down.
    #[error(
        "the camera on `{camera_link}` cannot look down: {}; if the camera looks along \
         another axis of its link, say how it is mounted with camera_mount (roll,pitch,yaw \
         turn the link's z axis onto the optical axis)",
        if .wrist.is_empty() {
            "no joint is left after the three learned ones to turn it".to_string()
        } else {
            format!("the joints after the learned ones ({}) turn the optical axis (the link's \
                     z axis as camera_mount turns it) straight down inside their limits at \
                     none of {} shoulder-elbow poses tried", .wrist.join(", "), .tried)
        }
    )]
    CannotLookDown {
        /// The camera link.
        camera_link: String,
        /// The joints that are not learned, nearest the base first.
        wrist: Vec<String>,
        /// The shoulder–elbow poses tried.
        tried: usize,
    },
    /// A camera that looks back into its own arm: a joint of the chain lies on its optical
    /// axis in front of it when it looks down.
    #[error(
        "the camera on `{camera_link}` looks back into the arm: joint `{joint}` lies {distance_cm:.1} cm \
         in front of it on its optical axis (the link's z axis) when it looks down; say with \
         camera_mount how it is mounted to look away from the arm"
    )]
    CameraFacesArm {
        /// The camera link.
        camera_link: String,
        /// The joint in front of the camera.
        joint: String,
        /// How far in front (cm).
        distance_cm: f64,
    },
    /// A chain with more moving joints than an arm model holds.
    #[error("the chain has {found} moving joints; an arm may have at most {max}")]
    TooManyJoints {
        /// Moving joints on the chain.
        found: usize,
        /// The most an arm model holds.
        max: usize,
    },
    /// A prismatic joint between the root and the camera link (arms turn their joints).
    #[error("joint `{joint}` on the chain to the camera is prismatic; an arm's joints must turn")]
    PrismaticOnChain {
        /// The joint.
        joint: String,
    },
    /// A joint vector or frame buffer of the wrong length for the chain.
    #[error("the chain has {expected} moving joints; {found} values were given")]
    JointCount {
        /// The chain's moving joints (or frames).
        expected: usize,
        /// The length given.
        found: usize,
    },
}
