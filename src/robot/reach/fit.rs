//! The reach space fitted to an arm: the study's half annulus, scaled as large as it fits
//! inside the camera positions the arm reaches looking down — wrist solution inside its
//! limits, every link clear of the floor and of the arm's other links, on one branch of
//! the arm's solutions — with a margin; where no such half annulus fits, the largest of
//! other proportions that does.

use crate::robot::contact::contact_free::{ContactRule, Touch};
use crate::robot::model::{Branch, Centre, PoseGrid};
use crate::robot::{ArmModel, ReachSpace};

use super::grid::{Grid, CELL};
/// Learned-joint steps per joint when sampling the shoulder and elbow.
const STEPS: usize = 240;
/// The longest diagonal (m) of a square of neighbouring samples that counts as reached
/// between its corners: longer, the wrist changed its solution between them.
const MAX_EDGE: f64 = 0.1;
/// How far inside the reached set the fitted space stays (m).
const MARGIN: f64 = 0.02;
/// The most branches tried, largest first.
const MAX_BRANCHES: usize = 4;
/// Scales tried, largest first, as fractions of the arm's furthest reach.
const SCALE_STEPS: usize = 200;
/// The smallest fraction tried: a space whose outer radius is under a quarter of the arm's
/// reach is a sliver the study's experiments say nothing about.
const MIN_SCALE_SHARE: f64 = 0.25;

/// A reach space fitted to an arm, and how much of what it reaches it takes.
#[derive(Debug, Clone, PartialEq)]
pub struct ReachFit {
    /// The fitted space.
    pub space: ReachSpace,
    /// The branch of the arm's solutions the space was fitted on (hand it to the arm with
    /// [`ArmModel::keep_branch`] so that its inverse kinematics keeps to it).
    pub branch: Branch,
    /// The share of the reached (r, z) cells inside the fitted space's (r, z) box.
    pub area_share: f64,
    /// Shoulder–elbow poses that were sampled, and how many were usable.
    pub sampled: usize,
    /// Usable poses (wrist solved within limits, clear of the floor and of the arm's own
    /// links, on the branch).
    pub usable: usize,
}

/// A wrist joint whose limits keep the camera from looking down: at how many sampled poses
/// the wrist's solution turns it outside them.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct WristLimit {
    /// The joint.
    pub joint: String,
    /// Its lower limit (°).
    pub lower_deg: f64,
    /// Its upper limit (°).
    pub upper_deg: f64,
    /// Sampled poses at which the wrist's solution turns it outside its limits (the
    /// first wrist joint that is).
    pub poses: usize,
}

/// Why no reach space fits an arm: how many of the sampled shoulder–elbow poses each
/// condition turned away, and how many were left.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct ReachFitFailure {
    /// Shoulder–elbow poses sampled.
    pub sampled: usize,
    /// Poses at which no wrist pose inside the limits keeps the camera looking down.
    pub no_wrist: usize,
    /// Of those, poses at which no angles of the wrist's joints turn the camera down.
    pub no_wrist_solution: usize,
    /// The wrist joint whose limits turned away most of those poses (its solution found,
    /// but outside them), if any did.
    pub wrist_limit: Option<WristLimit>,
    /// Poses free of contact on other branches of the arm's solutions than the largest
    /// (the elbow or the shoulder the other way round), or at an edge between two.
    pub other_branch: usize,
    /// Poses with a link or the camera below the floor, or less than
    /// [`CONTACT_MARGIN`](crate::robot::CONTACT_MARGIN) above it.
    pub below_floor: usize,
    /// Poses in which two links that may touch are less than [`CONTACT_MARGIN`](crate::robot::CONTACT_MARGIN) apart.
    pub in_contact: usize,
    /// Poses left, in which no half annulus fits.
    pub usable: usize,
}

impl std::fmt::Display for ReachFitFailure {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let share = |n: usize| 100.0 * n as f64 / self.sampled.max(1) as f64;
        let unsolved = match self.no_wrist_solution {
            0 => String::new(),
            n => format!(
                "; at {:.0}% no angles of its joints turn the camera down",
                share(n)
            ),
        };
        let limit = self.wrist_limit.as_ref().map_or(String::new(), |limit| {
            format!(
                " (at {:.0}% it would have to turn `{}` outside its limits, {:.0}°..{:.0}°{unsolved})",
                share(limit.poses),
                limit.joint,
                limit.lower_deg,
                limit.upper_deg,
            )
        });
        write!(
            f,
            "of {} shoulder-elbow poses sampled, the wrist could not look down at {:.0}%{limit}, \
             a link was at the floor at {:.0}%, the links touched each other at {:.0}% \
             (closer than 1 cm counts; the shoulder and elbow were sampled 10° inside their \
             limits) and {:.0}% lay on other branches of the arm's solutions than the \
             largest; no half annulus fits in the {} usable ones (of the study's shape, \
             reaching at least a quarter as far as the arm; of others, neither side over four \
             times the other, as large in area)",
            self.sampled,
            share(self.no_wrist),
            share(self.below_floor),
            share(self.in_contact),
            share(self.other_branch),
            self.usable
        )
    }
}

impl ReachSpace {
    /// The study's half annulus scaled as large as it fits inside what `model` reaches
    /// with the camera looking down on one branch of its solutions (the largest of the
    /// few largest in which one fits), its lowest target above `floor_z` (m; the
    /// object hangs `below` m under the camera); when no such space exists, how many
    /// sampled poses each of the conditions turned away.
    pub fn fit(model: &ArmModel, floor_z: f64, below: f64) -> Result<ReachFit, ReachFitFailure> {
        let (samples, mut tally) = reached_points(model, floor_z);
        let signs = samples.grid.signs(&samples.centres);
        let free: Vec<i8> = (0..signs.len())
            .map(|cell| if samples.free[cell] { signs[cell] } else { 0 })
            .collect();
        let branches = samples.grid.components(&free, &samples.centres);
        let free_poses = samples.free.iter().filter(|f| **f).count();
        let on = |cells: &[usize]| {
            let mut centres = vec![None; samples.centres.len()];
            for &cell in cells {
                centres[cell] = samples.centres[cell];
            }
            Samples {
                grid: samples.grid.clone(),
                centres,
                free: Vec::new(),
            }
        };
        let largest = branches.first().map_or(0, Vec::len);
        tally.usable = largest;
        tally.other_branch = free_poses - largest;
        let tried = || branches.iter().take(MAX_BRANCHES);
        let fit_on = |cells, shape| {
            let grid = Grid::new(&on(cells))?;
            Some((fit_in(&grid, floor_z, below, shape)?, cells))
        };
        let best = tried()
            .find_map(|cells| fit_on(cells, Shape::Study))
            .or_else(|| tried().find_map(|cells| fit_on(cells, Shape::Any)));
        let Some(((space, area_share), cells)) = best else {
            return Err(tally);
        };
        Ok(ReachFit {
            space,
            area_share,
            sampled: tally.sampled,
            usable: cells.len(),
            branch: Branch::new(
                samples.grid.clone(),
                cells,
                signs[cells[0]],
                samples.centres[cells[0]].map_or(0, |c| c.side),
            ),
        })
    }
}

/// The proportions a fitted half annulus may have.
#[derive(Debug, Clone, Copy)]
enum Shape {
    /// The study's (r_max − r_min : z_max − z_min = 47 : 52), scaled.
    Study,
    /// Any, each side at least a quarter of the other, no smaller in (r, z) area than the
    /// study's shape at the smallest scale tried ([`MIN_SCALE_SHARE`]).
    Any,
}

/// The largest half annulus of `shape` in `grid` (see [`ReachSpace::fit`]), and the share
/// of the reached cells inside its box.
fn fit_in(grid: &Grid, floor_z: f64, below: f64, shape: Shape) -> Option<(ReachSpace, f64)> {
    let study = ReachSpace::OSCAR6;
    let r_far = grid.cols as f64 * CELL;
    let lowest = (floor_z + below).max(grid.z0);
    let shares = (0..SCALE_STEPS).map(|step| 1.0 - step as f64 / SCALE_STEPS as f64);
    let smallest = r_far / study.r_max * MIN_SCALE_SHARE;
    let found = match shape {
        Shape::Study => shares
            .take_while(|share| *share >= MIN_SCALE_SHARE)
            .find_map(|share| place(grid, r_far / study.r_max * share, lowest)),
        Shape::Any => {
            let area = (study.r_max - study.r_min) * (study.z_max - study.z_min);
            grid.largest_box(lowest, MARGIN, area * smallest * smallest)
        }
    };
    found.map(|space| {
        let r = (space.r_min - MARGIN, space.r_max + MARGIN);
        let z = (space.z_min - MARGIN, space.z_max + MARGIN);
        let inside = grid.count(
            (
                ((z.0 - grid.z0) / CELL) as usize,
                ((z.1 - grid.z0) / CELL) as usize + 1,
            ),
            ((r.0 / CELL) as usize, (r.1 / CELL) as usize + 1),
        );
        (space, inside as f64 / grid.reached as f64)
    })
}

/// The study's half annulus at `scale` placed in `grid` with [`MARGIN`] to spare, its
/// lowest camera height at least `lowest` (m): at the study's radii when it fits there,
/// else moved out by as few cells as it takes; at the middle of the heights it fits at.
fn place(grid: &Grid, scale: f64, lowest: f64) -> Option<ReachSpace> {
    let study = ReachSpace::OSCAR6;
    let height = (study.z_max - study.z_min) * scale;
    let top = grid.z0 + grid.rows as f64 * CELL - height - MARGIN;
    let r_far = grid.cols as f64 * CELL;
    let radii = (0..)
        .map(|k| {
            (
                study.r_min * scale + k as f64 * CELL,
                study.r_max * scale + k as f64 * CELL,
            )
        })
        .take_while(|r| r.1 + MARGIN <= r_far);
    radii.into_iter().find_map(|(r_min, r_max)| {
        let r = (r_min - MARGIN, r_max + MARGIN);
        let fitting: Vec<f64> = (0..)
            .map(|k| lowest + MARGIN + k as f64 * CELL)
            .take_while(|z_min| *z_min <= top)
            .filter(|z_min| grid.covers(r, (z_min - MARGIN, z_min + height + MARGIN)))
            .collect();
        fitting.get(fitting.len() / 2).map(|&z_min| ReachSpace {
            r_min,
            r_max,
            z_min,
            z_max: z_min + height,
        })
    })
}

/// The camera centres of the shoulder–elbow poses of a [`PoseGrid`] whose wrist looks
/// down inside its limits (`None` elsewhere), and which of them are free of contact.
pub(super) struct Samples {
    pub(super) grid: PoseGrid,
    /// `centres[grid.index(i, k)]`: shoulder step i, elbow step k (see [`Centre`]).
    pub(super) centres: Vec<Option<Centre>>,
    /// Whether each pose is free of contact.
    free: Vec<bool>,
}

impl Samples {
    /// The triangles of neighbouring reached samples: two per grid square whose four
    /// corners are reached and lie within [`MAX_EDGE`] of each other.
    pub(super) fn triangles(&self) -> impl Iterator<Item = [(f64, f64); 3]> + '_ {
        let grid = &self.grid;
        let squares = (0..grid.steps).flat_map(move |i| (0..grid.steps).map(move |k| (i, k)));
        squares.flat_map(move |(i, k)| {
            let corners = grid.next(0, i).zip(grid.next(1, k)).and_then(|(i1, k1)| {
                let at = |i: usize, k: usize| self.centres[grid.index(i, k)].map(|c| c.point);
                Some([at(i, k)?, at(i1, k)?, at(i1, k1)?, at(i, k1)?])
            });
            let near = |c: &[(f64, f64); 4]| {
                let d = |a: (f64, f64), b: (f64, f64)| (a.0 - b.0).hypot(a.1 - b.1);
                d(c[0], c[2]).max(d(c[1], c[3])) <= MAX_EDGE
            };
            corners
                .filter(near)
                .into_iter()
                .flat_map(|[a, b, c, d]| [[a, b, c], [a, c, d]])
        })
    }
}

/// The camera centres (r, z) of the shoulder–elbow poses of a `STEPS` × `STEPS` grid
/// whose wrist looks down inside its limits, which of them keep every link
/// [`CONTACT_MARGIN`](crate::robot::CONTACT_MARGIN) clear of `floor_z` and of the links it
/// may touch, and how many poses each condition turned away.
fn reached_points(model: &ArmModel, floor_z: f64) -> (Samples, ReachFitFailure) {
    let grid = PoseGrid::of(model, STEPS);
    let mut tally = ReachFitFailure {
        sampled: STEPS * STEPS,
        ..ReachFitFailure::default()
    };
    let contact = ContactRule::new(model, floor_z);
    let mut free = vec![false; STEPS * STEPS];
    let mut beyond = vec![0; model.dof()];
    let centres = grid.centres(model, |cell, pose, fits| {
        if !fits {
            tally.no_wrist += 1;
            if pose.wrist_found {
                beyond[model.wrist_joint_at_fault(pose)] += 1;
            } else {
                tally.no_wrist_solution += 1;
            }
            return;
        }
        match contact.touch(model, pose) {
            Some(Touch::Floor) => tally.below_floor += 1,
            Some(Touch::Links) => tally.in_contact += 1,
            None => free[cell] = true,
        }
    });
    tally.wrist_limit = wrist_limit(model, &beyond);
    (
        Samples {
            grid,
            centres,
            free,
        },
        tally,
    )
}

/// The joint of `model` that `beyond` (per joint: poses whose wrist solution turns it
/// outside its limits) counts most often, if any.
fn wrist_limit(model: &ArmModel, beyond: &[usize]) -> Option<WristLimit> {
    let (j, &poses) = beyond.iter().enumerate().max_by_key(|(_, n)| **n)?;
    let joint = &model.joints()[j];
    (poses > 0).then(|| WristLimit {
        joint: joint.name.clone(),
        lower_deg: joint.lower.to_degrees(),
        upper_deg: joint.upper.to_degrees(),
        poses,
    })
}
