//! Every config entry: its name, type and meaning, in one list.

use super::ConfigErrorKind;
use crate::control::ServoMode;
use crate::experiment::config_values::{
    CameraKind, ConfigValue, ObstacleBox, ReachSetting, SimKind,
};
use crate::experiment::PackagePaths;
use crate::learn::{MergeStrategy, Method};

config_entries! {
    /// The learning method.
    method: Method,
    /// The simulator: kinematic or dynamic.
    sim: SimKind,
    /// The camera model: projection or raycast.
    camera: CameraKind,
    /// Seed of the run's random generator.
    seed: u64,
    /// Trials to run.
    trials: usize,
    /// Input boundary 0 (θ2, degrees), low end.
    boundary_0_low: f64,
    /// Input boundary 0 (θ2, degrees), high end.
    boundary_0_high: f64,
    /// Input boundary 1 (θ3, degrees), low end.
    boundary_1_low: f64,
    /// Input boundary 1 (θ3, degrees), high end.
    boundary_1_high: f64,
    /// Input boundary 2 (cx, pixels), low end.
    boundary_2_low: f64,
    /// Input boundary 2 (cx, pixels), high end.
    boundary_2_high: f64,
    /// Input boundary 3 (cy, pixels), low end.
    boundary_3_low: f64,
    /// Input boundary 3 (cy, pixels), high end.
    boundary_3_high: f64,
    /// Input boundary 4 (cz), low end.
    boundary_4_low: f64,
    /// Input boundary 4 (cz), high end.
    boundary_4_high: f64,
    /// Input boundary 5 (dx, pixels, lin8), low end.
    boundary_5_low: f64,
    /// Input boundary 5 (dx, pixels, lin8), high end.
    boundary_5_high: f64,
    /// Input boundary 6 (dy, pixels, lin8), low end.
    boundary_6_low: f64,
    /// Input boundary 6 (dy, pixels, lin8), high end.
    boundary_6_high: f64,
    /// Input boundary 7 (dz, lin8), low end.
    boundary_7_low: f64,
    /// Input boundary 7 (dz, lin8), high end.
    boundary_7_high: f64,
    /// ε: a trial stops once the camera is this close to the target (cm).
    min_target_distance: f64,
    /// Kept from the study's config, whose author did not know its use; unused.
    split_extension: f64,
    /// Relative merge error.
    merge_error: f64,
    /// Split error.
    split_error: f64,
    /// At most this many feedback steps per trial.
    feedback_steps: usize,
    /// At least this many feedback steps per trial before ε can stop it.
    min_feedback_steps: usize,
    /// Maximum depth of the tree.
    tree_depth: usize,
    /// Trial before which the camera is turned (0: never).
    rotate_trial: usize,
    /// Degrees the camera turns about its optical axis at `rotate_trial`.
    rotate_degrees: f64,
    /// Trial before which a link is stretched (0: never).
    elongate_trial: usize,
    /// The link stretched at `elongate_trial` (1, 2 or 3).
    elongate_link: usize,
    /// Signed length added to that link (cm).
    elongate_cm: f64,
    /// Staggered perceptrons (sum-sets) per node.
    nr_of_matrices: usize,
    /// Patterns a sum-set holds before it is cleared.
    max_pats_in_mat: usize,
    /// Patterns a sub-box needs before it can be split off.
    min_pats_for_split: usize,
    /// A pose pair is a learning pattern only if some joint moved at least this (degrees).
    minimal_joint_move: f64,
    /// Patterns averaged by the per-level error monitor.
    monitor_ave: usize,
    /// How changes of the mapping are handled: thesis or change_detection.
    merge_strategy: MergeStrategy,
    /// change_detection: a trial counts towards an alarm by how far its mean log relative
    /// pattern error is above the baseline, less this many spreads.
    change_drift: f64,
    /// change_detection: alarm level of the CUSUM statistic (spreads).
    change_threshold: f64,
    /// change_detection: trials the baseline averages over.
    change_baseline: usize,
    /// change_detection: trials that pass before a trial's error enters the baseline.
    change_lag: usize,
    /// change_detection: trials watched before the first alarm can come (after the start
    /// and after each alarm).
    change_warmup: usize,
    /// change_detection: patterns from after a detected change a node needs before it
    /// answers again.
    change_min_fresh: usize,
    /// change_detection: trials after a detected change, and between later checks, before
    /// subtrees starved of new patterns are cut.
    change_grace: usize,
    /// Absolute merge threshold of a node's running error.
    am_error_tresh: f64,
    /// Patterns averaged for the absolute merge.
    am_error_iters: usize,
    /// lin8: shrink factor of the d boundaries per depth.
    error_area_shrink: f64,
    /// 0: store patterns in the run's `pat_file`; anything else: in memory.
    use_pat_file: i64,
    /// The tree's per-level figures are recorded every this many trials.
    depth_info: usize,
    /// 1: print progress information during a run; 0: quiet.
    verbose_output: i64,
    /// Top joint speed of a move (degrees per second).
    robot_speed: f64,
    /// Joint acceleration of a move (degrees per second²).
    robot_accel: f64,
    /// Dynamic simulator: physics and servo time step (seconds).
    dt: f64,
    /// Dynamic simulator: constraint solver iterations per step.
    solver_iterations: usize,
    /// Dynamic simulator: joint servo position gain (1/s², scaled by the joint's inertia).
    motor_stiffness: f64,
    /// Dynamic simulator: joint servo velocity gain (1/s, scaled by the joint's inertia).
    motor_damping: f64,
    /// Dynamic simulator: a move has settled once every joint is this close to its
    /// set-point (degrees) …
    settle_position_tol: f64,
    /// … and turns slower than this (degrees per second).
    settle_speed_tol: f64,
    /// Dynamic simulator: simulated seconds a move may take to settle before it is
    /// reported as not settled.
    settle_timeout: f64,
    /// Height of the floor (cm, world frame): a move stops where a link or the camera
    /// would go below it, in both simulators; default −22 (the lowest target's bottom).
    floor_z: f64,
    /// The link the camera is fixed to; the chain from the URDF's root to it is the arm.
    camera_link: String,
    /// The camera centre in the camera link's frame (cm, x,y,z); its axes are the link's.
    camera_offset: [f64; 3],
    /// The three learned joints (base yaw, shoulder, elbow) by URDF name, a,b,c.
    learned_joints: [String; 3],
    /// Folders searched for the URDF's `package://NAME/rest` meshes, in order (`none`, or
    /// comma-separated; a relative one in a config file is taken from that file's folder).
    package_paths: PackagePaths,
    /// The camera's reach space: `auto` (fitted to the arm) or r_min,r_max,z_min,z_max (cm).
    reach_space: ReachSetting,
    /// Raycast camera: rays per image side (the 512×512 image is sampled N×N).
    raycast_resolution: usize,
    /// Raycast camera: σ of each pixel's grey level (coverage 0–1) before the blob is
    /// measured; 0 = noiseless.
    raycast_noise: f64,
    /// Sensor noise: σ of the blob centroid on each image axis (pixels); 0 = exact.
    camera_noise_px: f64,
    /// Sensor noise: σ of the blob area relative to itself; 0 = exact.
    camera_area_noise: f64,
    /// Sensor noise: σ of each joint encoder's reading (degrees); 0 = exact.
    joint_noise_deg: f64,
    /// Frames per second of a free-running camera (dynamic simulator); 0 = a frame the
    /// moment each move has settled (the study's).
    camera_fps: f64,
    /// A frame shows the world as it was this long before it is delivered (ms; a
    /// multiple of `dt`, dynamic simulator); default 0.
    camera_latency_ms: f64,
    /// step (each move settles before the next frame; the study's) or continuous (a new
    /// move at every frame while the arm moves; dynamic simulator, `camera_fps` > 0).
    servo_mode: ServoMode,
    /// Known patterns trained per 100 regular patterns.
    known_pattern_perc: f64,
    /// Learning patterns each bin keeps.
    bin_size: usize,
    /// Stored patterns in all bins together at most; past it the least recently used bins
    /// are dropped whole (0: no cap).
    max_stored_patterns: usize,
    /// nnw: at most this many patterns re-trained per node after a trial.
    nnw_train_limit: usize,
    /// nnw: a node is re-trained once it got this many new patterns.
    nnw_train_delay: usize,
    /// nnw: initial weights are drawn in ±wrange.
    wrange: f64,
    /// nnw: hidden units per network.
    hidden_units: usize,
    /// ffn: hidden units of the single network.
    ffn_hidden_units: usize,
    /// ffn: most recent patterns the network is trained on.
    ffn_window: usize,
    /// ffn: conjugate-gradient iterations after each trial.
    ffn_cg_iterations: usize,
    /// kohonen: neurons per side of the 5-D lattice.
    kohonen_side: usize,
    /// kohonen: patterns over which neighbourhood and rates shrink.
    kohonen_anneal_patterns: usize,
    /// lwpr: a new receptive field's distance metric, times the identity (per squared
    /// normalised input).
    init_D: f64,
    /// lwpr: a new field's learning rate of its distance metric.
    init_alpha: f64,
    /// lwpr: a new field is made where no field is activated above this.
    w_gen: f64,
    /// lwpr: of two fields both activated above this, the narrower is dropped.
    w_prune: f64,
    /// lwpr: a new field's forgetting factor.
    init_lambda: f64,
    /// lwpr: the forgetting factor's annealing rate per update.
    tau_lambda: f64,
    /// lwpr: the forgetting factor a field anneals to.
    final_lambda: f64,
    /// lwpr: 1: diagonal distance metrics; 0: full ones.
    diag_only: usize,
    /// lwpr: 1: the metric's learning rates adapt (meta learning); 0: fixed.
    meta: usize,
    /// lwpr: learning rate of the learning rates' logarithms (with meta 1).
    meta_rate: f64,
    /// lwpr: weight of the smoothness penalty on the distance metric.
    penalty: f64,
    /// lwpr: another projection is added when the last one cut the error below this
    /// fraction.
    add_threshold: f64,
    /// lwpr: outputs Δθ are learned divided by this (degrees).
    norm_out: f64,
    ;
    repeated {
        /// A box standing in the world, `x,y,z,sx,sy,sz`: its centre and side lengths (cm,
        /// world frame); zero or more lines. The ray-cast camera sees it, it can hide the
        /// target, targets are never drawn inside it, and moves stop at it.
        obstacle: ObstacleBox,
    }
}
