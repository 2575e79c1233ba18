//! An `obstacle` line's value: a box standing in the world, its centre and sides in cm.

use super::ConfigValue;
use crate::experiment::config::ValueError;

/// An `obstacle` line: a box standing in the world, sides along the axes.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ObstacleBox {
    /// The box's centre (cm, world frame).
    pub centre_cm: [f64; 3],
    /// Its side lengths along x, y and z (cm), each above zero.
    pub size_cm: [f64; 3],
}

/// The farthest an obstacle's centre may lie from the world's origin on an axis (cm): 100 m.
const OBSTACLE_REACH_CM: f64 = 1e4;
/// The thinnest and the longest side of an obstacle (cm): 0.1 mm and 100 m.
const OBSTACLE_SIDE_CM: (f64, f64) = (0.01, 1e4);

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

#[cfg(test)]
mod tests {
    use super::*;

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
}
