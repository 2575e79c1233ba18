//! The reach space fitted to an arm: the study's half annulus, scaled as large as it fits
//! inside the camera positions the arm reaches looking down — wrist solution inside its
//! limits, elbow up, every link above the floor — with a margin.

use super::collision::{body_elements, lowest_point};
use super::{ArmModel, Controlled, ReachSpace};

/// Grid cell of the reached (r, z) set (m).
const CELL: f64 = 0.01;
/// Learned-joint steps per joint when sampling the shoulder and elbow.
const STEPS: usize = 240;
/// How far inside the reached set the fitted space stays (m).
const MARGIN: f64 = 0.02;
/// Scales tried, largest first, as fractions of the arm's furthest reach.
const SCALE_STEPS: usize = 200;

/// A reach space fitted to an arm, and how much of what it reaches it takes.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ReachFit {
    /// The fitted space.
    pub space: ReachSpace,
    /// The share of the reached (r, z) cells inside the fitted space's (r, z) box.
    pub area_share: f64,
    /// Shoulder–elbow poses that were sampled, and how many were usable.
    pub sampled: usize,
    /// Usable poses (wrist solved within limits, elbow up, above the floor).
    pub usable: usize,
}

/// Why no reach space fits an arm: how many of the sampled shoulder–elbow poses each
/// condition turned away, and how many were left.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct ReachFitFailure {
    /// Shoulder–elbow poses sampled.
    pub sampled: usize,
    /// Poses at which no wrist pose inside the limits keeps the camera looking down.
    pub no_wrist: usize,
    /// Poses with the elbow not up (or the wrist behind the base).
    pub elbow_down: usize,
    /// Poses with a link or the camera below the floor.
    pub below_floor: usize,
    /// Poses left, in which no half annulus of the study's shape fits.
    pub usable: usize,
}

impl std::fmt::Display for ReachFitFailure {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let share = |n: usize| 100.0 * n as f64 / self.sampled.max(1) as f64;
        write!(
            f,
            "of {} shoulder-elbow poses sampled, the wrist could not look down at {:.0}%, \
             the elbow was not up at {:.0}% and a link was below the floor at {:.0}%; \
             no half annulus of the study's shape fits in the {} usable ones",
            self.sampled,
            share(self.no_wrist),
            share(self.elbow_down),
            share(self.below_floor),
            self.usable
        )
    }
}

/// The reached (r, z) cells: `rows` of `cols`, row 0 at `z0`, column 0 at r = 0.
struct Grid {
    z0: f64,
    rows: usize,
    cols: usize,
    /// Prefix sums of reached cells: `sums[(row) * (cols + 1) + col]` counts rows < row,
    /// cols < col.
    sums: Vec<u32>,
    reached: usize,
}

impl Grid {
    fn new(points: &[(f64, f64)]) -> Option<Grid> {
        let z_low = points.iter().map(|p| p.1).fold(f64::INFINITY, f64::min);
        let z_high = points.iter().map(|p| p.1).fold(f64::NEG_INFINITY, f64::max);
        let r_high = points.iter().map(|p| p.0).fold(0.0, f64::max);
        if !(z_low.is_finite() && z_high.is_finite()) {
            return None;
        }
        let rows = ((z_high - z_low) / CELL) as usize + 1;
        let cols = (r_high / CELL) as usize + 1;
        let mut hit = vec![false; rows * cols];
        for &(r, z) in points {
            hit[((z - z_low) / CELL) as usize * cols + (r / CELL) as usize] = true;
        }
        let mut sums = vec![0u32; (rows + 1) * (cols + 1)];
        for row in 0..rows {
            for col in 0..cols {
                let at = |r: usize, c: usize| sums[r * (cols + 1) + c];
                sums[(row + 1) * (cols + 1) + col + 1] = at(row, col + 1) + at(row + 1, col)
                    - at(row, col)
                    + u32::from(hit[row * cols + col]);
            }
        }
        let reached = hit.iter().filter(|h| **h).count();
        Some(Grid {
            z0: z_low,
            rows,
            cols,
            sums,
            reached,
        })
    }

    /// Reached cells in rows `r0..r1`, columns `c0..c1`.
    fn count(&self, (r0, r1): (usize, usize), (c0, c1): (usize, usize)) -> u32 {
        let at = |r: usize, c: usize| self.sums[r * (self.cols + 1) + c];
        at(r1, c1) + at(r0, c0) - at(r0, c1) - at(r1, c0)
    }

    /// True when every cell meeting the box r_min..r_max, z_min..z_max is reached.
    fn covers(&self, r: (f64, f64), z: (f64, f64)) -> bool {
        let col = |v: f64| (v / CELL).floor();
        let row = |v: f64| ((v - self.z0) / CELL).floor();
        let (c0, c1, r0, r1) = (col(r.0), col(r.1) + 1.0, row(z.0), row(z.1) + 1.0);
        if c0 < 0.0 || r0 < 0.0 || c1 > self.cols as f64 || r1 > self.rows as f64 {
            return false;
        }
        let (c0, c1, r0, r1) = (c0 as usize, c1 as usize, r0 as usize, r1 as usize);
        self.count((r0, r1), (c0, c1)) as usize == (r1 - r0) * (c1 - c0)
    }
}

impl ReachSpace {
    /// The study's half annulus scaled as large as it fits inside what `model` reaches
    /// with the camera looking down, its lowest target above `floor_z` (m; the object
    /// hangs `below` m under the camera); when no such space exists, how many sampled
    /// poses each of the conditions turned away.
    pub fn fit(model: &ArmModel, floor_z: f64, below: f64) -> Result<ReachFit, ReachFitFailure> {
        let (points, tally) = reached_points(model, floor_z);
        let usable = points.len();
        let grid = Grid::new(&points).ok_or(tally)?;
        let study = ReachSpace::OSCAR6;
        let r_far = grid.cols as f64 * CELL;
        let lowest = (floor_z + below).max(grid.z0);
        for step in 0..SCALE_STEPS {
            let scale = r_far / study.r_max * (1.0 - step as f64 / SCALE_STEPS as f64);
            let (r_min, r_max) = (study.r_min * scale, study.r_max * scale);
            let height = (study.z_max - study.z_min) * scale;
            let r = (r_min - MARGIN, r_max + MARGIN);
            let top = grid.z0 + grid.rows as f64 * CELL - height - MARGIN;
            let fitting: Vec<f64> = (0..)
                .map(|k| lowest + MARGIN + k as f64 * CELL)
                .take_while(|z_min| *z_min <= top)
                .filter(|z_min| grid.covers(r, (z_min - MARGIN, z_min + height + MARGIN)))
                .collect();
            // The middle of the heights it fits at.
            let Some(&z_min) = fitting.get(fitting.len() / 2) else {
                continue;
            };
            let z = (z_min - MARGIN, z_min + height + MARGIN);
            let space = ReachSpace {
                r_min,
                r_max,
                z_min,
                z_max: z_min + height,
            };
            let inside = grid.count(
                (
                    ((z.0 - grid.z0) / CELL) as usize,
                    ((z.1 - grid.z0) / CELL) as usize + 1,
                ),
                ((r.0 / CELL) as usize, (r.1 / CELL) as usize + 1),
            );
            return Ok(ReachFit {
                space,
                area_share: inside as f64 / grid.reached as f64,
                sampled: tally.sampled,
                usable,
            });
        }
        Err(tally)
    }
}

/// The camera centres (r, z) of shoulder–elbow poses on a grid inside the limits (the
/// base yaw at rest: turning it moves the camera about the base's z axis only) whose
/// wrist is solved inside its limits, elbow up, with every link above `floor_z`; and how
/// many poses each condition turned away.
fn reached_points(model: &ArmModel, floor_z: f64) -> (Vec<(f64, f64)>, ReachFitFailure) {
    let [yaw, s, e] = model.learned();
    let span = |j: usize| {
        let (lower, upper) = model.joints()[j].one_turn();
        (lower, upper - lower)
    };
    let (shoulder, elbow) = (span(s), span(e));
    let mut tally = ReachFitFailure {
        sampled: STEPS * STEPS,
        ..ReachFitFailure::default()
    };
    let bodies: Vec<_> = (1..=model.dof()).map(|k| body_elements(model, k)).collect();
    let base_yaw = model.rest()[yaw];
    let mut points = Vec::new();
    let at = |(lower, width): (f64, f64), n: usize| lower + width * (n as f64 + 0.5) / STEPS as f64;
    for i in 0..STEPS {
        let mut near = model.rest();
        for k in 0..STEPS {
            let theta = Controlled::new(base_yaw, at(shoulder, i), at(elbow, k));
            let pose = model.pose_near(&theta, &near);
            if !model.wrist_fits(&pose) {
                tally.no_wrist += 1;
                continue;
            }
            near = pose.joints;
            if !model.is_elbow_up(&theta) {
                tally.elbow_down += 1;
                continue;
            }
            if lowest_point(model, &bodies, &pose.joints) < floor_z {
                tally.below_floor += 1;
                continue;
            }
            let p = pose.camera.translation.vector;
            points.push((p.x.hypot(p.y), p.z));
        }
    }
    tally.usable = points.len();
    (points, tally)
}
