//! Typed values of config entries: how each kind is parsed and written back.

use super::ValueError;
use crate::control::ServoMode;
use crate::learn::change::ChangeRecovery;
use crate::learn::{BroydenUpdate, MergeStrategy, Method};
use crate::robot::{BaseLink, CameraLink, Engine, LearnedJoints};
use std::fmt;
use std::str::FromStr;

/// A value a config entry can hold.
pub(crate) trait ConfigValue: Sized {
    /// The kind of value, in words, for the docs ("integer", "real", "x,y,z", …).
    const KIND: &'static str;
    /// Parses the text after the entry's name; the error says why it is not a value.
    fn parse_value(raw: &str) -> Result<Self, ValueError>;
    /// The value as it is written in a config file.
    fn render(&self) -> String;
    /// The value as a number, for the rule of a numeric entry; `None` for the others.
    fn number(&self) -> Option<f64> {
        None
    }
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
            const KIND: &'static str = "integer";
            fn parse_value(raw: &str) -> Result<Self, ValueError> {
                parse_integer(raw, <$t>::MIN as i64, <$t>::MAX as u64)
            }
            fn render(&self) -> String {
                self.to_string()
            }
            fn number(&self) -> Option<f64> {
                Some(*self as f64)
            }
        }
    )*};
}
integer_value!(usize, u64, i64);

impl ConfigValue for f64 {
    const KIND: &'static str = "real";
    fn parse_value(raw: &str) -> Result<Self, ValueError> {
        match raw.parse::<f64>() {
            Ok(v) if v.is_finite() => Ok(v),
            _ => Err(ValueError::NotFiniteReal(raw.to_string())),
        }
    }
    fn render(&self) -> String {
        format!("{self:?}")
    }
    fn number(&self) -> Option<f64> {
        Some(*self)
    }
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

/// `parts` comma-separated items of `raw`, each parsed by `item`; `expected` names the form.
fn list<T, const N: usize>(
    raw: &str,
    expected: &'static str,
    item: impl Fn(&str) -> Option<T>,
) -> Result<[T; N], ValueError> {
    let bad = || ValueError::BadList {
        text: raw.to_string(),
        expected,
    };
    let items: Vec<T> = raw
        .split(',')
        .map(|part| item(part.trim()).ok_or_else(bad))
        .collect::<Result<_, _>>()?;
    items.try_into().map_err(|_| bad())
}

fn finite(part: &str) -> Option<f64> {
    part.parse::<f64>().ok().filter(|v| v.is_finite())
}

fn name(part: &str) -> Option<String> {
    (!part.is_empty()).then(|| part.to_string())
}

/// A URDF link or joint name (one word).
impl ConfigValue for String {
    const KIND: &'static str = "name";
    fn parse_value(raw: &str) -> Result<Self, ValueError> {
        Ok(raw.to_string())
    }
    fn render(&self) -> String {
        self.clone()
    }
}

/// Three reals `x,y,z`.
impl ConfigValue for [f64; 3] {
    const KIND: &'static str = "x,y,z";
    fn parse_value(raw: &str) -> Result<Self, ValueError> {
        list(raw, "three real numbers x,y,z", finite)
    }
    fn render(&self) -> String {
        self.map(|v| format!("{v:?}")).join(",")
    }
}

/// Five reals `a,b,c,d,e` (one per learner input).
impl ConfigValue for [f64; 5] {
    const KIND: &'static str = "a,b,c,d,e";
    fn parse_value(raw: &str) -> Result<Self, ValueError> {
        list(raw, "five real numbers a,b,c,d,e", finite)
    }
    fn render(&self) -> String {
        self.map(|v| format!("{v:?}")).join(",")
    }
}

/// The camera's pose on its link: `x,y,z,roll,pitch,yaw`.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct CameraMount {
    /// The camera centre's offset from the camera link's origin, in its frame (m).
    pub offset_m: [f64; 3],
    /// The camera's turn: roll, pitch and yaw about the link's x, y and z axes, in that
    /// order (as a URDF origin's rpy, in degrees).
    pub rpy_deg: [f64; 3],
}

impl CameraMount {
    /// The turn as a quaternion.
    pub fn turn(&self) -> nalgebra::UnitQuaternion<f64> {
        let [roll, pitch, yaw] = self.rpy_deg.map(f64::to_radians);
        nalgebra::UnitQuaternion::from_euler_angles(roll, pitch, yaw)
    }
}

impl ConfigValue for CameraMount {
    const KIND: &'static str = "x,y,z,roll,pitch,yaw";
    fn parse_value(raw: &str) -> Result<Self, ValueError> {
        let [x, y, z, roll, pitch, yaw] =
            list(raw, "six real numbers x,y,z,roll,pitch,yaw", finite)?;
        Ok(CameraMount {
            offset_m: [x, y, z],
            rpy_deg: [roll, pitch, yaw],
        })
    }
    fn render(&self) -> String {
        let [x, y, z] = self.offset_m;
        let [roll, pitch, yaw] = self.rpy_deg;
        [x, y, z, roll, pitch, yaw]
            .map(|v| format!("{v:?}"))
            .join(",")
    }
}

/// `root`, or a link's name.
impl ConfigValue for BaseLink {
    const KIND: &'static str = "root or a link";
    fn parse_value(raw: &str) -> Result<Self, ValueError> {
        Ok(match raw {
            "root" => BaseLink::Root,
            name => BaseLink::Named(name.to_string()),
        })
    }
    fn render(&self) -> String {
        match self {
            BaseLink::Root => "root".to_string(),
            BaseLink::Named(name) => name.clone(),
        }
    }
}

/// `auto`, or a link's name.
impl ConfigValue for CameraLink {
    const KIND: &'static str = "auto or a link";
    fn parse_value(raw: &str) -> Result<Self, ValueError> {
        Ok(match raw {
            "auto" => CameraLink::Auto,
            name => CameraLink::Named(name.to_string()),
        })
    }
    fn render(&self) -> String {
        match self {
            CameraLink::Auto => "auto".to_string(),
            CameraLink::Named(name) => name.clone(),
        }
    }
}

/// `auto`, or three joint names `a,b,c`.
impl ConfigValue for LearnedJoints {
    const KIND: &'static str = "auto or a,b,c";
    fn parse_value(raw: &str) -> Result<Self, ValueError> {
        if raw == "auto" {
            return Ok(LearnedJoints::Auto);
        }
        list(raw, "`auto` or three joint names a,b,c", name).map(LearnedJoints::Named)
    }
    fn render(&self) -> String {
        match self {
            LearnedJoints::Auto => "auto".to_string(),
            LearnedJoints::Named(names) => names.join(","),
        }
    }
}

/// The reach space: fitted to the arm, or given.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum ReachSetting {
    /// The study's shape scaled to what the arm reaches with the camera looking down.
    Auto,
    /// r_min, r_max, z_min, z_max (cm).
    Given([f64; 4]),
}

impl ConfigValue for ReachSetting {
    const KIND: &'static str = "auto or r_min,r_max,z_min,z_max";
    fn parse_value(raw: &str) -> Result<Self, ValueError> {
        if raw == "auto" {
            return Ok(ReachSetting::Auto);
        }
        list(
            raw,
            "`auto` or four real numbers r_min,r_max,z_min,z_max (cm)",
            finite,
        )
        .map(ReachSetting::Given)
    }
    fn render(&self) -> String {
        match self {
            ReachSetting::Auto => "auto".to_string(),
            ReachSetting::Given(values) => values.map(|v| format!("{v:?}")).join(","),
        }
    }
}

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

/// An `obstacle` line: a box standing in the world, sides along the axes.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ObstacleBox {
    /// The box's centre (cm, world frame).
    pub centre_cm: [f64; 3],
    /// Its side lengths along x, y and z (cm), each above zero.
    pub size_cm: [f64; 3],
}

/// The farthest an obstacle's centre may lie from the world's origin on an axis (cm): 100 m.
pub(super) const OBSTACLE_REACH_CM: f64 = 1e4;
/// The thinnest and the longest side of an obstacle (cm): 0.1 mm and 100 m.
pub(super) const OBSTACLE_SIDE_CM: (f64, f64) = (0.01, 1e4);

impl ObstacleBox {
    /// `[x, y, z, sx, sy, sz]`: its centre and side lengths (cm), as the config line and
    /// `summary.json` give them.
    pub fn centre_and_size(&self) -> [f64; 6] {
        let ([x, y, z], [sx, sy, sz]) = (self.centre_cm, self.size_cm);
        [x, y, z, sx, sy, sz]
    }

    /// The box in the simulators' units (m).
    pub fn obstacle(&self) -> crate::robot::Obstacle {
        let m = |v: [f64; 3]| nalgebra::Vector3::from(v) * crate::units::M_PER_CM;
        crate::robot::Obstacle {
            centre: m(self.centre_cm).into(),
            size: m(self.size_cm),
        }
    }
}

impl ConfigValue for ObstacleBox {
    const KIND: &'static str = "x,y,z,sx,sy,sz";
    fn parse_value(raw: &str) -> Result<Self, ValueError> {
        let bad = |reason: &str| ValueError::NotObstacle {
            text: raw.to_string(),
            reason: reason.to_string(),
        };
        let parts: Vec<&str> = raw.split(',').collect();
        if parts.len() != 6 {
            return Err(bad(&format!("{} numbers, not 6", parts.len())));
        }
        let mut values = [0.0; 6];
        for (value, part) in values.iter_mut().zip(&parts) {
            *value = f64::parse_value(part.trim())
                .map_err(|_| bad(&format!("`{part}` is not a finite number")))?;
        }
        let (centre, size) = values.split_at(3);
        if size.iter().any(|&side| side <= 0.0) {
            return Err(bad("every side must be above 0"));
        }
        if centre.iter().any(|c| c.abs() > OBSTACLE_REACH_CM) {
            return Err(bad(&format!(
                "its centre must be within {OBSTACLE_REACH_CM} cm of the world's origin on each axis"
            )));
        }
        if size
            .iter()
            .any(|side| !(OBSTACLE_SIDE_CM.0..=OBSTACLE_SIDE_CM.1).contains(side))
        {
            return Err(bad(&format!(
                "every side must be from {} to {} cm",
                OBSTACLE_SIDE_CM.0, OBSTACLE_SIDE_CM.1
            )));
        }
        Ok(ObstacleBox {
            centre_cm: [centre[0], centre[1], centre[2]],
            size_cm: [size[0], size[1], size[2]],
        })
    }

    fn render(&self) -> String {
        let all: Vec<String> = self
            .centre_cm
            .iter()
            .chain(&self.size_cm)
            .map(f64::render)
            .collect();
        all.join(",")
    }
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
choice_names!(ChangeRecovery, "change recovery", Correct => "correct", Forget => "forget");
choice_names!(BroydenUpdate, "broyden update", Broyden => "broyden", Rls => "rls");
choice_names!(ServoMode, "servo mode", Step => "step", Continuous => "continuous");
choice_names!(Engine, "engine", Rk4 => "rk4", Rapier => "rapier");

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
    fn obstacles_round_trip_and_need_six_numbers_and_positive_sides() {
        let box_ = ObstacleBox::parse_value("60,-10.5,0,20,20,40").unwrap();
        assert_eq!(box_.size_cm, [20.0, 20.0, 40.0]);
        assert_eq!(ObstacleBox::parse_value(&box_.render()), Ok(box_));
        for bad in [
            "1,2,3,4,5",
            "1,2,3,4,5,0",
            "1,2,3,4,-5,6",
            "1,2,x,4,5,6",
            "1,2,3,4,5,nan",
        ] {
            assert!(
                matches!(
                    ObstacleBox::parse_value(bad),
                    Err(ValueError::NotObstacle { .. })
                ),
                "{bad}"
            );
        }
    }

    #[test]
    fn lists_parse_their_items_and_say_what_they_take() {
        assert_eq!(<[f64; 3]>::parse_value("1,-2.5, 3"), Ok([1.0, -2.5, 3.0]));
        assert!(matches!(
            <[f64; 3]>::parse_value("1,2"),
            Err(ValueError::BadList { .. })
        ));
        let names = LearnedJoints::parse_value("a,b,c").unwrap();
        assert_eq!(names.render(), "a,b,c");
        assert!(LearnedJoints::parse_value("a,,c").is_err());
        assert_eq!(LearnedJoints::parse_value("auto"), Ok(LearnedJoints::Auto));
        assert_eq!(CameraLink::parse_value("auto"), Ok(CameraLink::Auto));
        assert_eq!(ReachSetting::parse_value("auto"), Ok(ReachSetting::Auto));
        let given = ReachSetting::parse_value("46,93,0,52").unwrap();
        assert_eq!(ReachSetting::parse_value(&given.render()), Ok(given));
        assert!(ReachSetting::parse_value("46,93,nan,52").is_err());
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
