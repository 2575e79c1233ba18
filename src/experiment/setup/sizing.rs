//! The camera's entries that follow an arm's scale, sized to a fitted reach space where the
//! config left them at the study's defaults: the standoff and cz's boundaries.

use crate::camera::CameraModel;
use crate::experiment::{Config, PreflightError, ReachSetting, Source, Sources};
use crate::robot::ReachSpace;
use crate::units::M_PER_CM;

/// The smallest standoff (cm) sized to an arm. The nearer the camera, the more of a low
/// space's starts see the object much nearer than the standoff, where a young learner's
/// first move overshoots (a pixel there is a smaller move) and loses it: at 15 cm the SO-100
/// and the Z1 failed about 1.5 times the trials they fail at 20 cm; at 17 cm the SO-100 and
/// the UR3 fail as many, and still learn finer (docs/ARMS.md).
pub const MIN_SIZED_STANDOFF_CM: f64 = 17.0;

/// The reach space's height (cm) from which an arm keeps the study's 20 cm standoff. The
/// arms measured with higher spaces (the Panda, the xArm7, the UR5, 37 to 42 cm) learned
/// barely finer at 14 to 16 cm and failed 1.8 to 2.9 times as many trials.
pub const FULL_STANDOFF_HEIGHT_CM: f64 = 36.0;

/// The standoff (cm) for a camera over `space`, fitted to an arm: the study's 20 cm over a
/// space at least [`FULL_STANDOFF_HEIGHT_CM`] high, over a lower one in proportion to its
/// height, at least [`MIN_SIZED_STANDOFF_CM`]; to the millimetre.
pub fn sized_standoff_cm(space: &ReachSpace) -> f64 {
    let study = CameraModel::default().standoff / M_PER_CM;
    let share = height(space) / (FULL_STANDOFF_HEIGHT_CM * M_PER_CM);
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

/// cz's boundaries (the reading from the blob's area) sized to `reach` where the config left
/// both at their defaults (the OSCAR-6's), the config checked again. cz is 100·(d/s − 1) for
/// a camera d above the object and the standoff s, so over a reach space it climbs to about
/// 100 times the space's height over the standoff: the study's upper bound is scaled by that
/// over the study's (52 cm over 20 cm). Below the study's standoff the lower bound is scaled
/// with it, keeping the target's reading, 0, a third of the way up the range, where the
/// study puts it (`lin5`'s module says why); at the study's standoff it keeps the study's
/// −150, which the arms measured there failed fewer trials with (docs/ARMS.md).
pub fn size_readings_to_arm(
    config: &mut Config,
    sources: &mut Sources,
    reach: &ReachSpace,
) -> Result<(), PreflightError> {
    let at_default = |name: &&str| config.source_of(name, sources) == Source::Default;
    if !["boundary_4_low", "boundary_4_high"].iter().all(at_default) {
        return Ok(());
    }
    let study_standoff = CameraModel::default().standoff;
    let study = height(&ReachSpace::OSCAR6) / study_standoff;
    let share = height(reach) / (config.standoff * M_PER_CM) / study;
    let high = (config.boundary_4_high * share).round();
    if config.standoff * M_PER_CM < study_standoff {
        config.boundary_4_low = config.boundary_4_low * high / config.boundary_4_high;
        sources.record("boundary_4_low", Source::Fitted);
    }
    config.boundary_4_high = high;
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
        // 32.4 cm high: nine tenths of 36, so nine tenths of the study's 20 cm.
        assert_eq!(sized_standoff_cm(&space(0.10, 0.424)), 18.0);
        // 34.1 cm high: 18.9 cm, to the millimetre.
        assert_eq!(sized_standoff_cm(&space(0.03, 0.371)), 18.9);
        // Lower than 30.6 cm: the smallest standoff; 36 cm or higher: the study's.
        assert_eq!(
            sized_standoff_cm(&space(0.083, 0.223)),
            MIN_SIZED_STANDOFF_CM
        );
        assert_eq!(sized_standoff_cm(&space(0.02, 0.389)), 20.0);
        assert_eq!(sized_standoff_cm(&space(0.02, 0.441)), 20.0);
    }

    #[test]
    fn the_standoff_is_sized_only_when_left_at_its_default_over_a_fitted_space() {
        let reach = space(0.10, 0.424);
        let mut config = Config::default_config();
        let mut sources = Sources::default();
        size_standoff_to_arm(&mut config, &mut sources, &reach).unwrap();
        assert_eq!(
            config.standoff, 20.0,
            "a given reach space keeps the study's"
        );
        config.reach_space = ReachSetting::Auto;
        size_standoff_to_arm(&mut config, &mut sources, &reach).unwrap();
        assert_eq!(config.standoff, 18.0);
        assert_eq!(config.source_of("standoff", &sources), Source::Fitted);
        let mut given = Config::default_config();
        given.reach_space = ReachSetting::Auto;
        given.standoff = 12.0;
        size_standoff_to_arm(&mut given, &mut Sources::default(), &reach).unwrap();
        assert_eq!(given.standoff, 12.0, "the config's own is kept");
    }

    #[test]
    fn cz_keeps_the_study_bounds_when_the_standoff_keeps_its_proportion() {
        let mut config = Config::default_config();
        let study = (config.boundary_4_low, config.boundary_4_high);
        config.standoff = 15.0;
        size_readings_to_arm(&mut config, &mut Sources::default(), &space(0.10, 0.49)).unwrap();
        assert_eq!((config.boundary_4_low, config.boundary_4_high), study);
    }

    #[test]
    fn below_the_study_standoff_cz_bounds_scale_together_keeping_the_target_a_third_up() {
        let mut config = Config::default_config();
        let (low, high) = (config.boundary_4_low, config.boundary_4_high);
        let mut sources = Sources::default();
        // 26 cm under 15 cm: two thirds of the study's 52 cm under 20 cm.
        config.standoff = 15.0;
        size_readings_to_arm(&mut config, &mut sources, &space(0.03, 0.29)).unwrap();
        assert_eq!(config.boundary_4_high, 200.0);
        assert_eq!(config.boundary_4_low, -100.0);
        let third = -config.boundary_4_low / (config.boundary_4_high - config.boundary_4_low);
        assert!((third - 1.0 / 3.0).abs() < 1e-12, "{third}");
        assert_eq!(config.source_of("boundary_4_low", &sources), Source::Fitted);
        // At the study's standoff only the upper end follows the height.
        let mut study = Config::default_config();
        let mut sources = Sources::default();
        size_readings_to_arm(&mut study, &mut sources, &space(0.03, 0.29)).unwrap();
        assert_eq!((study.boundary_4_low, study.boundary_4_high), (low, 150.0));
        assert_eq!(study.source_of("boundary_4_low", &sources), Source::Default);
        assert_eq!(study.source_of("boundary_4_high", &sources), Source::Fitted);
        // A given bound keeps both.
        let mut given = Config::default_config();
        given.standoff = 15.0;
        given.boundary_4_low = -100.0;
        size_readings_to_arm(&mut given, &mut Sources::default(), &space(0.03, 0.29)).unwrap();
        assert_eq!(
            (given.boundary_4_low, given.boundary_4_high),
            (-100.0, high)
        );
    }
}
