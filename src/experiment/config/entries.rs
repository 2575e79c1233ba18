//! Every config entry, declared once: its doc line, name, kind, default, unit, what it
//! applies to and the rule its value must meet on its own. A learner's entries take their
//! defaults from its settings' `Default`, written once in the learner's folder; the move and
//! dynamic simulator entries theirs from `DynamicSettings`' `Default`. The parser, the
//! defaults, `info`, `config defaults`, the error messages and docs/CONFIG.md all come from
//! here.

use super::declaration::{bad_value, meets_rule, one_line, Declaration};
use super::package_paths::PackagePaths;
use super::scope::{
    Scope, BOUNDED, BROYDEN, DYNAMIC, FFN, ISSGP, KOHONEN, LIN8, LWPR, MLP, NESTED, NETS, NNW,
    PERCEPTRONS, RAYCAST, REGRESSORS, WATCHING,
};
use super::urdf_file::UrdfFile;
use super::values::{CameraKind, CameraMount, ConfigValue, ObstacleBox, ReachSetting, SimKind};
use super::{ConfigErrorKind, Rule};
use crate::camera::CameraModel;
use crate::control::ServoMode;
use crate::learn::change::{ChangeRecovery, ChangeSettings};
use crate::learn::{
    BroydenSettings, BroydenUpdate, FfnSettings, IssgpSettings, KohonenSettings, Lin5Settings,
    Lin8Settings, LwprSettings, MergeStrategy, Method, MlpSettings, NestedSettings, NnwSettings,
    PatternSettings, PerceptronSettings, TreeSettings,
};
use crate::robot::{BaseLink, CameraLink, DynamicSettings, Engine, LearnedJoints};
use crate::units::M_PER_CM;

use Rule::{AtLeast, NonNegative, OpenUnit, Positive, PositiveUpTo, UnitBelowOne, Within};
use Scope::{All, Unused};

/// Largest magnitude of an input boundary.
const BOUNDARY: Rule = Within(-1e6, 1e6);

// The settings whose `Default` the learners' entries below take their defaults from.

fn lin5() -> Lin5Settings {
    Lin5Settings::default()
}

fn tree() -> TreeSettings {
    TreeSettings::default()
}

fn change() -> ChangeSettings {
    ChangeSettings::default()
}

fn lwpr() -> LwprSettings {
    LwprSettings::default()
}

fn issgp() -> IssgpSettings {
    IssgpSettings::default()
}

fn mlp() -> MlpSettings {
    MlpSettings::default()
}

fn broyden() -> BroydenSettings {
    BroydenSettings::default()
}

// And the simulators' settings, whose `Default` the move and dynamic entries take theirs
// from (in the entries' units).

fn dynamic() -> DynamicSettings {
    DynamicSettings::default()
}

config_entries! {
    /// The learning method: lin5, lin8, nnw, ffn, kohonen, ik, lwpr, issgp, mlp or
    /// broyden.
    method: Method = Method::Lin5, "", All, Rule::Any;
    /// The simulator: kinematic (forward kinematics) or dynamic (a Rapier multibody).
    sim: SimKind = SimKind::Kinematic, "", All, Rule::Any;
    /// The camera: projection (the exact analytic image) or raycast (a ray per pixel).
    camera: CameraKind = CameraKind::Projection, "", All, Rule::Any;
    /// Seed of every random draw of the run: the same seed gives the same data files.
    seed: u64 = 1, "", All, Rule::Any;
    /// Trials to run.
    trials: usize = 10000, "", All, Within(1.0, 1e9);
    /// Input boundary 0 (θ2, the shoulder) of the learner's root box, low end (boundaries 0
    /// and 1 left at their defaults on a URDF other than the shipped one: fitted to the arm).
    boundary_0_low: f64 = lin5().bounds[0].0, "°", BOUNDED, BOUNDARY;
    /// Input boundary 0 (θ2, the shoulder), high end.
    boundary_0_high: f64 = lin5().bounds[0].1, "°", BOUNDED, BOUNDARY;
    /// Input boundary 1 (θ3, the elbow), low end.
    boundary_1_low: f64 = lin5().bounds[1].0, "°", BOUNDED, BOUNDARY;
    /// Input boundary 1 (θ3, the elbow), high end.
    boundary_1_high: f64 = lin5().bounds[1].1, "°", BOUNDED, BOUNDARY;
    /// Input boundary 2 (cx, the blob's image x), low end.
    boundary_2_low: f64 = lin5().bounds[2].0, "pixels", BOUNDED, BOUNDARY;
    /// Input boundary 2 (cx), high end.
    boundary_2_high: f64 = lin5().bounds[2].1, "pixels", BOUNDED, BOUNDARY;
    /// Input boundary 3 (cy, the blob's image y), low end.
    boundary_3_low: f64 = lin5().bounds[3].0, "pixels", BOUNDED, BOUNDARY;
    /// Input boundary 3 (cy), high end.
    boundary_3_high: f64 = lin5().bounds[3].1, "pixels", BOUNDED, BOUNDARY;
    /// Input boundary 4 (cz, from the blob's area), low end (both ends left at their
    /// defaults on a URDF other than the shipped one: the high end scaled by its reach
    /// space's height over the standoff, this end with it where the standoff is below 20 cm,
    /// as `eyehand reach` prints).
    boundary_4_low: f64 = lin5().bounds[4].0, "", BOUNDED, BOUNDARY;
    /// Input boundary 4 (cz), high end.
    boundary_4_high: f64 = lin5().bounds[4].1, "", BOUNDED, BOUNDARY;
    /// Input boundary 5 (dx, the image x after the move), low end.
    boundary_5_low: f64 = Lin8Settings::default().bounds[5].0, "pixels", LIN8, BOUNDARY;
    /// Input boundary 5 (dx), high end.
    boundary_5_high: f64 = Lin8Settings::default().bounds[5].1, "pixels", LIN8, BOUNDARY;
    /// Input boundary 6 (dy, the image y after the move), low end.
    boundary_6_low: f64 = Lin8Settings::default().bounds[6].0, "pixels", LIN8, BOUNDARY;
    /// Input boundary 6 (dy), high end.
    boundary_6_high: f64 = Lin8Settings::default().bounds[6].1, "pixels", LIN8, BOUNDARY;
    /// Input boundary 7 (dz, cz after the move), low end.
    boundary_7_low: f64 = Lin8Settings::default().bounds[7].0, "", LIN8, BOUNDARY;
    /// Input boundary 7 (dz), high end.
    boundary_7_high: f64 = Lin8Settings::default().bounds[7].1, "", LIN8, BOUNDARY;
    /// ε: a trial may stop once the camera is this close to the target.
    min_target_distance: f64 = 0.05, "cm", All, PositiveUpTo(10.0);
    /// At most this many feedback steps per trial (a trial learns every pair of its poses).
    feedback_steps: usize = 10, "", All, Within(1.0, 1000.0);
    /// At least this many feedback steps per trial before reaching ε ends it (at most
    /// feedback_steps).
    min_feedback_steps: usize = 5, "", All, Rule::Any;
    /// A pose pair is a learning pattern only if at least one joint moved this much.
    minimal_joint_move: f64 = PatternSettings::default().minimal_joint_move, "°", All, Within(0.0, 10.0);
    /// Top joint speed of a move's trapezoidal profile (of the learned joint with the
    /// farthest to go); a move runs slower where a joint, learned or following the wrist,
    /// would otherwise turn faster than 99% of its URDF velocity limit (servo_mode continuous
    /// aside: it chases its goal at this speed).
    robot_speed: f64 = dynamic().moves.speed.to_degrees(), "°/s", All, Within(0.1, 3600.0);
    /// Joint acceleration of a move's trapezoidal profile.
    robot_accel: f64 = dynamic().moves.accel.to_degrees(), "°/s²", All, Within(1.0, 100_000.0);
    /// What steps the dynamic arm: rk4 (its joint-space equations, fourth order, under
    /// eyehand's servo law) or rapier (Rapier's multibody integrator and joint motors).
    engine: Engine = dynamic().engine, "", DYNAMIC, Rule::Any;
    /// Physics and servo time step (0.005: a 200 Hz control loop).
    dt: f64 = dynamic().dt, "s", DYNAMIC, Within(1e-5, 0.1);
    /// Rapier's constraint solver iterations: every tick on the rapier engine, on rk4 the
    /// ticks Rapier steps (a link touching).
    solver_iterations: usize = dynamic().solver_iterations, "", DYNAMIC, Within(1.0, 100.0);
    /// Rapier steps per tick on the rapier engine, each of dt divided by this.
    rapier_substeps: usize = dynamic().rapier_substeps, "", DYNAMIC, Within(1.0, 100.0);
    /// Joint servo position gain, scaled by the arm's mass matrix (400000 with motor_damping
    /// 1265: a critically damped 100 Hz servo).
    motor_stiffness: f64 = dynamic().motor_stiffness, "1/s²", DYNAMIC, PositiveUpTo(1e9);
    /// Joint servo velocity gain, scaled by the arm's mass matrix.
    motor_damping: f64 = dynamic().motor_damping, "1/s", DYNAMIC, PositiveUpTo(1e6);
    /// A move has settled once every joint is this close to its set-point …
    settle_position_tol: f64 = dynamic().settle_position_tol.to_degrees(), "°", DYNAMIC, PositiveUpTo(10.0);
    /// … and turns slower than this.
    settle_speed_tol: f64 = dynamic().settle_speed_tol.to_degrees(), "°/s", DYNAMIC, PositiveUpTo(1000.0);
    /// A move still unsettled this long after its profile ended is counted as not settled
    /// (at least dt, at most 60 s).
    settle_timeout: f64 = dynamic().settle_timeout, "s", DYNAMIC, Rule::Any;
    /// Height of the floor (world frame; −22 is the lowest target's bottom): a move stops
    /// where a link or the camera would go below it.
    floor_z: f64 = dynamic().moves.floor_z / M_PER_CM, "cm", All, Within(-1000.0, 0.0);
    /// The arm's URDF file (a relative one is taken from the config file's folder), or
    /// `shipped` for the OSCAR-6 built in; `--urdf` overrides it.
    urdf: UrdfFile = UrdfFile::default(), "", All, Rule::Any;
    /// The link the arm stands on (its frame the world's; one arm of a bigger robot), or
    /// `root`: the root of the URDF's tree.
    base_link: BaseLink = BaseLink::Root, "", All, Rule::Any;
    /// The link the camera is fixed to, the chain from base_link to it the arm; `auto`:
    /// the link named camera_link, else where the chain ends (tool0, a hand, the last link).
    camera_link: CameraLink = CameraLink::Auto, "", All, Rule::Any;
    /// The camera centre x,y,z in the camera link's frame (its z axis the optical axis).
    camera_offset: [f64; 3] = [0.0; 3], "cm", All, Rule::Any;
    /// The camera on its link: offset x,y,z (m, in the link's frame) and turn roll,pitch,yaw
    /// (° about the link's x, y, z axes, as a URDF origin's rpy); 0,0,0,0,0,0: at the link's
    /// origin looking along its z axis (a camera on a flange that faces along -z: 0,0,0,180,0,0).
    camera_mount: CameraMount = CameraMount::default(), "m, °", All, Rule::Any;
    /// The three learned joints (base yaw, shoulder, elbow) by URDF name, a,b,c; `auto`: the
    /// first joint turning about the vertical, then the two that move the camera most.
    learned_joints: LearnedJoints = LearnedJoints::Auto, "", All, Rule::Any;
    /// Folders searched for the URDF's `package://NAME/rest` meshes, comma-separated, or
    /// `none` (a relative one is taken from the config file's folder).
    package_paths: PackagePaths = PackagePaths::default(), "", All, Rule::Any;
    /// Where targets lie: r_min,r_max,z_min,z_max of the study's half annulus, or `auto`
    /// (the same shape, or where it does not fit one of other proportions, fitted to what
    /// the arm reaches looking down; what a URDF other than the shipped one gets when this
    /// is left at its default).
    reach_space: ReachSetting = ReachSetting::Given([46.0, 93.0, 0.0, 52.0]), "cm", All, Rule::Any;
    /// Height of the camera above the object's centre at the target (the study's 20; left
    /// at its default on a URDF other than the shipped one whose reach space is fitted:
    /// sized to that space, as `eyehand reach` prints).
    standoff: f64 = CameraModel::default().standoff / M_PER_CM, "cm", All, Within(5.0, 200.0);
    /// Rays per image side: the 512×512 image is sampled by an N×N grid of rays.
    raycast_resolution: usize = 256, "", RAYCAST, Within(16.0, 4096.0);
    /// σ of each pixel's grey level (its coverage, 0–1) before the blob is measured.
    raycast_noise: f64 = 0.0, "", RAYCAST, Within(0.0, 0.3);
    /// Sensor noise: σ of the blob centroid on each image axis (0: exact).
    camera_noise_px: f64 = 0.0, "pixels", All, Within(0.0, 50.0);
    /// Sensor noise: σ of the blob area relative to itself (0: exact).
    camera_area_noise: f64 = 0.0, "", All, Within(0.0, 0.5);
    /// Sensor noise: σ of each joint encoder's reading (0: exact).
    joint_noise_deg: f64 = 0.0, "°", All, Within(0.0, 10.0);
    /// Frames per second of a free-running camera; 0: a frame the moment each move has
    /// settled (the study's). Needs sim dynamic when above 0, but for learn_during_moves
    /// on the kinematic simulator (frames along each move's profile).
    camera_fps: f64 = 0.0, "frames/s", All, Within(0.0, 1000.0);
    /// 1: the frames the camera takes during each move (at camera_fps, or 30 frames/s when
    /// camera_fps is 0) are poses of the trial's path too, and the learning patterns come from all of
    /// them; 0: only the poses at which moves ended (the study's).
    learn_during_moves: usize = 0, "", All, Within(0.0, 1.0);
    /// With learn_during_moves: at most this many of each move's frames are learned,
    /// evenly spread, the last the latest before the move ended.
    move_frames_learned: usize = 1, "", All, Within(1.0, 100.0);
    /// A frame shows the world as it was this long before it is delivered (a whole number
    /// of dt steps).
    camera_latency_ms: f64 = 0.0, "ms", DYNAMIC, Within(0.0, 1000.0);
    /// step (each move settles before the next frame: the study's) or continuous (a new move
    /// at every frame while the arm moves; needs camera_fps above 0).
    servo_mode: ServoMode = ServoMode::Step, "", DYNAMIC, Rule::Any;
    /// Turn the camera about its optical axis by rotate_degrees before this trial (0:
    /// never).
    rotate_trial: usize = 0, "", All, Rule::Any;
    /// Degrees the camera turns at rotate_trial.
    rotate_degrees: f64 = 0.0, "°", All, Within(-360.0, 360.0);
    /// Stretch link elongate_link by elongate_cm before this trial (0: never).
    elongate_trial: usize = 0, "", All, Rule::Any;
    /// The link stretched at elongate_trial: 1, 2 or 3.
    elongate_link: usize = 2, "", All, Rule::Any;
    /// Signed length added to that link (negative shortens it).
    elongate_cm: f64 = 0.0, "cm", All, Within(-1000.0, 1000.0);
    /// The tree is not split deeper than this.
    tree_depth: usize = tree().max_depth, "", NESTED, Within(1.0, 12.0);
    /// A sub-box is split off when its stored patterns' error in its parent exceeds this.
    split_error: f64 = tree().split_error, "", NESTED, NonNegative;
    /// Stored patterns a sub-box needs before it is split off (keep it at 25 or more).
    min_pats_for_split: usize = tree().min_pats_for_split, "", NESTED, Within(1.0, 1e6);
    /// Learning patterns each bin keeps (the oldest is dropped when full).
    bin_size: usize = tree().bin_size, "", NESTED, Within(1.0, 10000.0);
    /// Stored patterns in all bins together at most, past which the least recently used
    /// bins are dropped whole (0: no cap; otherwise at least bin_size).
    max_stored_patterns: usize = tree().max_stored_patterns, "", NESTED, Rule::Any;
    /// Relative merge: a child is cut when its running error exceeds its parent's on its box
    /// by this much (99.05: never, in practice).
    merge_error: f64 = tree().merge_error, "", PERCEPTRONS, NonNegative;
    /// Absolute merge: a node is cut when its mean miss over its last am_error_iters
    /// patterns exceeds this.
    am_error_tresh: f64 = tree().am_error_tresh, "°", PERCEPTRONS, Positive;
    /// Patterns averaged for the absolute merge.
    am_error_iters: usize = tree().am_error_iters, "", PERCEPTRONS, Within(1.0, 10000.0);
    /// How changes of the mapping are handled: thesis (the study's merges) or
    /// change_detection (also watch the trials and relearn after an alarm).
    merge_strategy: MergeStrategy = NestedSettings::default().merge_strategy, "", WATCHING, Rule::Any;
    /// change_detection: a trial counts towards an alarm by how far its mean log relative
    /// error is above the baseline, less this many spreads.
    change_drift: f64 = change().detector.drift, "", WATCHING, NonNegative;
    /// change_detection: alarm level of the CUSUM statistic (spreads).
    change_threshold: f64 = change().detector.threshold, "", WATCHING, Positive;
    /// change_detection: trials the baseline averages over.
    change_baseline: usize = change().detector.baseline, "", WATCHING, Within(1.0, 1e9);
    /// change_detection: trials that pass before a trial's value enters the baseline.
    change_lag: usize = change().detector.lag, "", WATCHING, Within(0.0, 1e6);
    /// change_detection: trials watched before the first alarm can come, after the start
    /// and after each alarm (above change_lag).
    change_warmup: usize = change().detector.warmup, "", WATCHING, Rule::Any;
    /// change_detection: patterns from after a change a node needs before it answers again.
    change_min_fresh: usize = change().min_fresh, "", NESTED, Rule::Any;
    /// change_detection: trials after an alarm, and between later checks, before subtrees
    /// starved of new patterns are cut.
    change_grace: usize = change().grace, "", NESTED, AtLeast(1.0);
    /// change_detection: what an alarm does to a learner: correct (keep its model and fit a
    /// correction of the camera readings from the patterns since the change) or forget (a
    /// nested learner drops what was learned before the change and cuts what stays
    /// starved; lwpr, issgp and mlp forget as their notes say; ffn and kohonen have none).
    change_recovery: ChangeRecovery = change().recovery, "", WATCHING, Rule::Any;
    /// change_recovery correct: patterns since a change its correction of the readings is
    /// fitted from before it is fixed, once a refit no longer moves it, and the tree learns
    /// again (at least 30, the patterns from which queries go through it).
    change_fit_patterns: usize = change().fit_patterns, "", WATCHING, AtLeast(30.0);
    /// change_recovery correct: stored patterns a sub-box needs before it is split off once
    /// a correction is fixed (the changed robot works where the tree is still coarse; never
    /// more than min_pats_for_split).
    change_split_patterns: usize = change().split_patterns, "", NESTED, Within(1.0, 1e6);
    /// The error of each tree level is averaged over this many patterns.
    monitor_ave: usize = tree().monitor_ave, "", PERCEPTRONS, Within(1.0, 1e7);
    /// Kept from the study's config, whose author did not know its use.
    split_extension: f64 = 2.0, "", Unused, Rule::Any;
    /// Staggered sum-sets (perceptrons) per node.
    nr_of_matrices: usize = PerceptronSettings::default().sum_sets, "", PERCEPTRONS, Within(1.0, 1000.0);
    /// Patterns a sum-set holds before it is cleared (at least nr_of_matrices).
    max_pats_in_mat: usize = PerceptronSettings::default().set_size, "", PERCEPTRONS, Rule::Any;
    /// Known patterns (c = 0 → Δθ = 0) trained per 100 regular patterns.
    known_pattern_perc: f64 = tree().known_pattern_perc, "", PERCEPTRONS, Within(0.0, 1000.0);
    /// lin8: the d boundaries shrink by this factor per tree depth (the study's 0.20
    /// starves this arm's tree below depth 4; 0.5 halves the d box like every other input).
    error_area_shrink: f64 = Lin8Settings::default().error_area_shrink, "", LIN8, PositiveUpTo(1.0);
    /// nnw: at most this many patterns re-train a node after a trial.
    nnw_train_limit: usize = tree().retrain_limit, "", NNW, Within(0.0, 1e6);
    /// nnw: a node is re-trained once it got this many new patterns.
    nnw_train_delay: usize = tree().retrain_delay, "", NNW, Rule::Any;
    /// Initial weights of a net are drawn in ±wrange.
    wrange: f64 = NnwSettings::default().wrange, "", NETS, PositiveUpTo(10.0);
    /// nnw: hidden units of each node's net (at most 100: every node trains its own net,
    /// and 5,000 take 6 s a trial).
    hidden_units: usize = NnwSettings::default().hidden_units, "", NNW, Within(1.0, 100.0);
    /// ffn: hidden units of the one net (25; the study also tried 45; at most 1,000:
    /// 10,000 take 5 s a trial).
    ffn_hidden_units: usize = FfnSettings::default().hidden_units, "", FFN, Within(1.0, 1000.0);
    /// ffn: the net is trained on this many most recent patterns.
    ffn_window: usize = FfnSettings::default().window, "", FFN, Within(1.0, 1e6);
    /// ffn: conjugate-gradient (Polak-Ribière) iterations after every trial (at most
    /// 1,000: 10,000 take 3 s a trial).
    ffn_cg_iterations: usize = FfnSettings::default().cg_iterations, "", FFN, Within(0.0, 1000.0);
    /// kohonen: neurons per side of the 5-D lattice (7: the study's 16,807).
    kohonen_side: usize = KohonenSettings::default().side, "", KOHONEN, Within(2.0, 12.0);
    /// kohonen: patterns over which the neighbourhood and the learning rates shrink.
    kohonen_anneal_patterns: usize = KohonenSettings::default().anneal_patterns, "", KOHONEN, AtLeast(1.0);
    /// lwpr: a new receptive field's distance metric, times the identity (per squared
    /// normalised input; 25: a Gaussian of σ 0.2 of each input range).
    init_D: f64 = lwpr().init_d, "", LWPR, PositiveUpTo(1e6);
    /// lwpr: a new field's learning rate of its distance metric.
    init_alpha: f64 = lwpr().init_alpha, "", LWPR, PositiveUpTo(1e6);
    /// lwpr: a new field is made where no field is activated above this (at most 0.5:
    /// nearer 1 almost every pattern makes a field, and a run slows to a few trials per
    /// second).
    w_gen: f64 = lwpr().w_gen, "", LWPR, PositiveUpTo(0.5);
    /// lwpr: of two fields both activated above this, the narrower is dropped (1: never;
    /// above w_gen).
    w_prune: f64 = lwpr().w_prune, "", LWPR, Rule::Any;
    /// lwpr: a new field's forgetting factor.
    init_lambda: f64 = lwpr().init_lambda, "", LWPR, OpenUnit;
    /// lwpr: the forgetting factor's annealing rate per update.
    tau_lambda: f64 = lwpr().tau_lambda, "", LWPR, UnitBelowOne;
    /// lwpr: the forgetting factor a field anneals to.
    final_lambda: f64 = lwpr().final_lambda, "", LWPR, OpenUnit;
    /// lwpr: 1: diagonal distance metrics (a width per input); 0: full ones.
    diag_only: usize = usize::from(lwpr().diag_only), "", LWPR, Within(0.0, 1.0);
    /// lwpr: 1: the metric's learning rates adapt (meta learning); 0: fixed.
    meta: usize = usize::from(lwpr().meta), "", LWPR, Within(0.0, 1.0);
    /// lwpr: learning rate of the learning rates' logarithms (with meta 1).
    meta_rate: f64 = lwpr().meta_rate, "", LWPR, Within(0.0, 1e6);
    /// lwpr: weight of the smoothness penalty on the distance metric.
    penalty: f64 = lwpr().penalty, "", LWPR, Within(0.0, 1e3);
    /// lwpr: another PLS projection is added once the last cut the error below this
    /// fraction.
    add_threshold: f64 = lwpr().add_threshold, "", LWPR, OpenUnit;
    /// lwpr, issgp, mlp: outputs Δθ are learned in units of this many degrees.
    norm_out: f64 = lwpr().norm_out, "°", REGRESSORS, PositiveUpTo(1e4);
    /// issgp: D, the random Fourier features (the Cholesky factor is D×D).
    issgp_features: usize = issgp().features, "", ISSGP, Within(1.0, 4000.0);
    /// issgp: the kernel's length scale of each input θ2,θ3,cx*,cy*,cz*, as a fraction of
    /// the input's boundary range (each above 0, at most 100); by default wider over the
    /// joint angles than over the offsets (the best of the sweep in docs/PEERS.md).
    issgp_length_scales: [f64; 5] = issgp().length_scales, "", ISSGP, Rule::Any;
    /// issgp: σn, the noise of a target (in norm_out units).
    issgp_noise: f64 = issgp().noise, "", ISSGP, PositiveUpTo(1e3);
    /// issgp: σf, the kernel's amplitude (in norm_out units).
    issgp_signal: f64 = issgp().signal, "", ISSGP, PositiveUpTo(1e6);
    /// issgp: λ, the weight of everything learned is multiplied by this at each pattern (1:
    /// no forgetting; keep 1/(1 − λ) well above issgp_features).
    issgp_forgetting: f64 = issgp().forgetting, "", ISSGP, Within(0.9, 1.0);
    /// issgp: 1: the answer is anchored at the centred target (no move when cx*, cy*, cz*
    /// are 0; the default, the best of the sweep in docs/PEERS.md); 0: the paper's plain
    /// regression.
    issgp_anchored: usize = usize::from(issgp().anchored), "", ISSGP, Within(0.0, 1.0);
    /// mlp: tanh units in each of the net's two hidden layers.
    mlp_hidden: usize = mlp().hidden, "", MLP, Within(1.0, 1000.0);
    /// mlp: Adam's step size.
    mlp_rate: f64 = mlp().rate, "", MLP, PositiveUpTo(1.0);
    /// mlp: patterns drawn from the replay buffer for each step.
    mlp_batch: usize = mlp().batch, "", MLP, Within(1.0, 100000.0);
    /// mlp: Adam steps after each trial (16, the best of the sweep in docs/PEERS.md).
    mlp_steps_per_trial: usize = mlp().steps_per_trial, "", MLP, Within(1.0, 10000.0);
    /// mlp: the replay buffer keeps this many most recent patterns.
    mlp_buffer: usize = mlp().buffer, "", MLP, Within(1.0, 1e6);
    /// mlp: 1: the answer is anchored at the centred target (no move when cx*, cy*, cz* are
    /// 0; the default, the best of the sweep in docs/PEERS.md); 0: a plain net.
    mlp_anchored: usize = usize::from(mlp().anchored), "", MLP, Within(0.0, 1.0);
    /// broyden: how the image Jacobian follows each move: broyden (Broyden's rank-one
    /// secant update) or rls (recursive least squares with forgetting).
    broyden_update: BroydenUpdate = broyden().update, "", BROYDEN, Rule::Any;
    /// broyden: α, the gain of Broyden's update (1: each move's secant condition met).
    broyden_rate: f64 = broyden().rate, "", BROYDEN, PositiveUpTo(1.0);
    /// broyden: λ, the forgetting factor of the rls update.
    broyden_forgetting: f64 = broyden().forgetting, "", BROYDEN, Within(0.5, 1.0);
    /// broyden: μ² of the damped least-squares step, as a share of JᵀJ's mean diagonal.
    broyden_damping: f64 = broyden().damping, "", BROYDEN, Within(0.0, 1000.0);
    /// broyden: largest joint turn of one step (the move is scaled down to it).
    broyden_max_step: f64 = broyden().max_step_deg, "°", BROYDEN, PositiveUpTo(180.0);
    /// broyden: each exploratory move of the first trial turns one joint by this.
    broyden_probe: f64 = broyden().probe_deg, "°", BROYDEN, PositiveUpTo(10.0);
    /// 0: store learning patterns in the run's pat_file; anything else: in memory.
    use_pat_file: i64 = 1, "", NESTED, Rule::Any;
    /// Memory and the per-level tree error are recorded every this many trials.
    depth_info: usize = 5, "", All, AtLeast(1.0);
    /// 1: print progress during a run; 0: quiet.
    verbose_output: i64 = 0, "", All, Rule::Any;
    repeated {
        /// A box standing in the world, x,y,z,sx,sy,sz: its centre and side lengths (world
        /// frame); zero or more lines. The ray-cast camera sees it, it can hide the target,
        /// targets are never drawn inside it, and moves stop at it.
        obstacle: ObstacleBox, "cm", All;
    }
}
