//! Events that change the robot during a run: a camera turn or a link stretch at a trial.

use crate::experiment::Config;
use crate::robot::{RobotError, Simulator};
use crate::units::M_PER_CM;
use std::fmt;
use std::str::FromStr;

/// A change applied to the robot just before a trial.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Event {
    /// The camera turns about its optical axis.
    Rotate {
        /// The trial before which it happens (1-based).
        trial: usize,
        /// Degrees turned.
        degrees: f64,
    },
    /// A link is stretched (positive) or shortened.
    Elongate {
        /// The trial before which it happens (1-based).
        trial: usize,
        /// Link 1, 2 or 3.
        link: usize,
        /// Signed change of length (cm).
        cm: f64,
    },
}

/// A malformed `--event` value.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("bad event `{text}`: {reason} (expected rotate:TRIAL:DEG or elongate:TRIAL:LINK:CM)")]
pub struct EventError {
    /// The text given.
    pub text: String,
    /// What is wrong with it.
    pub reason: String,
}

impl Event {
    /// The trial before which the event happens.
    pub fn trial(&self) -> usize {
        match *self {
            Event::Rotate { trial, .. } | Event::Elongate { trial, .. } => trial,
        }
    }

    /// Every event of a run: the config's and `extra` (the command line's), in trial
    /// order.
    pub fn of_run(config: &Config, extra: &[Event]) -> Vec<Event> {
        let mut events = Event::from_config(config);
        events.extend(extra.iter().copied());
        events.sort_by_key(Event::trial);
        events
    }

    /// The events a config asks for (`rotate_trial`, `elongate_trial`; 0 means none).
    pub fn from_config(config: &Config) -> Vec<Event> {
        let mut events = Vec::new();
        if config.rotate_trial > 0 {
            events.push(Event::Rotate {
                trial: config.rotate_trial,
                degrees: config.rotate_degrees,
            });
        }
        if config.elongate_trial > 0 {
            events.push(Event::Elongate {
                trial: config.elongate_trial,
                link: config.elongate_link,
                cm: config.elongate_cm,
            });
        }
        events
    }

    /// Applies the event to the simulated robot.
    pub fn apply(&self, sim: &mut dyn Simulator) -> Result<(), RobotError> {
        match *self {
            Event::Rotate { degrees, .. } => {
                sim.rotate_camera(degrees.to_radians());
                Ok(())
            }
            Event::Elongate { link, cm, .. } => sim.stretch_link(link, cm * M_PER_CM),
        }
    }
}

impl fmt::Display for Event {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            Event::Rotate { trial, degrees } => write!(f, "rotate:{trial}:{degrees}"),
            Event::Elongate { trial, link, cm } => write!(f, "elongate:{trial}:{link}:{cm}"),
        }
    }
}

/// The largest camera turn an event may make (degrees), as `rotate_degrees` allows.
const MAX_TURN_DEG: f64 = 360.0;
/// The largest change of a link's length an event may make (cm), as `elongate_cm` allows.
const MAX_STRETCH_CM: f64 = 1000.0;

impl FromStr for Event {
    type Err = EventError;

    fn from_str(text: &str) -> Result<Self, Self::Err> {
        let fail = |reason: &str| EventError {
            text: text.to_string(),
            reason: reason.to_string(),
        };
        let parts: Vec<&str> = text.split(':').collect();
        let trial = |s: &str| match s.parse::<usize>() {
            Ok(t) if t >= 1 => Ok(t),
            _ => Err(fail("TRIAL must be an integer ≥ 1")),
        };
        // The bounds of the config's rotate_degrees and elongate_cm.
        let real = |s: &str, what: &str, bound: f64| match s.parse::<f64>() {
            Ok(v) if v.abs() <= bound => Ok(v),
            _ => Err(fail(&format!(
                "{what} must be a number from -{bound} to {bound}"
            ))),
        };
        match parts.as_slice() {
            ["rotate", t, deg] => Ok(Event::Rotate {
                trial: trial(t)?,
                degrees: real(deg, "DEG", MAX_TURN_DEG)?,
            }),
            ["elongate", t, link, cm] => {
                let link = match link.parse::<usize>() {
                    Ok(l @ 1..=3) => l,
                    _ => return Err(fail("LINK must be 1, 2 or 3")),
                };
                Ok(Event::Elongate {
                    trial: trial(t)?,
                    link,
                    cm: real(cm, "CM", MAX_STRETCH_CM)?,
                })
            }
            _ => Err(fail("unknown form")),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn events_parse_and_print_back() {
        for text in ["rotate:1500:90", "elongate:1500:2:-10", "rotate:3:-30.5"] {
            let event: Event = text.parse().unwrap();
            assert_eq!(event.to_string(), text);
        }
        assert_eq!(
            "elongate:7:1:2.5".parse::<Event>().unwrap(),
            Event::Elongate {
                trial: 7,
                link: 1,
                cm: 2.5
            }
        );
    }

    #[test]
    fn bad_events_say_why() {
        for (text, why) in [
            ("rotate:0:90", "TRIAL"),
            ("rotate:10:x", "DEG"),
            ("elongate:10:4:10", "LINK"),
            ("elongate:10:2:nan", "CM"),
            ("spin:10:2", "unknown form"),
        ] {
            let err = text.parse::<Event>().unwrap_err();
            assert!(err.to_string().contains(why), "{text}: {err}");
        }
    }
}
