//! Errors of the robot model and the simulators, as data: kinds with the names and numbers
//! of the elements at fault.

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
    /// A pose whose weight needs more torque at a joint than the joint's URDF effort: its
    /// motor is too weak to hold the arm there.
    #[error("joint {joint}'s motor is too weak to hold the arm there: its weight needs {torque_nm:.3} N·m, the joint's effort is {effort_nm} N·m")]
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
