//! Errors of the robot model and the simulators.

/// A URDF that cannot be the OSCAR-6: the message names the element at fault.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("{file}: {reason}")]
pub struct UrdfError {
    /// The URDF file as the user named it.
    pub file: String,
    /// What is wrong, naming the link or joint.
    pub reason: String,
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
}
