//! The camera's entries that follow an arm's scale, sized to a fitted reach space where the
//! config left them at the study's defaults: the standoff and cz's upper boundary.

use crate::camera::CameraModel;
use crate::experiment::{Config, PreflightError, ReachSetting, Source, Sources};
use crate::robot::ReachSpace;
use crate::units::M_PER_CM;

/// The smallest standoff (cm) sized to an arm: the ball's top (its radius, 2 cm, above its
/// centre) twice the camera's nearest sight (5 cm) below the camera at the target. Nearer,
/// a table-top arm's first moves lose the object more often (it leaves the narrower view,
/// or the gripper's jaw hides it), and at 6 cm the SO-100's pre-learning starts do not see it.
pub const MIN_SIZED_STANDOFF_CM: f64 = 12.0;

/// The standoff (cm) for a camera over `space`, fitted to an arm: the study's 20 cm in
/// proportion to the space's height (20 to its 52 cm), at least [`MIN_SIZED_STANDOFF_CM`],
/// at most the study's; to the millimetre.
pub fn sized_standoff_cm(space: &ReachSpace) -> f64 {
    let study = CameraModel::default().standoff / M_PER_CM;
    let share = height(space) / height(&ReachSpace::OSCAR6);
    let standoff = (study * share).clamp(MIN_SIZED_STANDOFF_CM, study);
    (standoff * 10.0).round() / 10.0
}

/// The height (m) of a reach space.
fn height(space: &ReachSpace) -> f64 {
    space.z_max - space.z_min
}

/// `standoff` sized to `reach` ([`sized_standoff_cm`]) where the config left it at its
/// default and the reach space is fitted (`reach_space auto`), recorded as fitted to the
/// arm; the config checked again.
pub fn size_standoff_to_arm(
    config: &mut Config,
    sources: &mut Sources,
    reach: &ReachSpace,
) -> Result<(), PreflightError> {
    let fitted = config.reach_space == ReachSetting::Auto;
    if !fitted || config.source_of("standoff", sources) != Source::Default {
        return Ok(());
    }
    config.standoff = sized_standoff_cm(reach);
    sources.record("standoff", Source::Fitted);
    Ok(config.check()?)
}

/// The upper boundary of cz (the reading from the blob's area) sized to `reach` where the
/// config left both of cz's boundaries at their defaults (the OSCAR-6's), the config
/// checked again. cz is 100·(d/s − 1) for a camera d above the object and the standoff s,
/// so over a reach space it spans about 100 times the space's height over the standoff:
/// the study's bound is scaled by that span over the study's (52 cm over 20 cm).
pub fn size_readings_to_arm(
    config: &mut Config,
    sources: &mut Sources,
    reach: &ReachSpace,
) -> Result<(), PreflightError> {
    let at_default = |name: &&str| config.source_of(name, sources) == Source::Default;
    if !["boundary_4_low", "boundary_4_high"].iter().all(at_default) {
        return Ok(());
    }
    let study = height(&ReachSpace::OSCAR6) / CameraModel::default().standoff;
    let share = height(reach) / (config.standoff * M_PER_CM) / study;
    config.boundary_4_high = (config.boundary_4_high * share).round();
    sources.record("boundary_4_high", Source::Fitted);
    Ok(config.check()?)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn space(z_min: f64, z_max: f64) -> ReachSpace {
        ReachSpace {
            r_min: 0.2,
            r_max: 0.4,
            z_min,
            z_max,
        }
    }

    #[test]
    fn the_study_space_keeps_the_study_standoff() {
        assert_eq!(sized_standoff_cm(&ReachSpace::OSCAR6), 20.0);
    }

    #[test]
    fn the_standoff_follows_the_height_between_its_bounds() {
        // 39 cm high: three quarters of the study's 52, so three quarters of its 20 cm.
        assert_eq!(sized_standoff_cm(&space(0.10, 0.49)), 15.0);
        // 42.4 cm high (the UR5's): 16.3 cm, to the millimetre.
        assert_eq!(sized_standoff_cm(&space(0.03, 0.454)), 16.3);
        // Lower than 31.2 cm: the smallest standoff; higher than 52: the study's.
        assert_eq!(
            sized_standoff_cm(&space(0.083, 0.223)),
            MIN_SIZED_STANDOFF_CM
        );
        assert_eq!(sized_standoff_cm(&space(0.02, 0.644)), 20.0);
    }

    #[test]
    fn the_standoff_is_sized_only_when_left_at_its_default_over_a_fitted_space() {
        let reach = space(0.10, 0.49);
        let mut config = Config::default_config();
        let mut sources = Sources::default();
        size_standoff_to_arm(&mut config, &mut sources, &reach).unwrap();
        assert_eq!(
            config.standoff, 20.0,
            "a given reach space keeps the study's"
        );
        config.reach_space = ReachSetting::Auto;
        size_standoff_to_arm(&mut config, &mut sources, &reach).unwrap();
        assert_eq!(config.standoff, 15.0);
        assert_eq!(config.source_of("standoff", &sources), Source::Fitted);
        let mut given = Config::default_config();
        given.reach_space = ReachSetting::Auto;
        given.standoff = 12.0;
        size_standoff_to_arm(&mut given, &mut Sources::default(), &reach).unwrap();
        assert_eq!(given.standoff, 12.0, "the config's own is kept");
    }

    #[test]
    fn cz_keeps_the_study_bound_when_the_standoff_keeps_its_proportion() {
        let mut config = Config::default_config();
        let study_bound = config.boundary_4_high;
        config.standoff = 15.0;
        size_readings_to_arm(&mut config, &mut Sources::default(), &space(0.10, 0.49)).unwrap();
        assert_eq!(config.boundary_4_high, study_bound);
        let mut config = Config::default_config();
        size_readings_to_arm(&mut config, &mut Sources::default(), &space(0.03, 0.29)).unwrap();
        assert_eq!(config.boundary_4_high, (study_bound / 2.0).round());
    }
}
