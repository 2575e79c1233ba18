//! Where a move first would bring two of the arm's bodies, or a link and an obstacle,
//! into contact: marched in steps no pair can close its gap in, then bisected.

use super::clearance::{ArmGeometry, MAX_BODIES};
use super::collision::MoveStart;
use super::reaches::Sweep;
use super::world::Obstacle;
use crate::robot::kinematic::motion::last_holding;
use crate::robot::{ArmModel, MAX_JOINTS};

/// The shortest step of the march (a fraction of the move).
const MIN_MARCH: f64 = 1e-3;
/// The room (m) a known distance bound must leave over what a move can close for the
/// move to go unmeasured.
const KNOWN_GAP_MARGIN: f64 = 1e-9;

impl ArmGeometry {
    /// The most a move whose joints turn by `turns` ([`Sweep::turns`]) can bring any pair
    /// of bodies together (m): what the bodies' distance bound at the start, less this,
    /// still bounds at its end.
    pub(crate) fn closing(&self, turns: &[f64; MAX_JOINTS]) -> f64 {
        self.closing_at(&body_rates(turns))
    }

    /// [`closing`](Self::closing) with the bodies' joints turning at `rates`.
    fn closing_at(&self, rates: &[f64; MAX_BODIES]) -> f64 {
        self.pairs
            .iter()
            .map(|&(i, j)| self.pair_speed(rates, i, j))
            .fold(0.0, f64::max)
    }

    /// How far along the controlled move from every joint at `start` along `sweep`
    /// (fractions of `sweep.delta` up to `up_to`) the arm gets before two of its bodies or
    /// a link and an obstacle touch: `up_to` when none do, or when they already touch at
    /// the start. Marches in steps no pair can close in, then bisects the contact. A point
    /// of body j moves, relative to body i, no faster than the turns of the joints between
    /// them ([`Sweep::turns`]) times its reach from their axes.
    ///
    /// `nearest` is a lower bound (m) on every pair's distance at the start, 0 when none is
    /// known: where it exceeds what the whole move can close and there are no obstacles,
    /// nothing is measured (the march would return `up_to` at its first look). Otherwise it
    /// becomes the smallest distance measured there.
    pub(crate) fn contact_stop(
        &self,
        model: &ArmModel,
        start: &MoveStart,
        sweep: &Sweep,
        up_to: f64,
        obstacles: &[Obstacle],
        nearest: &mut f64,
    ) -> f64 {
        let (theta, delta) = (&start.theta, &sweep.delta);
        // A numerical wrist starts from the last pose looked at.
        let near = std::cell::Cell::new(start.pose.joints);
        let rates = body_rates(&sweep.turns);
        if obstacles.is_empty()
            && *nearest > 0.0
            && *nearest > self.closing_at(&rates) * up_to + KNOWN_GAP_MARGIN
        {
            return up_to;
        }
        let allowance = |s: f64| {
            let pose = model.pose_near(&(theta + delta * s), &near.get());
            near.set(pose.joints);
            self.allowance_at(&pose.frames, &rates, obstacles).0
        };
        let (mut s, (mut now, measured)) = (
            0.0,
            self.allowance_at(&start.pose.frames, &rates, obstacles),
        );
        *nearest = measured.max(0.0);
        if now <= 0.0 {
            return up_to;
        }
        while s < up_to {
            if now >= up_to - s {
                return up_to; // the rest of the move cannot close any gap
            }
            let next = (s + now.max(MIN_MARCH)).min(up_to);
            let then = allowance(next);
            if then <= 0.0 {
                return last_holding(s, next, |middle| {
                    let allow = allowance(middle);
                    allow > 0.0 || allow.is_nan()
                });
            }
            (s, now) = (next, then);
        }
        up_to
    }
}

/// How fast (rad per move) each body's own joint turns with the joints turning at `turns`
/// ([`Sweep::turns`]): body k hangs from joint k - 1; the base (body 0) stays.
pub(super) fn body_rates(turns: &[f64; MAX_JOINTS]) -> [f64; MAX_BODIES] {
    std::array::from_fn(|body| body.checked_sub(1).map_or(0.0, |joint| turns[joint]))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_carried_distance_bound_gives_the_stops_a_fresh_look_gives() {
        use crate::robot::contact::collision::MoveStart;
        use crate::robot::kinematic::wrist_gains::WristGains;
        use crate::robot::Controlled;
        use rand::{Rng, SeedableRng};
        let model = ArmModel::oscar6();
        let geometry = ArmGeometry::new(&model);
        let gains = WristGains::new(&model);
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(3);
        let (lower, upper): (Vec<f64>, Vec<f64>) = model
            .learned()
            .iter()
            .map(|&j| (model.joints()[j].lower, model.joints()[j].upper))
            .unzip();
        let mut theta = Controlled::from_fn(|i, _| 0.5 * (lower[i] + upper[i]));
        let (mut carried, mut skipped, mut stops) = (0.0, 0, 0);
        for _ in 0..400 {
            let goal = Controlled::from_fn(|i, _| rng.random_range(lower[i]..upper[i]));
            // Large moves and small corrections, as a trial makes them.
            let delta = (goal - theta) * [1.0, 0.01, 0.001][rng.random_range(0..3)];
            let start = MoveStart::at(&model, model.pose_of(&theta));
            let sweep = gains.sweep(&model, &start, &delta, 1.0);
            skipped += usize::from(carried > geometry.closing(&sweep.turns) + KNOWN_GAP_MARGIN);
            let fresh = geometry.contact_stop(&model, &start, &sweep, 1.0, &[], &mut 0.0);
            let kept = geometry.contact_stop(&model, &start, &sweep, 1.0, &[], &mut carried);
            assert_eq!(
                fresh.to_bits(),
                kept.to_bits(),
                "from {theta:?} by {delta:?}"
            );
            stops += usize::from(fresh < 1.0);
            let executed = delta * fresh;
            theta += executed;
            let turns = gains.executed_turns(&sweep, &executed, fresh);
            carried = (carried - geometry.closing(&turns)).max(0.0);
        }
        assert!(
            skipped > 100 && stops > 0,
            "{skipped} moves skipped, {stops} stopped"
        );
    }
}
