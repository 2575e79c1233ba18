//! `eyehand reach`: the reach space an arm works in, how much of what it reaches that is,
//! and the pre-learning pose.

use super::{bad_input, say, warned, Failure};
use crate::control::prelearning_moves;
use crate::experiment::setup::{
    camera_model, fit_reach, fitted_boundaries, learned_ranges, load_arm, proposed_mount,
    reach_space, refuses_where_it_looks, size_readings_to_arm, size_standoff_to_arm,
    BOUNDARY_MARGIN_DEG, FULL_STANDOFF_HEIGHT_CM, MIN_SIZED_STANDOFF_CM,
};
use crate::experiment::{
    contact_stopped_moves, fit_reach_space_to_arm, target_poses_in_contact, Config, PreflightError,
    ReachSetting, RunRequest, Source, Sources, REACH_SAMPLES,
};
use crate::robot::{ArmModel, ReachSpace, Wrist, CONTACT_MARGIN};
use crate::units::M_PER_CM;
use std::fmt::Write;
use std::path::PathBuf;

#[derive(Debug, clap::Args)]
pub(super) struct ReachArgs {
    /// The URDF (default: the shipped urdf/oscar6.urdf).
    #[arg(long)]
    urdf: Option<PathBuf>,
    #[command(flatten)]
    arm: ArmConfigArgs,
}

/// The config an arm is read with: a file and `--set`s.
#[derive(Debug, clap::Args)]
pub(super) struct ArmConfigArgs {
    /// The config whose arm entries (camera_link, camera_offset, learned_joints,
    /// reach_space, floor_z, standoff) apply (default: every entry at its default).
    #[arg(long)]
    config: Option<PathBuf>,
    /// Sets a config entry (repeatable), as `run --set` does.
    #[arg(long = "set", value_name = "NAME=VALUE")]
    sets: Vec<String>,
}

impl ArmConfigArgs {
    /// The config file (or the default) with every `--set` applied, checked.
    pub(super) fn config(&self) -> Result<Config, Failure> {
        self.sourced_config().map(|(config, _)| config)
    }

    /// [`config`](ArmConfigArgs::config), with where each value came from.
    fn sourced_config(&self) -> Result<(Config, Sources), Failure> {
        let request = RunRequest {
            config: self.config.clone(),
            sets: super::run::name_values(&self.sets)?,
            ..RunRequest::default()
        };
        request
            .sourced_config()
            .map(|(config, _, sources)| (config, sources))
            .map_err(bad_input)
    }
}

pub(super) fn reach(args: ReachArgs) -> Result<(), Failure> {
    let (mut config, mut sources) = args.arm.sourced_config()?;
    let own_arm = args.urdf.is_some() || config.urdf.path().is_some();
    if own_arm {
        fit_reach_space_to_arm(&mut config, &mut sources);
    }
    let urdf = args.urdf.as_deref();
    // A camera refused as its link's z axis points it: which other axis would do.
    let refused =
        |refusal: String, looks: bool| match proposed_mount(&config, urdf, &[], &sources, looks) {
            Some(Ok(other)) => bad_input(format!("{refusal}; {other}")),
            Some(Err(search)) => bad_input(format!("{refusal}; {search}")),
            None => bad_input(refusal),
        };
    let loaded =
        load_arm(&config, urdf).map_err(|e| refused(e.to_string(), refuses_where_it_looks(&e)))?;
    let camera = loaded.camera.clone();
    let mut model = warned(loaded);
    let mut report = arm_lines(&model);
    let _ = writeln!(report, "camera link          {camera}");
    // Fitted once, and only for `auto`.
    let fit = match config.reach_space {
        ReachSetting::Auto => Some(fit_reach(&config, &mut model)),
        ReachSetting::Given(_) => None,
    };
    let space = match &fit {
        Some(fit) => fit.as_ref().map(|fit| fit.space).map_err(|why| why.clone()),
        None => reach_space(&config, &mut model),
    }
    .map_err(|why| {
        // What was chosen is printed before why no space fits it.
        match say(&report) {
            Ok(()) => refused(PreflightError::NoReachSpace(why).to_string(), true),
            Err(failure) => failure,
        }
    })?;
    let how = match config.reach_space {
        ReachSetting::Auto => "fitted",
        ReachSetting::Given(_) => "given",
    };
    let _ = writeln!(
        report,
        "reach space ({how})  r {:.1}..{:.1} cm, z {:.1}..{:.1} cm, {:.1} dm³",
        space.r_min * 100.0,
        space.r_max * 100.0,
        space.z_min * 100.0,
        space.z_max * 100.0,
        space.volume() * 1000.0
    );
    if let Some(Ok(fit)) = fit {
        let _ = writeln!(
            report,
            "box share            the space's (r, z) box holds {:.0}% of the (r, z) cells the arm reaches ({} of {} shoulder-elbow poses usable)",
            fit.area_share * 100.0,
            fit.usable,
            fit.sampled
        );
    }
    // The same seeded targets give the coverage and the contact line.
    let (solved, touching) = target_poses_in_contact(&config, &model, &space, REACH_SAMPLES);
    let _ = writeln!(
        report,
        "covered              {:.1}% of {REACH_SAMPLES} points sampled in the reach space are reached looking down",
        100.0 * solved as f64 / REACH_SAMPLES as f64
    );
    let _ = writeln!(
        report,
        "target contact       {touching} of the {solved} reached points put a link within {:.0} cm of the floor or of another link ({:.1}%)",
        CONTACT_MARGIN / M_PER_CM,
        100.0 * touching as f64 / solved.max(1) as f64
    );
    let (made, stopped) = contact_stopped_moves(&config, &model, &space, CONTACT_MOVES);
    let _ = writeln!(
        report,
        "contact              {stopped} of {made} moves between reached points stopped by a contact ({:.1}%; the floor, obstacles, the arm's own links)",
        100.0 * stopped as f64 / made.max(1) as f64
    );
    let ranges = learned_ranges(&model, &space).zip(fitted_boundaries(&model, &space));
    if let Some(([(low2, high2), (low3, high3)], [(b0, b1), (b2, b3)])) = ranges {
        let _ = writeln!(
            report,
            "learned θ2, θ3       {low2:.1}..{high2:.1}°, {low3:.1}..{high3:.1}° over the reach space (boundary_0, boundary_1 with {BOUNDARY_MARGIN_DEG}° to spare: {b0} {b1}, {b2} {b3}; {})",
            if own_arm { "a run of this arm takes them unless the config gives its own" } else { "the OSCAR-6's config gives its own" }
        );
    }
    let _ = writeln!(
        report,
        "{}",
        standoff_line(&mut config, &mut sources, &space, own_arm)?
    );
    match prelearning_moves(&model, &camera_model(&config), &space) {
        Some(_) => {
            let goal = space.prelearning_goal();
            let theta = model
                .solve_camera_position(&goal)
                .expect("the pre-learning moves exist");
            let q = model.full_pose(&theta);
            let _ = writeln!(
                report,
                "pre-learning pose    camera at ({:.1}, {:.1}, {:.1}) cm: {}",
                goal.x * 100.0,
                goal.y * 100.0,
                goal.z * 100.0,
                degrees(&model, q.as_slice())
            );
        }
        None => {
            report += "pre-learning pose    none: the middle of the reach space is not reached\n"
        }
    }
    say(&report)
}

/// The standoff and cz's boundaries a run of this arm takes over `space`: sized to the
/// space where the config leaves them at their defaults on a fitted space of its own arm.
fn standoff_line(
    config: &mut Config,
    sources: &mut Sources,
    space: &ReachSpace,
    own_arm: bool,
) -> Result<String, Failure> {
    if own_arm {
        size_standoff_to_arm(config, sources, space).map_err(bad_input)?;
        size_readings_to_arm(config, sources, space).map_err(bad_input)?;
    }
    let how = match config.source_of("standoff", sources) {
        Source::Fitted => format!(
            "sized to the fitted space: the study's 20 cm times its height over {FULL_STANDOFF_HEIGHT_CM} cm, {MIN_SIZED_STANDOFF_CM}..20 cm; a run of this arm takes it unless the config gives its own"
        ),
        Source::Default => "the study's".to_string(),
        given => format!("given: {given}"),
    };
    let (low, high) = (
        space.z_min / M_PER_CM - config.standoff,
        space.z_max / M_PER_CM - config.standoff,
    );
    Ok(format!(
        "standoff             {:.1} cm above the object's centre at the target ({how}): the object's centre at z {low:.1}..{high:.1} cm; cz's boundaries {} {}",
        config.standoff, config.boundary_4_low, config.boundary_4_high
    ))
}

/// Moves between random reached points tried for the share a contact stops.
const CONTACT_MOVES: usize = 500;

/// The arm's name, chain, learned joints and wrist.
fn arm_lines(model: &ArmModel) -> String {
    let names: Vec<&str> = model.joints().iter().map(|j| j.name.as_str()).collect();
    let learned = model.learned().map(|j| names[j]);
    let wrist = match *model.wrist() {
        Wrist::OneJoint(j) => format!("`{}` in closed form", names[j]),
        Wrist::Numerical { joints, count } => format!(
            "{} by Newton steps",
            joints[..count]
                .iter()
                .map(|&j| format!("`{}`", names[j]))
                .collect::<Vec<_>>()
                .join(", ")
        ),
        Wrist::None => "none".to_string(),
    };
    format!(
        "arm                  {} ({} joints: {})\nlearned joints       {}\nwrist                {wrist}\n",
        model.name(),
        names.len(),
        names.join(", "),
        learned.join(", ")
    )
}

/// `name=angle°` for every joint.
fn degrees(model: &ArmModel, q: &[f64]) -> String {
    model
        .joints()
        .iter()
        .zip(q)
        .map(|(j, v)| format!("{}={:.2}°", j.name, v.to_degrees()))
        .collect::<Vec<_>>()
        .join(" ")
}
