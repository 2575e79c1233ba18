//! The arm a config describes: its URDF read as a robot description, the arm settings, and
//! the reach space (given, or fitted to the arm).

use crate::camera::CameraModel;
use crate::experiment::setup::camera_model;
use crate::experiment::{Config, ReachSetting};
use crate::robot::description::{
    camera_choice, mesh_candidates, DescriptionError, DescriptionErrorKind as Kind,
    DescriptionOptions, DescriptionWarning, RobotDescription,
};
use crate::robot::{
    ArmModel, ArmSettings, CameraLink, ReachFit, ReachFitFailure, ReachSpace, DEFAULT_URDF,
    DEFAULT_URDF_NAME,
};
use crate::units::M_PER_CM;
use nalgebra::Vector3;
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;
use std::path::{Path, PathBuf};

/// The arm settings from `base_link`, `camera_link`, `camera_offset` (cm), `camera_mount`
/// and `learned_joints`.
pub fn arm_settings(config: &Config) -> ArmSettings {
    ArmSettings {
        base_link: config.base_link.clone(),
        camera_link: config.camera_link.clone(),
        camera_offset: Vector3::from(config.camera_offset) * M_PER_CM
            + Vector3::from(config.camera_mount.offset_m),
        camera_turn: config.camera_mount.turn(),
        learned_joints: config.learned_joints.clone(),
    }
}

/// An arm read from its URDF, with what the URDF was missing.
#[derive(Debug, Clone)]
pub struct LoadedArm {
    /// The arm the config's entries pick out of the URDF.
    pub model: ArmModel,
    /// What the URDF was missing and what stands in for it, in one line (the URDF, how
    /// many meshes, and the first one's link, file and the paths it was looked for at);
    /// empty when nothing was missing.
    pub warnings: Vec<String>,
    /// The camera link and why it is the one: `auto`'s reason, or the config naming it.
    pub camera: String,
}

/// The arm of `urdf` (else the config's `urdf`; the shipped OSCAR-6 without either) as
/// the config's arm entries pick it out of its robot description, `package://` meshes looked up in `package_paths`.
pub fn load_arm(config: &Config, urdf: Option<&Path>) -> Result<LoadedArm, DescriptionError> {
    let description = load_description(config, urdf)?;
    let urdf = urdf.or(config.urdf.path());
    let options = DescriptionOptions {
        package_paths: config.package_paths.0.clone(),
    };
    let settings = arm_settings(config);
    let model = ArmModel::from_description(&description, &settings)?;
    let camera = match &config.camera_link {
        CameraLink::Auto => {
            let choice = camera_choice(&description, settings.base(&description)?);
            let name = &description.links[choice.link].name;
            format!("`{name}` (camera_link auto: {})", choice.reason)
        }
        CameraLink::Named(name) => format!("`{name}` (the config's camera_link)"),
    };
    let folder = urdf.and_then(Path::parent).unwrap_or(Path::new("."));
    let file = &description.file;
    let warnings = match description.warnings.as_slice() {
        [] => Vec::new(),
        [first, rest @ ..] => {
            let first = warning_text(first, folder, &options.package_paths);
            vec![match rest {
                [] => format!("{file}: {first}"),
                _ => {
                    let counts = mesh_counts(&description.warnings);
                    format!("{file}: {counts}; the first: {first}")
                }
            }]
        }
    };
    Ok(LoadedArm {
        model,
        warnings,
        camera,
    })
}

/// The robot description of `urdf` (else the config's `urdf`; the shipped OSCAR-6 without
/// either), `package://` meshes looked up in the config's `package_paths`.
pub fn load_description(
    config: &Config,
    urdf: Option<&Path>,
) -> Result<RobotDescription, DescriptionError> {
    let options = DescriptionOptions {
        package_paths: config.package_paths.0.clone(),
    };
    match urdf.or(config.urdf.path()) {
        Some(path) => RobotDescription::load(path, &options),
        None => RobotDescription::parse(DEFAULT_URDF, DEFAULT_URDF_NAME, Path::new("."), &options),
    }
}

/// How many meshes a URDF's warnings are about, by what stands in for them: the head of
/// the one warning line a URDF with several missing meshes gets.
fn mesh_counts(warnings: &[DescriptionWarning]) -> String {
    let collisions = warnings
        .iter()
        .filter(|w| matches!(w, DescriptionWarning::MissingCollisionMesh { .. }))
        .count();
    let visuals = warnings.len() - collisions;
    format!(
        "{} meshes missing or unread ({collisions} collision meshes, replaced by capsules; \
         {visuals} visual meshes, left out of pictures)",
        warnings.len()
    )
}

/// A warning in words: what is missing, and for a mesh not found the paths it was looked
/// for at.
fn warning_text(
    warning: &DescriptionWarning,
    urdf_folder: &Path,
    package_paths: &[PathBuf],
) -> String {
    if matches!(warning, DescriptionWarning::UnreadVisualMesh { .. }) {
        return warning.to_string();
    }
    let tried: Vec<String> = mesh_candidates(warning.filename(), urdf_folder, package_paths)
        .iter()
        .map(|path| path.components().collect::<PathBuf>().display().to_string())
        .collect();
    if tried.is_empty() {
        format!("{warning}; no package_paths to look in")
    } else {
        format!("{warning}; looked for {}", tried.join(", "))
    }
}

/// The config entry an error reading the arm is about (`camera_link` or
/// `learned_joints`), when it is about one.
pub fn arm_entry(error: &DescriptionError) -> Option<&'static str> {
    match error.kind {
        Kind::UnknownLink { .. } | Kind::NoMovingJoint { .. } | Kind::PrismaticOnChain { .. } => {
            Some("camera_link")
        }
        Kind::CannotLookDown { .. } => Some("camera_mount"),
        Kind::UnknownBaseLink { .. } | Kind::CameraNotBelowBase { .. } => Some("base_link"),
        Kind::UnknownJoint { .. }
        | Kind::LearnedJointFixed { .. }
        | Kind::LearnedJointOffChain { .. }
        | Kind::LearnedJointRepeated { .. }
        | Kind::NoBaseYaw
        | Kind::TooFewJointsToLearn { .. } => Some("learned_joints"),
        _ => None,
    }
}

/// The reach space `reach_space` gives (cm), or the one fitted to `model` for `auto`
/// (when nothing fits: why not), `model` then keeping to the branch it was fitted on.
pub fn reach_space(config: &Config, model: &mut ArmModel) -> Result<ReachSpace, ReachFitFailure> {
    match config.reach_space {
        ReachSetting::Given([r_min, r_max, z_min, z_max]) => Ok(ReachSpace {
            r_min: r_min / 100.0,
            r_max: r_max / 100.0,
            z_min: z_min / 100.0,
            z_max: z_max / 100.0,
        }),
        ReachSetting::Auto => fit_reach(config, model).map(|fit| fit.space),
    }
}

/// The reach space fitted to `model` above the config's floor, targets hanging the
/// sphere's radius and the config's standoff below the camera, or the study's where that
/// is larger: a standoff sized to the space afterwards
/// ([`sized_standoff_cm`](crate::experiment::setup::sized_standoff_cm)) is never
/// larger, so it never moves the space, and a run read back from its `info` fits the same
/// one. `model` keeps to the branch of its solutions the space was fitted on.
pub fn fit_reach(config: &Config, model: &mut ArmModel) -> Result<ReachFit, ReachFitFailure> {
    let study = CameraModel::default();
    let camera = camera_model(config);
    let below = camera
        .object_bottom_below()
        .max(study.object_bottom_below());
    let fit = ReachSpace::fit(model, config.floor_z * M_PER_CM, below)?;
    model.keep_branch(fit.branch.clone());
    Ok(fit)
}

/// How far the fitted boundaries of θ2 and θ3 reach beyond the angles met (degrees).
pub const BOUNDARY_MARGIN_DEG: f64 = 10.0;
/// Reach-space points sampled for the ranges of θ2 and θ3, and their seed.
const RANGE_SAMPLES: usize = 1000;
const RANGE_SEED: u64 = 1;

/// The range (degrees) of θ2 and θ3 over points sampled in `space` that the arm reaches
/// looking down; `None` when it reaches none.
pub fn learned_ranges(model: &ArmModel, space: &ReachSpace) -> Option<[(f64, f64); 2]> {
    let mut rng = ChaCha8Rng::seed_from_u64(RANGE_SEED);
    let mut ranges = [(f64::INFINITY, f64::NEG_INFINITY); 2];
    for _ in 0..RANGE_SAMPLES {
        if let Ok(theta) = model.solve_camera_position(&space.sample(&mut rng)) {
            for (range, angle) in ranges.iter_mut().zip([theta.y, theta.z]) {
                let degrees = angle.to_degrees();
                *range = (range.0.min(degrees), range.1.max(degrees));
            }
        }
    }
    ranges[0].0.is_finite().then_some(ranges)
}

/// `boundary_0` and `boundary_1` (θ2, θ3) fitted to the arm: the ranges it uses over
/// `space`, [`BOUNDARY_MARGIN_DEG`] to spare on each side, rounded to whole degrees.
pub fn fitted_boundaries(model: &ArmModel, space: &ReachSpace) -> Option<[(f64, f64); 2]> {
    learned_ranges(model, space).map(|ranges| {
        ranges.map(|(low, high)| {
            (
                (low - BOUNDARY_MARGIN_DEG).round(),
                (high + BOUNDARY_MARGIN_DEG).round(),
            )
        })
    })
}
