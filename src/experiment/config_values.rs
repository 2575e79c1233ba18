//! Typed values of config entries: how each kind is parsed and written back.

use super::config::ValueError;
use crate::control::ServoMode;
use crate::learn::{MergeStrategy, Method};
use std::fmt;
use std::str::FromStr;

/// A value a config entry can hold.
pub(crate) trait ConfigValue: Sized {
    /// Parses the text after the entry's name; the error says why it is not a value.
    fn parse_value(raw: &str) -> Result<Self, ValueError>;
    /// The value as it is written in a config file.
    fn render(&self) -> String;
}

fn parse_integer<T: FromStr>(raw: &str, min: i64, max: u64) -> Result<T, ValueError> {
    raw.parse().map_err(|_| {
        let digits = raw.strip_prefix(['-', '+']).unwrap_or(raw);
        if !digits.is_empty() && digits.bytes().all(|b| b.is_ascii_digit()) {
            ValueError::IntegerOutOfRange {
                text: raw.to_string(),
                min,
                max,
            }
        } else if raw.parse::<f64>().is_ok() {
            ValueError::RealForInteger(raw.to_string())
        } else {
            ValueError::NotInteger(raw.to_string())
        }
    })
}

macro_rules! integer_value {
    ($($t:ty),*) => {$(
        impl ConfigValue for $t {
            fn parse_value(raw: &str) -> Result<Self, ValueError> {
                parse_integer(raw, <$t>::MIN as i64, <$t>::MAX as u64)
            }
            fn render(&self) -> String {
                self.to_string()
            }
        }
    )*};
}
integer_value!(usize, u64, i64);

impl ConfigValue for f64 {
    fn parse_value(raw: &str) -> Result<Self, ValueError> {
        match raw.parse::<f64>() {
            Ok(v) if v.is_finite() => Ok(v),
            _ => Err(ValueError::NotFiniteReal(raw.to_string())),
        }
    }
    fn render(&self) -> String {
        format!("{self:?}")
    }
}

macro_rules! named_value {
    ($($t:ty),*) => {$(
        impl ConfigValue for $t {
            fn parse_value(raw: &str) -> Result<Self, ValueError> {
                raw.parse().map_err(ValueError::UnknownChoice)
            }
            fn render(&self) -> String {
                self.to_string()
            }
        }
    )*};
}
named_value!(Method, SimKind, CameraKind, MergeStrategy, ServoMode);

/// Which simulator moves the arm.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum SimKind {
    /// Forward kinematics straight from the URDF, no dynamics.
    Kinematic,
    /// The URDF as a Rapier multibody with motors and gravity.
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
choice_names!(ServoMode, "servo mode", Step => "step", Continuous => "continuous");

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_real_number_for_an_integer_says_so() {
        assert_eq!(
            usize::parse_value("2.5"),
            Err(ValueError::RealForInteger("2.5".into()))
        );
        assert!(matches!(
            usize::parse_value("-3"),
            Err(ValueError::IntegerOutOfRange { min: 0, .. })
        ));
        assert!(matches!(
            u64::parse_value("99999999999999999999999999999999999999999"),
            Err(ValueError::IntegerOutOfRange { .. })
        ));
        assert_eq!(
            usize::parse_value("x"),
            Err(ValueError::NotInteger("x".into()))
        );
        assert_eq!(i64::parse_value("-3"), Ok(-3));
        assert_eq!(usize::parse_value("42"), Ok(42));
    }

    #[test]
    fn reals_round_trip_and_reject_nan() {
        for v in [0.05, 1e-5, -200.0, 3.0] {
            assert_eq!(f64::parse_value(&v.render()), Ok(v));
        }
        assert!(f64::parse_value("nan").is_err());
        assert!(f64::parse_value("inf").is_err());
    }

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
