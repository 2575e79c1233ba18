//! Errors of the robot model and the simulators, as data: kinds with the names and numbers
//! of the elements at fault.

/// A URDF that cannot be the OSCAR-6: the file and what is wrong, naming the element.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("{file}: {kind}")]
pub struct UrdfError {
    /// The URDF file as the user named it.
    pub file: String,
    /// What is wrong.
    pub kind: UrdfErrorKind,
}

/// What is wrong with a URDF, with the names and numbers of the elements at fault.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum UrdfErrorKind {
    /// The file cannot be read.
    #[error("cannot read: {reason}")]
    Unreadable {
        /// The operating system's reason.
        reason: String,
    },
    /// Not XML, or not a URDF urdf-rs can read.
    #[error("not a valid URDF: {reason}")]
    NotUrdf {
        /// The reader's reason.
        reason: String,
    },
    /// A joint names a link that does not exist.
    #[error("joint `{joint}` names link `{link}`, which does not exist")]
    MissingLink {
        /// The joint.
        joint: String,
        /// The link it names.
        link: String,
    },
    /// Every link is some joint's child.
    #[error("no root link: every link is some joint's child")]
    NoRoot,
    /// A second link without a parent joint.
    #[error("link `{link}` is not connected to `{root}`: a joint is missing")]
    NotConnected {
        /// The loose link.
        link: String,
        /// The root link.
        root: String,
    },
    /// The joints form a loop.
    #[error("the joints after link `{link}` form a loop")]
    Loop {
        /// Where the loop was found.
        link: String,
    },
    /// A link with more than one child joint.
    #[error("link `{link}` has {} child joints ({}): the arm must be a serial chain", .joints.len(), .joints.join(", "))]
    Branch {
        /// The link.
        link: String,
        /// Its child joints.
        joints: Vec<String>,
    },
    /// One of the first six joints is not revolute.
    #[error("joint `{joint}` has type {found}; joint {number} of the OSCAR-6 must be revolute")]
    NotRevolute {
        /// The joint.
        joint: String,
        /// Its type.
        found: String,
        /// Its 1-based place in the chain.
        number: usize,
    },
    /// Fewer than six revolute joints.
    #[error("the chain has {count} revolute joints; the OSCAR-6 needs 6 (missing joint {})", .count + 1)]
    TooFewJoints {
        /// Revolute joints found.
        count: usize,
    },
    /// No joint after the sixth.
    #[error("missing the fixed camera joint after joint `{after}`")]
    NoCameraJoint {
        /// The sixth joint.
        after: String,
    },
    /// The joint after the sixth is not fixed.
    #[error("joint `{joint}` has type {found}; the joint after the six revolute joints must be a fixed camera joint")]
    CameraJointNotFixed {
        /// The joint.
        joint: String,
        /// Its type.
        found: String,
    },
    /// The fixed joint's child is not a camera link.
    #[error("link `{link}` after the fixed joint `{joint}` is not a camera link (its name must contain `camera`)")]
    NotCameraLink {
        /// The link.
        link: String,
        /// The fixed joint.
        joint: String,
    },
    /// A joint after the camera link.
    #[error("unexpected joint `{joint}` after the camera link")]
    AfterCamera {
        /// The joint.
        joint: String,
    },
    /// A number that is NaN or infinite.
    #[error("{element} has a non-finite number ({value})")]
    NonFinite {
        /// The element (`joint `j` origin`, `link `l` inertial`, …).
        element: String,
        /// The number.
        value: f64,
    },
    /// A joint axis of length zero.
    #[error("joint `{joint}` has a zero axis")]
    ZeroAxis {
        /// The joint.
        joint: String,
    },
    /// A joint without finite limits.
    #[error("joint `{joint}` needs finite lower and upper limits")]
    NoLimits {
        /// The joint.
        joint: String,
    },
    /// A lower limit not below the upper one.
    #[error("joint `{joint}` has lower limit {lower} not below its upper limit {upper}")]
    LimitsInverted {
        /// The joint.
        joint: String,
        /// Lower limit (rad).
        lower: f64,
        /// Upper limit (rad).
        upper: f64,
    },
    /// An effort or velocity limit that is not positive.
    #[error("joint `{joint}` needs a positive effort and velocity limit (has {effort} N·m, {velocity} rad/s)")]
    NoEffort {
        /// The joint.
        joint: String,
        /// Effort limit (N·m).
        effort: f64,
        /// Velocity limit (rad/s).
        velocity: f64,
    },
    /// A `<dynamics>` damping or friction that is negative or not finite.
    #[error("joint `{joint}` needs a finite, non-negative dynamics damping and friction (has {damping} N·m·s/rad, {friction} N·m)")]
    BadDynamics {
        /// The joint.
        joint: String,
        /// Viscous damping (N·m·s/rad).
        damping: f64,
        /// Dry friction (N·m).
        friction: f64,
    },
    /// A link mass that is not positive.
    #[error("link `{link}` needs a positive mass, has {mass}")]
    NoMass {
        /// The link.
        link: String,
        /// Its mass (kg).
        mass: f64,
    },
    /// An inertia tensor with an eigenvalue ≤ 0.
    #[error("link `{link}` has an inertia tensor that is not positive definite")]
    BadInertia {
        /// The link.
        link: String,
    },
    /// A mesh collision shape.
    #[error("link `{link}` has a mesh collision (`{filename}`): only boxes, cylinders, capsules and spheres are supported")]
    MeshCollision {
        /// The link.
        link: String,
        /// The mesh file.
        filename: String,
    },
    /// A collision shape with a size that is not positive.
    #[error("link `{link}` has a collision shape with a size that is not positive")]
    BadShape {
        /// The link.
        link: String,
    },
    /// A robot description (any arm's URDF, `robot::description`) that cannot be read.
    #[error("{0}")]
    Description(super::description::DescriptionErrorKind),
}

/// A request the robot cannot carry out.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum RobotError {
    /// No elbow-up pose with every joint inside its limits puts the camera there.
    #[error("camera position ({x_cm:.2}, {y_cm:.2}, {z_cm:.2}) cm is unreachable: {why}")]
    Unreachable {
        /// Target x (cm).
        x_cm: f64,
        /// Target y (cm).
        y_cm: f64,
        /// Target z (cm).
        z_cm: f64,
        /// Why no pose was found.
        why: String,
    },
    /// A pose outside the joint limits or with non-finite angles.
    #[error("joint {joint} angle {angle_deg:.3}° is outside its limits [{lower_deg:.3}°, {upper_deg:.3}°]")]
    OutsideLimits {
        /// 1-based joint number.
        joint: usize,
        /// The requested angle (degrees).
        angle_deg: f64,
        /// Lower limit (degrees).
        lower_deg: f64,
        /// Upper limit (degrees).
        upper_deg: f64,
    },
    /// No wrist angles keep the camera looking straight down with its image x axis radial.
    #[error("no wrist pose keeps the camera looking down at learned angles ({:.3}°, {:.3}°, {:.3}°)", .theta_deg[0], .theta_deg[1], .theta_deg[2])]
    NoWristSolution {
        /// The learned angles (degrees).
        theta_deg: [f64; 3],
    },
    /// A chain with more joints than an arm model holds, or a learned joint not in it.
    #[error("a chain of {joints} joints with three learned ones among them: an arm may have at most {max}")]
    ChainTooLong {
        /// Joints in the chain.
        joints: usize,
        /// The most an arm model holds.
        max: usize,
    },
    /// Only links 1, 2 and 3 can be stretched.
    #[error("link {0} cannot be stretched: only links 1, 2 and 3 can")]
    NoSuchLink(usize),
    /// A stretch that would leave a link with no length.
    #[error("stretching link {link} by {delta_cm} cm leaves it {length_cm:.2} cm long")]
    LinkTooShort {
        /// The link.
        link: usize,
        /// The requested change (cm).
        delta_cm: f64,
        /// The length it would have (cm).
        length_cm: f64,
    },
    /// A pose whose weight needs more torque at a joint than the joint's URDF effort.
    #[error("joint {joint} cannot hold the arm there: its weight needs {torque_nm:.3} N·m, the joint's effort is {effort_nm} N·m")]
    CannotHold {
        /// 1-based joint number.
        joint: usize,
        /// The torque the weight needs (N·m).
        torque_nm: f64,
        /// The joint's URDF effort (N·m).
        effort_nm: f64,
    },
    /// A pose that puts a link inside an obstacle box.
    #[error("link {link} would stand inside obstacle {obstacle}")]
    InsideObstacle {
        /// The link (1–6; 6 carries the camera).
        link: usize,
        /// The obstacle (1-based, in the config's order).
        obstacle: usize,
    },
}
