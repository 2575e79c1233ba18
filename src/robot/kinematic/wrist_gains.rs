//! How the joints the wrist solves turn with the learned joints, the bounds the floor and
//! contact rules march by and a move's pace: where they follow them linearly (the
//! OSCAR-6's θ5 against θ2 and θ3, the public collection's Panda's joint 6), each one's
//! slopes, worked out once per arm, which give a move's exact turns; otherwise (the
//! SO-100's, the xArm7's, the UR5's and the shipped Panda's wrists) each move's turns
//! sampled along its line, with a margin.

use super::pace::pieces;
use crate::robot::contact::collision::MoveStart;
use crate::robot::contact::reaches::Sweep;
use crate::robot::model::tilting;
use crate::robot::{ArmModel, Controlled, Joints, Wrist, MAX_JOINTS};
use nalgebra::{Matrix3, Vector3};
use std::f64::consts::{PI, TAU};

/// Probes per learned joint across its range ([`RevoluteJoint::one_turn`]): the wrist's
/// slopes are compared on a grid of `PROBES³` poses.
///
/// [`RevoluteJoint::one_turn`]: crate::robot::RevoluteJoint::one_turn
const PROBES: usize = 9;
/// The most a linear wrist's slopes may differ between probes (the rounding of its solve).
const LINEAR_SPREAD: f64 = 1e-12;
/// The grid a linear wrist's slopes are snapped to, where they lie within
/// [`SNAP_TOLERANCE`] of it (the OSCAR-6's 0 and ±1 exactly).
const SNAP: f64 = 1e-9;
/// See [`SNAP`].
const SNAP_TOLERANCE: f64 = 1e-12;
/// How much faster than its slopes give a linear wrist solved by Newton steps is taken to
/// turn: room for its slopes' spread over the grid ([`LINEAR_SPREAD`]) and its solve's
/// tolerance, many times over. (A wrist solved in closed form needs none: see
/// [`WristGains::sweep`].)
const LINEAR_MARGIN: f64 = 1e-6;
/// How much faster than its samples show (its turn over a piece, its slopes at each
/// sample) a wrist that does not follow linearly is taken to turn anywhere along a move.
/// Against each move's wrist solved in 200 steps (300 seeded moves of up to 0.4 rad a
/// joint, seed 1, the tests below): no turn beyond it on the SO-100, the UR5 or the shipped
/// Panda; on the xArm7 none with the crossings of its wrist's singular pose bisected
/// ([`CROSSING_BISECTIONS`]) and the floor of [`drift_floor`] (without the floor, 5 moves
/// whose joint 5 drifts near that pose).
const SAMPLED_MARGIN: f64 = 1.5;
/// How many times a piece in which the line of a move crosses its wrist's singular poses
/// is halved toward the crossing.
const CROSSING_BISECTIONS: usize = 24;
/// How far a linear wrist's turn over a move may differ from its slopes' answer before the
/// move is taken to have wrapped a wrist angle by a whole turn (rad).
const WRAP_TOLERANCE: f64 = 1e-6;

/// Slopes of a chain's joints against the learned joints: `[k][i]` is d(joint k)/d(learned
/// joint i).
type Slopes = [[f64; 3]; MAX_JOINTS];

/// How the joints of an arm's chain turn with its learned joints.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub(crate) struct WristGains {
    /// Each joint's slopes, the same at every pose: present when the wrist follows the
    /// learned joints linearly (1 for a learned joint against itself, 0 for a joint held
    /// at rest).
    slope: Option<Slopes>,
    /// What each joint's turn from the slopes is grown by: 1 + [`LINEAR_MARGIN`] for a
    /// joint a wrist solves by Newton steps, 1 for the others.
    grow: [f64; MAX_JOINTS],
    /// The joints of the chain.
    len: usize,
}

impl WristGains {
    /// The gains of `model` as it is now, from the wrist's slopes on a grid of poses over
    /// the learned joints' ranges.
    pub(crate) fn new(model: &ArmModel) -> WristGains {
        let (mut first, mut spread) = (None::<Slopes>, 0.0f64);
        for_each_probe(model, |slopes| {
            let first = first.get_or_insert(slopes);
            for (row, first_row) in slopes.iter().zip(first.iter()) {
                for (s, f) in row.iter().zip(first_row) {
                    spread = spread.max((s - f).abs());
                }
            }
        });
        let slope = first.filter(|_| spread <= LINEAR_SPREAD).map(|mut slope| {
            slope.iter_mut().flatten().for_each(|s| *s = snapped(*s));
            for (i, &j) in model.learned().iter().enumerate() {
                slope[j] = [0.0; 3];
                slope[j][i] = 1.0;
            }
            slope
        });
        let numerical = !matches!(model.wrist(), Wrist::OneJoint(_));
        let mut grow = [1.0; MAX_JOINTS];
        if numerical {
            model
                .wrist()
                .solved()
                .for_each(|k| grow[k] = 1.0 + LINEAR_MARGIN);
        }
        WristGains {
            slope,
            grow,
            len: model.dof(),
        }
    }

    /// The move from the arm at `start` by `delta` up to the fraction `up_to` of it, with
    /// how fast each joint can turn along it (rad per whole move): a learned joint by its
    /// share; a linear wrist's joint by each learned joint's share times its slope's size,
    /// added up, grown by [`LINEAR_MARGIN`] where the wrist is solved by Newton steps;
    /// another wrist's joint as fast as its samples show, in a piece per 3.6° of the lead
    /// joint (`pace::pieces`, a crossing of a two-joint wrist's singular pose bisected),
    /// grown by [`SAMPLED_MARGIN`] and at least the second and third learned joints' turns
    /// together ([`drift_floor`]); a joint held at rest not at all.
    ///
    /// A wrist in closed form (one joint, [`Wrist::OneJoint`]) that is linear is its
    /// rest angle plus the learned pitch joints' angles, each signed (the OSCAR-6's
    /// θ5 = 90° + θ2 − θ3 on a straight wrist): its slopes are exactly the snapped 0 and
    /// ±1, and its turn over any part of a move, |δθ2 − δθ3| on the OSCAR-6, is at most
    /// what they give, |δθ2| + |δθ3|, up to the rounding of its angle. So it is not grown:
    /// on the OSCAR-6 these are, bit for bit, the turns its golden runs were recorded with.
    pub(crate) fn sweep(
        &self,
        model: &ArmModel,
        start: &MoveStart,
        delta: &Controlled,
        up_to: f64,
    ) -> Sweep {
        let turns = match &self.slope {
            Some(slope) => self.gained(slope, delta),
            None => sampled_turns(model, start, delta, up_to),
        };
        Sweep {
            delta: *delta,
            turns,
        }
    }

    /// How fast (rad per whole move) each joint can turn in the move `executed`, the
    /// fraction `fraction` of `sweep`'s.
    pub(crate) fn executed_turns(
        &self,
        sweep: &Sweep,
        executed: &Controlled,
        fraction: f64,
    ) -> [f64; MAX_JOINTS] {
        match &self.slope {
            Some(slope) => self.gained(slope, executed),
            None => sweep.turns.map(|turn| turn * fraction),
        }
    }

    /// How far (rad) each joint turns in the move by `delta` from the joints `start` to
    /// `end`, exactly: where the wrist follows the learned joints linearly and no wrist
    /// angle was wrapped by a whole turn on the way (its turn from `start` to `end` is what
    /// its slopes give); `None` otherwise.
    pub(crate) fn linear_turns(
        &self,
        delta: &Controlled,
        start: &Joints,
        end: &Joints,
    ) -> Option<Joints> {
        let slope = self.slope.as_ref()?;
        let mut turns = Joints::zeros(self.len);
        for k in 0..self.len {
            let turn = slope[k][0] * delta[0] + slope[k][1] * delta[1] + slope[k][2] * delta[2];
            if (end[k] - start[k] - turn).abs() > WRAP_TOLERANCE {
                return None;
            }
            turns[k] = turn.abs();
        }
        Some(turns)
    }

    /// Each joint's turn in the move by `delta` with slopes `slope`: each learned joint's
    /// turn times the slope's size, added up, grown by [`grow`](Self::grow).
    fn gained(&self, slope: &Slopes, delta: &Controlled) -> [f64; MAX_JOINTS] {
        let turn = delta.map(f64::abs);
        std::array::from_fn(|k| {
            let s = slope[k];
            (s[0].abs() * turn[0] + s[1].abs() * turn[1] + s[2].abs() * turn[2]) * self.grow[k]
        })
    }
}

/// How fast (rad per whole move by `delta`) each joint turns along the move from `start`
/// up to the fraction `up_to`: the learned joints by their share, each wrist joint as fast
/// as the samples in `pace::pieces` show (a piece's turn, whole turns of a wrapped angle
/// aside, and its slopes at each sample) grown by [`SAMPLED_MARGIN`]. Where a two-joint
/// wrist passes its singular poses between two samples (the side its two joints' tilts
/// lie on turns over), the crossing is bisected [`CROSSING_BISECTIONS`] times, each half's
/// turn taken: the wrist swings fastest there. Each wrist joint's turn is at least the
/// second and third learned joints' turns together ([`drift_floor`]).
fn sampled_turns(
    model: &ArmModel,
    start: &MoveStart,
    delta: &Controlled,
    up_to: f64,
) -> [f64; MAX_JOINTS] {
    let mut samples = Samples {
        model,
        start,
        delta,
        turns: [0.0; MAX_JOINTS],
    };
    for (i, &j) in model.learned().iter().enumerate() {
        samples.turns[j] = delta[i].abs();
    }
    let mut last = start.pose.wrist_found.then(|| {
        let side = samples.slopes(&start.pose.joints);
        (0.0, start.pose.joints, side)
    });
    if up_to <= 0.0 {
        return samples.turns;
    }
    let n = pieces(delta.amax() * up_to);
    let mut near = start.pose.joints;
    for piece in 1..=n {
        let s = up_to * piece as f64 / n as f64;
        let Some((q, side)) = samples.look(s, &near) else {
            last = None;
            continue;
        };
        near = q;
        if let Some((before, q_before, side_before)) = last {
            samples.piece(before, &q_before, s, &q);
            if (side < 0.0) != (side_before < 0.0) {
                samples.crossing((before, q_before, side_before), (s, q));
            }
        }
        last = Some((s, q, side));
    }
    drift_floor(model, delta, &mut samples.turns);
    samples.turns
}

/// Raises each wrist joint's sampled turn in `turns` to at least the second and third
/// learned joints' turns together (`delta`'s). Near a two-joint wrist's singular pose its
/// weak joint drifts with the pose it is solved from (the tilt across it is left, up to
/// `LOOSE_RAD`), which samples a piece apart cannot see: on the xArm7, 5 of 300 seeded
/// moves turned joint 5 by 0.007–0.08 rad against a sampled 0.0001–0.003, each under half
/// this floor.
fn drift_floor(model: &ArmModel, delta: &Controlled, turns: &mut [f64; MAX_JOINTS]) {
    let floor = delta.y.abs() + delta.z.abs();
    for k in model.wrist().solved() {
        turns[k] = turns[k].max(floor);
    }
}

/// The wrist's turns found so far along a move (see [`sampled_turns`]).
struct Samples<'a> {
    model: &'a ArmModel,
    start: &'a MoveStart,
    delta: &'a Controlled,
    /// Each joint's fastest turn (rad per whole move), grown by [`SAMPLED_MARGIN`].
    turns: [f64; MAX_JOINTS],
}

impl Samples<'_> {
    /// Takes joint `k` turning at `rate` (rad per whole move).
    fn fastest(&mut self, k: usize, rate: f64) {
        self.turns[k] = self.turns[k].max(rate * SAMPLED_MARGIN);
    }

    /// The joints at fraction `s` of the move, solved from `near`, with the wrist's side
    /// there ([`wrist_at`]), its slopes taken; `None` where the wrist has no solution.
    fn look(&mut self, s: f64, near: &Joints) -> Option<(Joints, f64)> {
        let pose = self
            .model
            .pose_near(&(self.start.theta + self.delta * s), near);
        pose.wrist_found
            .then(|| (pose.joints, self.slopes(&pose.joints)))
    }

    /// Takes the wrist's slopes at `q` along the move; gives its side there.
    fn slopes(&mut self, q: &Joints) -> f64 {
        let (slopes, side) = wrist_at(self.model, q);
        if let Some(slopes) = slopes {
            let d = self.delta;
            for k in self.model.wrist().solved() {
                let s = slopes[k];
                self.fastest(k, (s[0] * d[0] + s[1] * d[1] + s[2] * d[2]).abs());
            }
        }
        side
    }

    /// Takes each wrist joint's turn from `qa` at fraction `a` to `qb` at `b`.
    fn piece(&mut self, a: f64, qa: &Joints, b: f64, qb: &Joints) {
        for k in self.model.wrist().solved() {
            let turn = (qb[k] - qa[k] + PI).rem_euclid(TAU) - PI;
            self.fastest(k, turn.abs() / (b - a));
        }
    }

    /// Bisects toward where the wrist's side turns over between `a` (its joints and side)
    /// and `b`, taking each half's turn.
    fn crossing(&mut self, a: (f64, Joints, f64), b: (f64, Joints)) {
        let ((mut a, mut qa, side_a), (mut b, mut qb)) = (a, b);
        for _ in 0..CROSSING_BISECTIONS {
            let m = 0.5 * (a + b);
            let Some((qm, side)) = self.look(m, &qa) else {
                return;
            };
            self.piece(a, &qa, m, &qm);
            self.piece(m, &qm, b, &qb);
            if (side < 0.0) != (side_a < 0.0) {
                (b, qb) = (m, qm);
            } else {
                (a, qa) = (m, qm);
            }
        }
    }
}

/// `s`, or the multiple of [`SNAP`] it lies within [`SNAP_TOLERANCE`] of.
fn snapped(s: f64) -> f64 {
    let near = (s / SNAP).round() * SNAP;
    if (s - near).abs() <= SNAP_TOLERANCE {
        near
    } else {
        s
    }
}

/// Calls `take` with the wrist's slopes at every probe of the grid where it has a solution
/// and is not singular, each probe's solve starting from the last one found.
fn for_each_probe(model: &ArmModel, mut take: impl FnMut(Slopes)) {
    let ranges = model.learned().map(|j| model.joints()[j].one_turn());
    let at = |(lower, upper): (f64, f64), k: usize| {
        lower + (upper - lower) * (k as f64 + 0.5) / PROBES as f64
    };
    let mut near = model.rest();
    for a in 0..PROBES {
        for b in 0..PROBES {
            for c in 0..PROBES {
                let theta = Controlled::new(at(ranges[0], a), at(ranges[1], b), at(ranges[2], c));
                let pose = model.pose_near(&theta, &near);
                if pose.wrist_found {
                    near = pose.joints;
                    slopes_at(model, &pose.joints).map(&mut take);
                }
            }
        }
    }
}

/// d(joint k)/d(learned joint i) at the pose `q`, whose optical axis points down: the
/// wrist joints turn so that the learned joints' turns tilt the axis not at all (each
/// joint tilts it by the part of its axis across it; least squares where the wrist has
/// more joints than it needs). `None` where the wrist is singular.
fn slopes_at(model: &ArmModel, q: &Joints) -> Option<Slopes> {
    wrist_at(model, q).0
}

/// The wrist's slopes at `q` ([`slopes_at`]), and its side: for a wrist of two joints, the
/// optical axis against the cross product of the two joints' tilts (its sign turns over
/// where the line of a move passes its singular poses); NaN for another.
fn wrist_at(model: &ArmModel, q: &Joints) -> (Option<Slopes>, f64) {
    let frames = model.link_frames(q);
    let optical = (frames.last() * model.camera_mount()).rotation * Vector3::z();
    let tilting = |k: usize| {
        let axis = frames[k].rotation * model.joints()[k].axis.into_inner();
        tilting(&axis, &optical)
    };
    let (mut solved, mut count) = ([0; 3], 0);
    for k in model.wrist().solved().take(3) {
        solved[count] = k;
        count += 1;
    }
    let wrist = Matrix3::from_fn(|r, c| {
        if c < count {
            tilting(solved[c])[r]
        } else {
            0.0
        }
    });
    let learned = Matrix3::from_columns(&model.learned().map(tilting));
    let unused = Vector3::from_fn(|i, _| if i < count { 0.0 } else { 1.0 });
    let normal = wrist.transpose() * wrist + Matrix3::from_diagonal(&unused);
    let side = match count {
        2 => optical.dot(&wrist.column(0).cross(&wrist.column(1))),
        _ => f64::NAN,
    };
    let Some(follow) = normal.lu().solve(&(wrist.transpose() * learned)) else {
        return (None, side);
    };
    let mut slopes = [[0.0; 3]; MAX_JOINTS];
    for (s, &k) in solved.iter().enumerate().take(count) {
        slopes[k] = [0, 1, 2].map(|i| -follow[(s, i)]);
    }
    (Some(slopes), side)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_oscar6_wrist_follows_theta2_and_theta3_with_slopes_of_one() {
        let model = ArmModel::oscar6();
        let gains = WristGains::new(&model);
        let slope = gains.slope.expect("linear");
        assert_eq!(slope[4], [0.0, 1.0, -1.0]);
        assert_eq!((slope[3], slope[5]), ([0.0; 3], [0.0; 3]));
        assert_eq!(slope[1], [0.0, 1.0, 0.0]);
        // Along a move, θ5 turns by exactly what its slopes give.
        let delta = Controlled::new(0.3, -0.2, 0.5);
        let from = Controlled::new(0.1, 0.4, -0.6);
        let (start, end) = (model.full_pose(&from), model.full_pose(&(from + delta)));
        let exact = gains.linear_turns(&delta, &start, &end).expect("no wrap");
        assert_eq!(exact.as_slice()[..3], [0.3, 0.2, 0.5]);
        assert!((exact[4] - (end[4] - start[4]).abs()).abs() < 1e-12);
        assert!((exact[4] - 0.7).abs() < 1e-12, "{}", exact[4]);
        // A wrist angle wrapped by a whole turn on the way: not exact.
        let mut wrapped = end;
        wrapped[4] -= std::f64::consts::TAU;
        assert_eq!(gains.linear_turns(&delta, &start, &wrapped), None);
    }

    #[test]
    fn the_oscar6_sweep_turns_theta5_by_theta2_and_theta3_together_bit_for_bit() {
        // The turns its golden runs were recorded with: θ5 by |δθ2| + |δθ3|.
        let model = ArmModel::oscar6();
        let gains = WristGains::new(&model);
        let from = Controlled::new(0.1, 0.4, -0.6);
        let start = MoveStart::at(&model, model.pose_of(&from));
        for delta in [
            Controlled::new(0.3, -0.2, 0.5),
            Controlled::new(-1e-7, 3e-5, 0.1),
            Controlled::new(0.0, -0.0, 0.25),
        ] {
            let turns = gains.sweep(&model, &start, &delta, 1.0).turns;
            let mut old = [0.0; MAX_JOINTS];
            (old[0], old[1], old[2]) = (delta.x.abs(), delta.y.abs(), delta.z.abs());
            old[4] = delta.y.abs() + delta.z.abs();
            assert_eq!(turns.map(f64::to_bits), old.map(f64::to_bits), "{delta:?}");
        }
    }

    /// The arm of `urdf` in the public collection at the default arm settings (its
    /// `share/example-robot-data` folder named by `EYEHAND_ROBOT_DATA`, as tests/corpus.rs
    /// reads it; the test fails without it).
    fn corpus_arm(urdf: &str) -> ArmModel {
        let folder = std::env::var_os("EYEHAND_ROBOT_DATA")
            .expect("EYEHAND_ROBOT_DATA names the public robot collection (scripts/test-all.sh)");
        let path = std::path::Path::new(&folder).join("robots").join(urdf);
        crate::robot::description::load_urdf(&path).expect("the arm loads")
    }

    /// The fastest each wrist joint turns (rad per whole move) in any 1/`STEPS` of the move
    /// by `delta` from `from`, solved step by step as the dynamic simulator's set-points
    /// follow it (whole turns of a wrapped angle aside; 0 for the other joints), or `None`
    /// where the wrist loses its solution on the way.
    fn densest_turns(model: &ArmModel, from: &Controlled, delta: &Controlled) -> Option<Joints> {
        const STEPS: usize = 200;
        let mut before = model.pose_of(from).joints;
        let mut fastest = Joints::zeros(model.dof());
        for step in 1..=STEPS {
            let pose = model.pose_near(&(from + delta * (step as f64 / STEPS as f64)), &before);
            if !pose.wrist_found {
                return None;
            }
            for k in model.wrist().solved() {
                let turn = (pose.joints[k] - before[k] + PI).rem_euclid(TAU) - PI;
                fastest[k] = fastest[k].max(turn.abs() * STEPS as f64);
            }
            before = pose.joints;
        }
        Some(fastest)
    }

    /// Seeded moves of up to 0.4 rad a joint from poses across the learned joints' ranges
    /// (`moves` of them, where the wrist keeps its solution): each one's `delta`, its
    /// wrist's fastest turns step by step ([`densest_turns`]) and its sweep's turns.
    fn seeded_moves(model: &ArmModel, moves: usize) -> Vec<(Controlled, Joints, Joints)> {
        use rand::{Rng, SeedableRng};
        let gains = WristGains::new(model);
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(1);
        let ranges = model.learned().map(|j| model.joints()[j].one_turn());
        let mut made = Vec::new();
        while made.len() < moves {
            let from = Controlled::from_fn(|i, _| rng.random_range(ranges[i].0..ranges[i].1));
            let delta = Controlled::from_fn(|_, _| rng.random_range(-0.4..0.4));
            let start = MoveStart::at(model, model.pose_of(&from));
            if !start.pose.wrist_found {
                continue;
            }
            if let Some(dense) = densest_turns(model, &from, &delta) {
                let turns = gains.sweep(model, &start, &delta, 1.0).turns;
                made.push((delta, dense, Joints::from_fn(model.dof(), |k| turns[k])));
            }
        }
        made
    }

    /// How many of `moves` turn a wrist joint faster than the second and third learned
    /// joints together (the OSCAR-6's bound, not one on other arms),
    /// and how many faster than their sweep says.
    fn beyond(moves: &[(Controlled, Joints, Joints)]) -> (usize, usize) {
        let faster = |(delta, dense, _): &&(Controlled, Joints, Joints)| {
            dense.amax() > delta.y.abs() + delta.z.abs() + 1e-9
        };
        let outside = |(_, dense, turns): &&(Controlled, Joints, Joints)| {
            dense.iter().zip(turns.iter()).any(|(d, t)| d > &(t + 1e-9))
        };
        (
            moves.iter().filter(faster).count(),
            moves.iter().filter(outside).count(),
        )
    }

    /// [`beyond`] over 300 seeded moves of the collection's arm `urdf`, whose wrist does
    /// not follow its learned joints linearly (its sweep is sampled).
    fn sampled_beyond(urdf: &str) -> (usize, usize) {
        let model = corpus_arm(urdf);
        assert!(WristGains::new(&model).slope.is_none(), "linear");
        beyond(&seeded_moves(&model, 300))
    }

    #[test]
    fn a_wrist_joint_turning_faster_than_theta2_and_theta3_stays_within_its_sweep() {
        // The SO-100's wrist: its joints 4 and 5, solved by Newton steps.
        let (faster, outside) = sampled_beyond("so_arm_description/urdf/so100.urdf");
        assert!(faster > 30, "{faster} of 300 moves beyond θ2 + θ3");
        assert_eq!(outside, 0, "moves beyond their sweep");
    }

    #[test]
    fn the_xarm7s_wrist_swinging_past_its_singular_pose_stays_within_its_sweep() {
        // The xArm7's wrist (its joints 5 and 6) sits near its singular pose, joint 5 at 0:
        // where a move passes it, the crossing's bisection finds the swing, and near it the
        // weak joint's drift with the pose it is solved from stays under the second and
        // third learned joints' turns together (drift_floor); without that floor 5 of
        // these 300 moves turn joint 5 beyond their sampled sweep.
        let (faster, outside) = sampled_beyond("xarm_description/urdf/xarm7.urdf");
        assert!(faster > 15, "{faster} of 300 moves beyond θ2 + θ3");
        assert_eq!(outside, 0, "moves beyond their sweep");
    }
}
