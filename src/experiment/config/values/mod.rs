//! Typed values of config entries: how each kind is parsed and written back. Numbers,
//! lists and names are here; `choices.rs` holds the named choices, `obstacle.rs` an
//! obstacle box.

mod choices;
mod obstacle;

pub use choices::{CameraKind, SimKind};
pub use obstacle::ObstacleBox;

use super::ValueError;
use crate::robot::{BaseLink, CameraLink, LearnedJoints};
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

/// Reals as a config file writes them: each exactly, comma-separated.
fn render_reals(values: &[f64]) -> String {
    let texts: Vec<String> = values.iter().map(|v| format!("{v:?}")).collect();
    texts.join(",")
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

/// A list of `N` reals, its kind written as the list's names (`x,y,z`), the error saying
/// what it takes.
macro_rules! reals_value {
    ($($n:literal: $kind:literal, $expected:literal);*) => {$(
        impl ConfigValue for [f64; $n] {
            const KIND: &'static str = $kind;
            fn parse_value(raw: &str) -> Result<Self, ValueError> {
                list(raw, $expected, finite)
            }
            fn render(&self) -> String {
                render_reals(self)
            }
        }
    )*};
}
// Three reals `x,y,z`; five `a,b,c,d,e` (one per learner input).
reals_value!(
    3: "x,y,z", "three real numbers x,y,z";
    5: "a,b,c,d,e", "five real numbers a,b,c,d,e"
);

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
        render_reals(&[x, y, z, roll, pitch, yaw])
    }
}

/// A link entry: a keyword for the one variant that names no link, or a link's name
/// (`Named`).
macro_rules! link_value {
    ($($t:ident: $keyword:literal => $variant:ident),*) => {$(
        impl ConfigValue for $t {
            const KIND: &'static str = concat!($keyword, " or a link");
            fn parse_value(raw: &str) -> Result<Self, ValueError> {
                Ok(match raw {
                    $keyword => $t::$variant,
                    name => $t::Named(name.to_string()),
                })
            }
            fn render(&self) -> String {
                match self {
                    $t::$variant => $keyword.to_string(),
                    $t::Named(name) => name.clone(),
                }
            }
        }
    )*};
}
// `root` or a link's name; `auto` or a link's name.
link_value!(BaseLink: "root" => Root, CameraLink: "auto" => Auto);

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
            ReachSetting::Given(values) => render_reals(values),
        }
    }
}

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
        assert_eq!(BaseLink::parse_value("root"), Ok(BaseLink::Root));
        let named = BaseLink::parse_value("base_link").unwrap();
        assert_eq!(
            (named.render(), BaseLink::KIND),
            ("base_link".into(), "root or a link")
        );
        assert_eq!(ReachSetting::parse_value("auto"), Ok(ReachSetting::Auto));
        let given = ReachSetting::parse_value("46,93,0,52").unwrap();
        assert_eq!(ReachSetting::parse_value(&given.render()), Ok(given));
        assert!(ReachSetting::parse_value("46,93,nan,52").is_err());
    }
}
