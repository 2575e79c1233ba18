//! A move's pace: the lead joint's top speed is `robot_speed`, lowered where a joint of the
//! chain (learned, or following the wrist's solution) would otherwise turn faster than its
//! URDF velocity limit somewhere along the move's line.

use super::motion::TrapezoidProfile;
use crate::robot::Joints;

/// The share of a joint's URDF velocity limit a move plans it to at most: the servos'
/// following error rides on top of the set-point's speed. (The OSCAR-6's learned joints,
/// limited to 91.7°/s, keep the default 90°/s.)
pub(crate) const LIMIT_SHARE: f64 = 0.99;

/// Pieces per radian of the lead joint's turn in which a move's line is sampled for the
/// following joints' rates (one every 3.6°: about seven control ticks of a move at 90°/s).
const PIECES_PER_RAD: f64 = 16.0;

/// The most pieces a move's line is sampled in.
const MOST_PIECES: usize = 128;
/// Pieces a long move's line is sampled in first: a move whose coarse rates, grown by
/// [`COARSE_MARGIN`], keep every joint within its limit is not sampled finely (most moves;
/// on the OSCAR-6, whose wrist follows θ2 and θ3 linearly, the coarse rates are exact).
pub(crate) const COARSE_PIECES: usize = 4;
/// How much faster than its coarse sampling shows a joint may turn somewhere along a move.
pub(crate) const COARSE_MARGIN: f64 = 1.1;
/// The most sampling can make a joint's turn per whole move exceed its exact turn (rad):
/// the rounding of the sampled angles (about 1e-15 rad each) times at most [`MOST_PIECES`],
/// with room. A move whose exact turns, grown by this, keep every joint within its limit
/// runs at `robot_speed` whatever its sampling would show.
pub(crate) const SAMPLING_SLACK: f64 = 1e-9;

/// The profile of a move whose lead joint turns `distance` (rad) at up to `speed` (rad/s),
/// accelerating at `accel` (rad/s²), where each joint k turns at most `rates[k]` (rad per
/// whole move, in any part of it) and may turn at most `limits[k]` fast (rad/s; not
/// positive or not finite: no limit): the profile at `speed` itself wherever no joint would
/// exceed [`LIMIT_SHARE`] of its limit, else at the highest lead speed that keeps every
/// joint within it.
pub(crate) fn paced_profile(
    distance: f64,
    speed: f64,
    accel: f64,
    rates: &Joints,
    limits: impl IntoIterator<Item = f64>,
) -> TrapezoidProfile {
    let distance = distance.abs();
    // Joint k turns at rates[k] / distance times the lead joint's speed.
    let allowed = rates
        .iter()
        .zip(limits)
        .filter(|&(&rate, limit)| rate > 0.0 && limit > 0.0 && limit.is_finite())
        .map(|(&rate, limit)| LIMIT_SHARE * limit * distance / rate)
        .fold(speed, f64::min);
    TrapezoidProfile::new(distance, allowed, accel)
}

/// How many pieces a move whose lead joint turns `distance` (rad) is sampled in.
pub(crate) fn pieces(distance: f64) -> usize {
    ((distance.abs() * PIECES_PER_RAD).ceil() as usize).clamp(1, MOST_PIECES)
}

/// The most each joint turns per whole move in any of `n` equal pieces of it, from the
/// joints at its start (`start`) and at each piece's end (`at(s)` for s = 1/n … 1, in
/// order): the largest turn of a piece times `n`. Angles that are not finite (no wrist
/// solution there) count no turn.
pub(crate) fn turn_rates(start: &Joints, n: usize, mut at: impl FnMut(f64) -> Joints) -> Joints {
    let mut rates = Joints::zeros(start.len());
    let mut last = *start;
    for k in 1..=n {
        let next = at(k as f64 / n as f64);
        for j in 0..start.len() {
            let turn = (next[j] - last[j]).abs() * n as f64;
            if turn.is_finite() {
                rates[j] = rates[j].max(turn);
            }
        }
        last = next;
    }
    rates
}

#[cfg(test)]
mod tests {
    use super::*;

    const DEG: f64 = std::f64::consts::PI / 180.0;

    /// The largest speed (rad/s) of each joint over the profile, sampled every 1 ms, for
    /// a joint k that moves `rates[k]` × the move's fraction (a straight line).
    fn peak_speeds(profile: &TrapezoidProfile, rates: &Joints) -> Joints {
        let h = 1e-3;
        let steps = (profile.duration() / h).ceil() as usize;
        let fastest = (0..steps)
            .map(|k| {
                (profile.fraction_at((k + 1) as f64 * h) - profile.fraction_at(k as f64 * h)) / h
            })
            .fold(0.0, f64::max);
        rates.map(|rate| rate * fastest)
    }

    #[test]
    fn a_move_within_every_limit_keeps_its_speed_bit_for_bit() {
        // A 40° lead at 90°/s; the others at most 60°/s; limits 91.7°/s (the OSCAR-6's).
        let rates = Joints::from([40.0 * DEG, 30.0 * DEG, 10.0 * DEG]);
        let limits = [1.6, 1.6, 1.6];
        let paced = paced_profile(40.0 * DEG, 90.0 * DEG, 180.0 * DEG, &rates, limits);
        assert_eq!(
            paced,
            TrapezoidProfile::new(40.0 * DEG, 90.0 * DEG, 180.0 * DEG)
        );
        // No limit at all (absent from the URDF: infinite), or a rate of zero.
        let free = [f64::INFINITY, 0.0, -1.0];
        let paced = paced_profile(40.0 * DEG, 90.0 * DEG, 180.0 * DEG, &rates, free);
        assert_eq!(
            paced,
            TrapezoidProfile::new(40.0 * DEG, 90.0 * DEG, 180.0 * DEG)
        );
    }

    #[test]
    fn a_following_joint_that_would_turn_too_fast_slows_the_move() {
        // The OSCAR-6's θ5 follows θ2 − θ3: θ2 up 30° and θ3 down 30° turn it 60° while
        // the lead turns 30°, twice the lead's speed (180°/s at 90°/s) against 114.6°/s.
        let rates = Joints::from([0.0, 30.0 * DEG, 30.0 * DEG, 0.0, 60.0 * DEG, 0.0]);
        let limits = [1.6, 1.6, 1.6, 2.0, 2.0, 2.5];
        let paced = paced_profile(30.0 * DEG, 90.0 * DEG, 180.0 * DEG, &rates, limits);
        let peaks = peak_speeds(&paced, &rates);
        assert!(peaks[4] <= LIMIT_SHARE * 2.0 + 1e-9, "θ5 at {}", peaks[4]);
        assert!(
            peaks[4] > 0.98 * LIMIT_SHARE * 2.0,
            "θ5 at only {}",
            peaks[4]
        );
        let unpaced = TrapezoidProfile::new(30.0 * DEG, 90.0 * DEG, 180.0 * DEG);
        assert!(peak_speeds(&unpaced, &rates)[4] > 2.0);
        assert!(paced.duration() > unpaced.duration());
    }

    #[test]
    fn a_learned_joint_limited_below_robot_speed_sets_the_pace() {
        // The SO-100: every joint limited to 1 rad/s, below a 90°/s robot_speed.
        let rates = Joints::from([50.0 * DEG, 20.0 * DEG, 5.0 * DEG]);
        let paced = paced_profile(50.0 * DEG, 90.0 * DEG, 180.0 * DEG, &rates, [1.0; 3]);
        let peaks = peak_speeds(&paced, &rates);
        assert!(peaks.amax() <= LIMIT_SHARE + 1e-9 && peaks[0] > 0.98 * LIMIT_SHARE);
    }

    #[test]
    fn turn_rates_take_the_fastest_piece() {
        // A joint that turns along s², 0.5 rad over the move: its last piece is fastest.
        let start = Joints::from([0.0, 1.0]);
        let rates = turn_rates(&start, 4, |s| Joints::from([0.5 * s * s, f64::NAN]));
        assert!((rates[0] - 0.5 * (1.0 - 0.5625) * 4.0).abs() < 1e-12);
        assert_eq!(rates[1], 0.0);
        assert_eq!(pieces(0.0), 1);
        assert_eq!(pieces(10.0), MOST_PIECES);
        assert_eq!(pieces(0.1), 2);
    }
}
