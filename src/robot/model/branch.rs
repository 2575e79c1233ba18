//! The branch of an arm's solutions its inverse kinematics keeps to: one connected region
//! of shoulder–elbow poses over which the camera's distance from the base axis and its
//! height turn the same way (the sign of ∂(r, z)/∂(θ2, θ3), the wrist following, never
//! changes) and the camera stays on one side of the base axis. Crossing its edge — the
//! elbow passing straight, the camera passing over the base axis — changes the sign, so a
//! camera position reached on the branch is reached by one shoulder–elbow pose on it: the
//! mapping the learners learn has one value. Where the two edges cross (the straight arm
//! over the base axis) the regions of the elbow bent one way on one side and the other way
//! on the other side have the same sign and touch; the side keeps them apart.

use super::{ArmModel, ArmPose, Controlled, Joints};
use nalgebra::Vector3;
use std::f64::consts::TAU;

/// How far (degrees) sampled shoulder and elbow angles stay inside limits that do not go
/// all the way round: poses at a limit leave the learner no room to move past its aim.
const LIMIT_MARGIN_DEG: f64 = 10.0;
/// Steps per joint of the branch an arm gets before any reach space is fitted to it.
const KINEMATIC_STEPS: usize = 48;
/// A determinant (m² per rad²) this close to 0 is on the edge between two branches.
const SINGULAR: f64 = 1e-12;

/// A grid of shoulder–elbow poses over the learned shoulder's and elbow's limits (10°
/// inside limits that do not go all the way round, one turn of those that do), the base
/// yaw at rest.
#[derive(Debug, Clone, PartialEq)]
pub struct PoseGrid {
    /// The lowest angle and the width (rad) sampled of the shoulder, then the elbow.
    spans: [(f64, f64); 2],
    /// Whether the shoulder's and the elbow's steps go all the way round (the last step
    /// neighbours the first).
    pub full_turn: [bool; 2],
    /// Steps per joint.
    pub steps: usize,
}

impl PoseGrid {
    /// The grid of `model`'s learned shoulder and elbow, `steps` per joint.
    pub fn of(model: &ArmModel, steps: usize) -> PoseGrid {
        let [_, s, e] = model.learned();
        let full_turn = [s, e].map(|j| {
            let (lower, upper) = model.joints()[j].one_turn();
            upper - lower >= TAU - 1e-9
        });
        let span = |j: usize, full_turn: bool| {
            let (lower, upper) = model.joints()[j].one_turn();
            let margin = if full_turn {
                0.0
            } else {
                LIMIT_MARGIN_DEG.to_radians()
            };
            (lower + margin, (upper - lower - 2.0 * margin).max(0.0))
        };
        PoseGrid {
            spans: [span(s, full_turn[0]), span(e, full_turn[1])],
            full_turn,
            steps,
        }
    }

    /// The angle (rad) of step `n` of the shoulder (`joint` 0) or the elbow (1).
    pub fn angle(&self, joint: usize, n: usize) -> f64 {
        let (lower, width) = self.spans[joint];
        lower + width * (n as f64 + 0.5) / self.steps as f64
    }

    /// The step nearest `angle` of the shoulder (`joint` 0) or the elbow (1), a full turn's
    /// angle taken by whole turns into its span, any other clamped to it.
    pub fn step_of(&self, joint: usize, angle: f64) -> usize {
        let (lower, width) = self.spans[joint];
        let mut at = (angle - lower) / width * self.steps as f64 - 0.5;
        if self.full_turn[joint] {
            at = at.round().rem_euclid(self.steps as f64);
        }
        at.round().clamp(0.0, (self.steps - 1) as f64) as usize
    }

    /// The index of step `i` of the shoulder and `k` of the elbow in a grid's cells.
    pub fn index(&self, i: usize, k: usize) -> usize {
        i * self.steps + k
    }

    /// The step after `n` (of the shoulder, `joint` 0, or the elbow), round a full turn.
    pub fn next(&self, joint: usize, n: usize) -> Option<usize> {
        match n + 1 {
            m if m < self.steps => Some(m),
            _ if self.full_turn[joint] => Some(0),
            _ => None,
        }
    }

    /// The step before `n`, round a full turn.
    fn previous(&self, joint: usize, n: usize) -> Option<usize> {
        match n.checked_sub(1) {
            Some(m) => Some(m),
            None if self.full_turn[joint] => Some(self.steps - 1),
            None => None,
        }
    }

    /// The grid's four neighbours of cell (`i`, `k`) (fewer at an edge that is a limit).
    fn neighbours(&self, i: usize, k: usize) -> impl Iterator<Item = (usize, usize)> {
        let shoulder = [self.previous(0, i), self.next(0, i)].map(|n| n.map(|n| (n, k)));
        let elbow = [self.previous(1, k), self.next(1, k)].map(|n| n.map(|n| (i, n)));
        shoulder.into_iter().chain(elbow).flatten()
    }

    /// The sign of ∂(r, z)/∂(θ2, θ3) at every cell from the camera centres of the cells
    /// where the wrist was found (`None` elsewhere), by differences with the neighbouring
    /// cells: +1 or −1, 0 where it is singular or cannot be told.
    pub fn signs(&self, centres: &[Option<Centre>]) -> Vec<i8> {
        let point = |cell: usize| centres[cell].map(|c| c.point);
        let derivative = |joint: usize, i: usize, k: usize| {
            let step = |n: Option<usize>| {
                n.and_then(|n| match joint {
                    0 => point(self.index(n, k)),
                    _ => point(self.index(i, n)),
                })
            };
            let here = point(self.index(i, k))?;
            let n = [i, k][joint];
            let (after, before) = (step(self.next(joint, n)), step(self.previous(joint, n)));
            let (a, b, steps) = match (before, after) {
                (Some(b), Some(a)) => (a, b, 2.0),
                (None, Some(a)) => (a, here, 1.0),
                (Some(b), None) => (here, b, 1.0),
                (None, None) => return None,
            };
            let per = steps * self.spans[joint].1 / self.steps as f64;
            Some(((a.0 - b.0) / per, (a.1 - b.1) / per))
        };
        let mut signs = vec![0; self.steps * self.steps];
        for i in 0..self.steps {
            for k in 0..self.steps {
                if let (Some(s), Some(e)) = (derivative(0, i, k), derivative(1, i, k)) {
                    let det = s.0 * e.1 - s.1 * e.0;
                    if det.abs() > SINGULAR {
                        signs[self.index(i, k)] = det.signum() as i8;
                    }
                }
            }
        }
        signs
    }

    /// The connected sets of cells (four-neighbours, round full turns) of one non-zero
    /// sign in `signs` and one side of the base axis (see `side_of`) in `centres`, largest
    /// first.
    pub fn components(&self, signs: &[i8], centres: &[Option<Centre>]) -> Vec<Vec<usize>> {
        let sides: Vec<i8> = centres.iter().map(|c| c.map_or(0, |c| c.side)).collect();
        let mut seen = vec![false; signs.len()];
        let mut found = Vec::new();
        for start in 0..signs.len() {
            if seen[start] || signs[start] == 0 || sides[start] == 0 {
                continue;
            }
            seen[start] = true;
            let (mut cells, mut stack) = (Vec::new(), vec![start]);
            while let Some(cell) = stack.pop() {
                cells.push(cell);
                let (i, k) = (cell / self.steps, cell % self.steps);
                for (a, b) in self.neighbours(i, k) {
                    let next = self.index(a, b);
                    if !seen[next] && signs[next] == signs[start] && sides[next] == sides[start] {
                        seen[next] = true;
                        stack.push(next);
                    }
                }
            }
            found.push(cells);
        }
        found.sort_by_key(|cells| std::cmp::Reverse(cells.len()));
        found
    }

    /// The camera centres of the grid's poses of `model` whose wrist keeps the camera
    /// looking down inside its limits, each wrist solved from its neighbour's, outwards
    /// from the rest pose, so that the whole grid keeps the rest pose's wrist branch.
    /// `visit` sees every pose with its cell's index and whether its wrist fits. Indexed
    /// by [`index`](Self::index); `None` where the wrist does not fit.
    pub fn centres(
        &self,
        model: &ArmModel,
        mut visit: impl FnMut(usize, &ArmPose, bool),
    ) -> Vec<Option<Centre>> {
        let steps = self.steps;
        let [yaw, s, e] = model.learned();
        let rest = model.rest();
        let (i_rest, k_rest) = (self.step_of(0, rest[s]), self.step_of(1, rest[e]));
        let mut centres = vec![None; steps * steps];
        let mut row_starts: Vec<Joints> = vec![rest; steps];
        for (i, from_row) in outward(i_rest, steps) {
            let start = from_row.map_or(rest, |f| row_starts[f]);
            let mut row = vec![start; steps];
            for (k, from) in outward(k_rest, steps) {
                let near = from.map_or(start, |f| row[f]);
                row[k] = near;
                let theta = Controlled::new(rest[yaw], self.angle(0, i), self.angle(1, k));
                let pose = model.pose_of(&theta);
                let fits = model.wrist_fits(&pose);
                visit(self.index(i, k), &pose, fits);
                if fits {
                    row[k] = pose.joints;
                    let p = pose.camera.translation.vector;
                    centres[self.index(i, k)] = Some(Centre {
                        point: (p.x.hypot(p.y), p.z),
                        side: side_of(model, &pose),
                    });
                }
            }
            row_starts[i] = row[k_rest];
        }
        centres
    }
}

/// The camera centre of a [`PoseGrid`] pose whose wrist looks down inside its limits, and
/// the side of the base axis it lies on.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Centre {
    /// The camera centre (r, z; m).
    pub point: (f64, f64),
    /// The side of the base axis (`side_of`): +1 or −1, 0 on the axis.
    pub side: i8,
}

/// The side of the base axis the camera of `pose` lies on: the sign (+1 or −1) of its
/// distance along the horizontal line across the shoulder's axis (the line the shoulder
/// swings it along), 0 on the axis; +1 when the shoulder's axis is vertical.
pub(crate) fn side_of(model: &ArmModel, pose: &ArmPose) -> i8 {
    let shoulder = model.learned()[1];
    let axis = pose.frames[shoulder].rotation * model.joints()[shoulder].axis.into_inner();
    let across = Vector3::z().cross(&axis);
    if across.norm() < 1e-9 {
        return 1;
    }
    let along = across.dot(&pose.camera.translation.vector);
    if along == 0.0 {
        0
    } else {
        along.signum() as i8
    }
}

/// The steps 0..`steps` from `centre` outwards, up then down, each with the step next to
/// it that it continues from (none for `centre`).
fn outward(centre: usize, steps: usize) -> impl Iterator<Item = (usize, Option<usize>)> {
    let up = (centre + 1..steps).map(|n| (n, Some(n - 1)));
    let down = (0..centre).rev().map(|n| (n, Some(n + 1)));
    std::iter::once((centre, None)).chain(up).chain(down)
}

/// The branch of an arm's solutions: the cells of a [`PoseGrid`] it holds, the sign of
/// ∂(r, z)/∂(θ2, θ3) over them and the side of the base axis (`side_of`) they lie on.
#[derive(Debug, Clone, PartialEq)]
pub struct Branch {
    grid: PoseGrid,
    /// `cells[grid.index(i, k)]`: whether shoulder step i, elbow step k is on the branch.
    cells: Vec<bool>,
    sign: f64,
    side: i8,
    /// The shoulder's and the elbow's angle (rad) at the middle of the branch: a joint
    /// that turns all the way round answers within half a turn of it.
    middle: [f64; 2],
}

impl Branch {
    /// The branch of `grid` made of `cells` (indices), over which ∂(r, z)/∂(θ2, θ3) has
    /// sign `sign` and the camera lies on side `side` of the base axis.
    pub fn new(grid: PoseGrid, cells: &[usize], sign: i8, side: i8) -> Branch {
        let mut on = vec![false; grid.steps * grid.steps];
        for &cell in cells {
            on[cell] = true;
        }
        // The mean direction of each joint's angles over the branch.
        let middle = [0, 1].map(|joint| {
            let (sin, cos) = cells.iter().fold((0.0, 0.0), |(sin, cos), &cell| {
                let n = [cell / grid.steps, cell % grid.steps][joint];
                let angle = grid.angle(joint, n);
                (sin + angle.sin(), cos + angle.cos())
            });
            f64::atan2(sin, cos)
        });
        Branch {
            grid,
            cells: on,
            sign: f64::from(sign),
            side,
            middle,
        }
    }

    /// `angle` of the shoulder (`joint` 0) or the elbow (1) taken by whole turns to within
    /// half a turn of the branch's middle when the joint turns all the way round; any other
    /// angle as it is.
    pub fn wrapped(&self, joint: usize, angle: f64) -> f64 {
        let low = self.middle[joint] - std::f64::consts::PI;
        if self.grid.full_turn[joint] && angle.is_finite() {
            low + (angle - low).rem_euclid(TAU)
        } else {
            angle
        }
    }

    /// The branch `model` gets before a reach space is fitted to it: the largest connected
    /// region of one sign among the poses of a coarse grid whose wrist looks down inside
    /// its limits (contacts not looked at).
    pub(super) fn kinematic(model: &ArmModel) -> Option<Branch> {
        let grid = PoseGrid::of(model, KINEMATIC_STEPS);
        let centres = grid.centres(model, |_, _, _| {});
        let signs = grid.signs(&centres);
        let largest = grid.components(&signs, &centres).into_iter().next()?;
        let side = centres[largest[0]].map_or(0, |c| c.side);
        let sign = signs[largest[0]];
        Some(Branch::new(grid, &largest, sign, side))
    }

    /// True when the shoulder at `theta2` and the elbow at `theta3` (rad) lie on the branch:
    /// the nearest cell, or one next to it, is on it.
    pub fn holds(&self, theta2: f64, theta3: f64) -> bool {
        let grid = &self.grid;
        let (i, k) = (grid.step_of(0, theta2), grid.step_of(1, theta3));
        self.cells[grid.index(i, k)]
            || grid
                .neighbours(i, k)
                .any(|(a, b)| self.cells[grid.index(a, b)])
    }

    /// True when a pose at `theta2`, `theta3` whose ∂(r, z)/∂(θ2, θ3) has determinant `det`
    /// and whose camera lies on side `side` of the base axis lies on the branch.
    pub fn holds_with(&self, theta2: f64, theta3: f64, det: f64, side: i8) -> bool {
        det * self.sign > 0.0 && side == self.side && self.holds(theta2, theta3)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A grid of `steps` per joint over one turn of each, the shoulder's and the elbow's.
    fn full_turns(steps: usize) -> PoseGrid {
        PoseGrid {
            spans: [(-std::f64::consts::PI, TAU); 2],
            full_turn: [true, true],
            steps,
        }
    }

    #[test]
    fn a_full_turn_wraps_its_steps_and_its_neighbours() {
        let grid = full_turns(8);
        assert_eq!(grid.step_of(0, grid.angle(0, 3)), 3);
        assert_eq!(grid.step_of(0, grid.angle(0, 3) + TAU), 3);
        assert_eq!(grid.step_of(1, grid.angle(1, 7) - 2.0 * TAU), 7);
        let around: Vec<_> = grid.neighbours(0, 7).collect();
        assert!(
            around.contains(&(7, 7)) && around.contains(&(0, 0)),
            "{around:?}"
        );
    }

    #[test]
    fn the_sign_of_a_two_link_arm_splits_at_the_straight_elbow() {
        // A planar two-link arm (upper arm 1, forearm 0.6) reaching from the base axis:
        // r, z of the hand; the sign flips where the elbow passes straight (θ3 = 0, π).
        let grid = full_turns(36);
        let centres: Vec<_> = (0..36 * 36)
            .map(|cell| {
                let (s, e) = (grid.angle(0, cell / 36), grid.angle(1, cell % 36));
                let (r, z) = (s.cos() + 0.6 * (s + e).cos(), s.sin() + 0.6 * (s + e).sin());
                let point = (r.abs() + 2.0, z);
                Some(Centre { point, side: 1 })
            })
            .collect();
        let signs = grid.signs(&centres);
        let components = grid.components(&signs, &centres);
        let elbow_sign = |k: usize| signs[grid.index(5, k)];
        assert_ne!(elbow_sign(9), elbow_sign(27), "elbow one way and the other");
        // The hand's r is kept away from the axis, so only the elbow splits the grid.
        assert_eq!(
            components.len(),
            2,
            "{:?}",
            components.iter().map(Vec::len).collect::<Vec<_>>()
        );
        let branch = Branch::new(grid.clone(), &components[0], signs[components[0][0]], 1);
        let cell = components[0][components[0].len() / 2];
        let (s, e) = (grid.angle(0, cell / 36), grid.angle(1, cell % 36));
        assert!(branch.holds(s, e) && branch.holds(s + TAU, e - TAU));
        let det = f64::from(signs[cell]);
        assert!(!branch.holds_with(s, e, -det, 1));
        assert!(branch.holds_with(s, e, det, 1) && !branch.holds_with(s, e, det, -1));
    }
}
