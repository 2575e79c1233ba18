//! The config's named choices (`sim`, `camera`, `method`, …): their names, parsed and
//! written back.

use super::ConfigValue;
use crate::control::ServoMode;
use crate::experiment::config::ValueError;
use crate::learn::change::ChangeRecovery;
use crate::learn::{BroydenUpdate, MergeStrategy, Method};
use crate::robot::Engine;
use std::fmt;
use std::str::FromStr;

/// Which simulator moves the arm.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum SimKind {
    /// Forward kinematics straight from the URDF, no dynamics.
    Kinematic,
    /// The URDF as a multibody under gravity, its joints servoed, stepped by the `engine`.
    Dynamic,
}

/// How the camera produces its reading.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum CameraKind {
    /// Exact analytic projection of the sphere.
    Projection,
    /// Rays through every pixel against the object's collider.
    Raycast,
}

macro_rules! named_value {
    ($($t:ty),*) => {$(
        impl ConfigValue for $t {
            const KIND: &'static str = "choice";
            fn parse_value(raw: &str) -> Result<Self, ValueError> {
                raw.parse().map_err(ValueError::UnknownChoice)
            }
            fn render(&self) -> String {
                self.to_string()
            }
        }
    )*};
}
named_value!(
    Method,
    SimKind,
    CameraKind,
    MergeStrategy,
    ChangeRecovery,
    ServoMode,
    BroydenUpdate,
    Engine
);
macro_rules! choice_names {
    ($t:ty, $what:literal, $($variant:ident => $name:literal),*) => {
        impl fmt::Display for $t {
            fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
                f.write_str(match self { $(Self::$variant => $name),* })
            }
        }
        impl FromStr for $t {
            type Err = String;
            fn from_str(s: &str) -> Result<Self, String> {
                match s {
                    $($name => Ok(Self::$variant),)*
                    _ => Err(format!(
                        concat!("unknown ", $what, " `{}` (expected one of {})"),
                        s,
                        [$($name),*].join(", ")
                    )),
                }
            }
        }
    };
}
choice_names!(SimKind, "simulator", Kinematic => "kinematic", Dynamic => "dynamic");
choice_names!(CameraKind, "camera", Projection => "projection", Raycast => "raycast");
choice_names!(MergeStrategy, "merge strategy", Thesis => "thesis", ChangeDetection => "change_detection");
choice_names!(ChangeRecovery, "change recovery", Correct => "correct", Forget => "forget");
choice_names!(BroydenUpdate, "broyden update", Broyden => "broyden", Rls => "rls");
choice_names!(ServoMode, "servo mode", Step => "step", Continuous => "continuous");
choice_names!(Engine, "engine", Rk4 => "rk4", Rapier => "rapier");

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn choices_parse_their_names_only() {
        assert_eq!("dynamic".parse::<SimKind>(), Ok(SimKind::Dynamic));
        assert_eq!(CameraKind::Raycast.render(), "raycast");
        assert!("Projection"
            .parse::<CameraKind>()
            .unwrap_err()
            .contains("projection, raycast"));
        assert!(matches!(
            CameraKind::parse_value("x"),
            Err(ValueError::UnknownChoice(_))
        ));
    }
}
