//! Which wrist joints keep the camera looking down, chosen once per arm: one joint in
//! closed form where it can do it alone, else the two (or one) of the last three wrist
//! joints, with the others held at the angles, that look down at most test poses.

use super::look_down::tilt_angle;
use super::{reference_angles, Wrist};
use crate::robot::model::{ArmModel, Controlled, Joints};

/// A closed-form wrist must leave at most this tilt (rad) at every test pose.
const ONE_JOINT_TOLERANCE_RAD: f64 = 1e-9;
/// Test poses per learned joint when deciding whether one joint can do the wrist's work.
const TEST_STEPS: usize = 4;
/// Test poses per shoulder and elbow when scoring a numerical wrist.
const SCORE_STEPS: usize = 6;
/// Angles tried for a held joint besides its rest angle, evenly over its limits.
const HOLD_STEPS: usize = 8;

impl Wrist {
    /// The shoulder–elbow poses a numerical wrist is scored at.
    pub const POSES_TRIED: usize = SCORE_STEPS * SCORE_STEPS;

    /// The wrist of `model` and the rest angles it holds its other joints at: one joint in
    /// closed form when it keeps the camera looking down at every test pose; else the
    /// two (or, when no two do, one) of the last three wrist joints, solved by Newton
    /// steps, with the others at the angles from their rest and a grid over their limits,
    /// that look down inside the limits at most test poses (the first such: solved joints
    /// nearest the end, held joints at rest, first).
    pub(in crate::robot::model) fn choose(model: &ArmModel) -> (Wrist, Joints) {
        let wrist: Vec<usize> = (0..model.dof())
            .filter(|i| !model.learned.contains(i))
            .collect();
        if wrist.is_empty() {
            return (Wrist::None, model.rest);
        }
        let one_joint = wrist
            .iter()
            .map(|&j| Wrist::OneJoint(j))
            .find(|candidate| candidate.keeps_vertical(model));
        if let Some(found) = one_joint {
            return (found, model.rest);
        }
        let last = &wrist[wrist.len().saturating_sub(3)..];
        let mut trial = model.clone();
        let mut best: Option<(usize, Wrist, Joints)> = None;
        for count in (1..=last.len().min(2)).rev() {
            for solved in subsets(last, count) {
                let mut joints = [0; 3];
                joints[..count].copy_from_slice(&solved);
                let candidate = Wrist::Numerical { joints, count };
                let held: Vec<usize> = last
                    .iter()
                    .copied()
                    .filter(|j| !solved.contains(j))
                    .collect();
                for rest in hold_grid(model, &held) {
                    let score = candidate.score(&mut trial, &rest);
                    if best.as_ref().is_none_or(|(top, ..)| score > *top) {
                        best = Some((score, candidate, rest));
                    }
                }
            }
            if best.as_ref().is_some_and(|(top, ..)| *top > 0) {
                break;
            }
        }
        let (_, chosen, rest) = best.expect("at least one wrist joint");
        (chosen, rest)
    }

    /// True when `model`'s wrist looks down inside its limits at one or more of the
    /// shoulder–elbow poses it was chosen by, at least.
    pub(in crate::robot::model) fn looks_down_somewhere(model: &ArmModel) -> bool {
        model.wrist != Wrist::None && model.wrist.score(&mut model.clone(), &model.rest) > 0
    }

    /// True when this wrist turns the optical axis straight down at a grid of learned
    /// poses inside the limits.
    fn keeps_vertical(&self, model: &ArmModel) -> bool {
        let span = |j: usize| {
            let (lower, upper) = model.joints[j].one_turn();
            (lower, upper - lower)
        };
        (0..TEST_STEPS.pow(3)).all(|k| {
            let theta = Controlled::from_fn(|i, _| {
                let (lower, width) = span(model.learned[i]);
                let step = (k / TEST_STEPS.pow(i as u32)) % TEST_STEPS;
                lower + width * (step as f64 + 0.5) / TEST_STEPS as f64
            });
            let level = model.with_learned(&theta);
            let pose = self.solve(model, &theta, model.link_frames(&level), &level);
            tilt_angle(&pose.camera) <= ONE_JOINT_TOLERANCE_RAD
        })
    }

    /// How many of a grid of shoulder–elbow poses (the base yaw in the middle of its
    /// limits) this wrist looks down at inside its limits, exactly even near a singularity
    /// (its rest angles the start), with its other joints at `rest`; `trial` is the model,
    /// its rest angles and wrist set here.
    fn score(&self, trial: &mut ArmModel, rest: &Joints) -> usize {
        trial.rest = *rest;
        trial.wrist = *self;
        let middle = reference_angles(trial);
        let [_, s, e] = trial.learned;
        let at = |j: usize, n: usize| {
            let (lower, upper) = trial.joints[j].one_turn();
            lower + (upper - lower) * (n as f64 + 0.5) / SCORE_STEPS as f64
        };
        let mut found = 0;
        for i in 0..SCORE_STEPS {
            for k in 0..SCORE_STEPS {
                let theta = Controlled::new(middle.x, at(s, i), at(e, k));
                let level = trial.with_learned(&theta);
                let frames = trial.link_frames(&level);
                let pose = self.solve_as(trial, &theta, frames, &trial.rest, true);
                if trial.wrist_fits(&pose) {
                    found += 1;
                }
            }
        }
        found
    }
}

/// The rest angles with the `held` joints at their rest angle and then at each of a grid
/// over their limits (every combination).
fn hold_grid(model: &ArmModel, held: &[usize]) -> Vec<Joints> {
    let mut grid = vec![model.rest];
    for &j in held {
        let (lower, upper) = model.joints[j].one_turn();
        let angles: Vec<f64> = std::iter::once(model.rest[j])
            .chain((0..HOLD_STEPS).map(|n| lower + (upper - lower) * n as f64 / HOLD_STEPS as f64))
            .collect();
        grid = grid
            .iter()
            .flat_map(|rest| {
                angles.iter().map(move |&angle| {
                    let mut with = *rest;
                    with[j] = angle;
                    with
                })
            })
            .collect();
    }
    grid
}

/// Every `count`-joint subset of `joints` (in chain order), those nearest the end first.
fn subsets(joints: &[usize], count: usize) -> Vec<Vec<usize>> {
    if count == 0 {
        return vec![Vec::new()];
    }
    let mut found = Vec::new();
    for (i, &last) in joints.iter().enumerate().rev() {
        for mut head in subsets(&joints[..i], count - 1) {
            head.push(last);
            found.push(head);
        }
    }
    found
}
