//! The floor rule both simulators share: how low the arm's collision elements reach, and
//! where a move first would bring one below the floor.

use super::collision::{body_elements, Elements, MoveStart};
use super::reaches::{first_tilt, reaches, sinking_speed, sinking_speeds, Reaches, Sweep};
use crate::robot::kinematic::motion::last_holding;
use crate::robot::{ArmModel, Frames, Joints, Shape, MAX_JOINTS};
use nalgebra::{Isometry3, Vector3};

/// The floor's default height (m, world frame): the bottom of the lowest target — the
/// reach space's lowest camera height 0, less the 20 cm standoff and the 2 cm sphere radius.
pub const DEFAULT_FLOOR_Z: f64 = -0.22;

/// The shortest step of the floor march (a fraction of the move).
const MIN_MARCH: f64 = 1e-3;
/// The room (m) the bound of a whole move must leave above the floor to skip the march.
const FLOOR_MARGIN: f64 = 1e-9;

/// The lowest world height (m) any moving link or the camera reaches at pose `q`, with
/// each body's collision elements (`bodies[k - 1]` for link k).
pub(crate) fn lowest_point(model: &ArmModel, bodies: &[Elements], q: &Joints) -> f64 {
    lowest_of(&model.link_frames(q), bodies)
}

/// The lowest z (m) of the collision elements of links placed at `frames`.
fn lowest_of(frames: &Frames, bodies: &[Elements]) -> f64 {
    frames
        .iter()
        .zip(bodies)
        .map(|(frame, elements)| lowest_of_link(frame, elements))
        .fold(f64::INFINITY, f64::min)
}

/// The lowest z (m) of a link's collision `elements` with the link placed at `frame`.
fn lowest_of_link(frame: &Isometry3<f64>, elements: &Elements) -> f64 {
    elements
        .iter()
        .map(|(p, s)| lowest_z(&(frame * p), s))
        .fold(f64::INFINITY, f64::min)
}

/// The floor rule both simulators share: each link's collision elements and how far the
/// arm reaches beyond each joint, which bound how fast any link can sink in a move.
#[derive(Debug, Clone, Default)]
pub(crate) struct FloorRule {
    /// Each link's collision elements (`bodies[k - 1]` for link k).
    pub bodies: Vec<Elements>,
    reaches: Reaches,
}

impl FloorRule {
    /// The rule for `model` as it is now (its stretched links and turned camera included).
    pub(crate) fn new(model: &ArmModel) -> FloorRule {
        let bodies: Vec<Elements> = (1..=model.dof()).map(|k| body_elements(model, k)).collect();
        let reaches = reaches(model, &bodies);
        FloorRule { bodies, reaches }
    }

    /// Whether no link can get below `floor` (m) anywhere in the move up to fraction
    /// `up_to`, judged at once from the start: each link's lowest point there less how far
    /// that link can sink over the move (`speeds`, from [`link_sinking_speeds`]), with
    /// [`FLOOR_MARGIN`] to spare. The march finds no crossing where this holds.
    fn clear_of_floor(
        &self,
        start: &MoveStart,
        speeds: &[f64; MAX_JOINTS],
        up_to: f64,
        floor: f64,
    ) -> bool {
        let (bodies, reaches) = (&self.bodies, &self.reaches);
        start
            .pose
            .frames
            .iter()
            .zip(bodies)
            .enumerate()
            .all(|(i, (frame, elements))| {
                let k = i + 1;
                let sinking = speeds[i];
                let room = |lowest: f64| lowest - sinking * up_to - floor;
                // No point of the link lies farther from its frame's origin than its own
                // reach: a looser bound, checked first, spares most links the exact one.
                let loose = frame.translation.vector.z - reaches.body[i][k];
                room(loose) > 2.0 * FLOOR_MARGIN
                    || room(lowest_of_link(frame, elements)) > FLOOR_MARGIN
            })
    }

    /// How far along the controlled move from every joint at `start` along `sweep`
    /// (fractions of `sweep.delta` up to `up_to`) the arm gets before a link or the camera
    /// would go below `floor` (m):
    /// `up_to` when none does, or when the arm starts below it. Marches in steps that cannot
    /// skip a dip (each no longer than every link's own clearance over its own sinking speed
    /// allows), then bisects the crossing.
    pub(crate) fn stop(
        &self,
        model: &ArmModel,
        start: &MoveStart,
        sweep: &Sweep,
        up_to: f64,
        floor: f64,
    ) -> f64 {
        let (bodies, reaches) = (&self.bodies, &self.reaches);
        let (theta, delta) = (&start.theta, &sweep.delta);
        // A numerical wrist starts from the last pose looked at.
        let near = std::cell::Cell::new(start.pose.joints);
        // Each link's gap over the floor (m) at fraction `s`, NaN where the wrist fails.
        let gaps = |s: f64| {
            let pose = model.pose_near(&(theta + delta * s), &near.get());
            if pose.wrist_found {
                near.set(pose.joints);
                link_gaps(&pose.frames, bodies, floor)
            } else {
                [f64::NAN; MAX_JOINTS]
            }
        };
        let clearance = |s: f64| lowest_gap(&gaps(s), bodies.len());
        let speeds = link_sinking_speeds(model, reaches, &sweep.turns);
        if start.pose.wrist_found && self.clear_of_floor(start, &speeds, up_to, floor) {
            return up_to;
        }
        let mut s = 0.0;
        let mut gap = if start.pose.wrist_found {
            near.set(start.pose.joints);
            link_gaps(&start.pose.frames, bodies, floor)
        } else {
            [f64::NAN; MAX_JOINTS]
        };
        let links = bodies.len();
        let lowest = lowest_gap(&gap, links);
        if lowest.is_nan() || lowest < 0.0 || sinking_speed(model, reaches, &sweep.turns) == 0.0 {
            return up_to;
        }
        while s < up_to {
            // No link can reach the floor before its own gap over its own sinking speed.
            let safe = (0..links)
                .filter(|&k| speeds[k] > 0.0 || gap[k].is_nan())
                .map(|k| gap[k] / speeds[k])
                .fold(f64::INFINITY, nan_or_min);
            let next = s + safe.max(MIN_MARCH);
            let rest = up_to - s;
            if next >= up_to && (0..links).all(|k| gap[k] >= speeds[k] * rest) {
                return up_to; // the rest of the move cannot reach the floor
            }
            let next = next.min(up_to);
            let next_gap = gaps(next);
            if lowest_gap(&next_gap, links) < 0.0 {
                // (A failed wrist, NaN, counts as above the floor, as in the march.)
                return last_holding(s, next, |middle| {
                    let gap = clearance(middle);
                    gap >= 0.0 || gap.is_nan()
                });
            }
            (s, gap) = (next, next_gap);
        }
        up_to
    }
}

/// Each link's lowest z (m) over `floor` with links placed at `frames` (`bodies[k]` for
/// link k + 1; unused entries infinite).
fn link_gaps(frames: &Frames, bodies: &[Elements], floor: f64) -> [f64; MAX_JOINTS] {
    let mut gaps = [f64::INFINITY; MAX_JOINTS];
    for ((gap, frame), elements) in gaps.iter_mut().zip(frames).zip(bodies) {
        *gap = lowest_of_link(frame, elements) - floor;
    }
    gaps
}

/// The smallest of the first `links` gaps (m), NaN when any is (the wrist failed).
fn lowest_gap(gaps: &[f64; MAX_JOINTS], links: usize) -> f64 {
    gaps[..links]
        .iter()
        .copied()
        .fold(f64::INFINITY, nan_or_min)
}

/// The smaller of `a` and `b`, NaN when either is.
fn nan_or_min(a: f64, b: f64) -> f64 {
    if a.is_nan() || b.is_nan() {
        f64::NAN
    } else {
        a.min(b)
    }
}

/// How fast (m per unit fraction of a move) each link can sink (entry k for link k + 1)
/// with the joints turning at `turns` ([`Sweep::turns`]): its joints' turns times its own
/// reaches ([`Reaches::body`]).
fn link_sinking_speeds(
    model: &ArmModel,
    reaches: &Reaches,
    turns: &[f64; MAX_JOINTS],
) -> [f64; MAX_JOINTS] {
    let tilt = first_tilt(model);
    let mut speeds = [0.0; MAX_JOINTS];
    // Link k moves with the joints before it alone.
    for (i, speed) in speeds.iter_mut().enumerate().take(model.dof()) {
        let k = i + 1;
        *speed = sinking_speeds(turns, tilt, k, |joint| reaches.body[joint][k]);
    }
    speeds
}

/// The lowest world height (m) of `shape` at world pose `pose` (a mesh's: its hull's lowest
/// vertex).
fn lowest_z(pose: &Isometry3<f64>, shape: &Shape) -> f64 {
    let centre = pose.translation.vector.z;
    let axis_z = (pose.rotation * Vector3::z()).z.abs();
    let across = (1.0 - axis_z * axis_z).max(0.0).sqrt();
    match *shape {
        Shape::Sphere { radius } => centre - radius,
        Shape::Cuboid(size) => {
            let r = pose.rotation.to_rotation_matrix();
            centre - (0..3).map(|i| r[(2, i)].abs() * 0.5 * size[i]).sum::<f64>()
        }
        Shape::Cylinder { radius, length } => centre - 0.5 * length * axis_z - radius * across,
        Shape::Capsule { radius, length } => centre - 0.5 * length * axis_z - radius,
        Shape::Mesh { ref mesh, .. } => {
            let row = pose
                .rotation
                .to_rotation_matrix()
                .matrix()
                .row(2)
                .transpose();
            let lowest = mesh
                .hull_or_mesh()
                .vertices
                .iter()
                .map(|v| row.dot(&v.coords))
                .fold(f64::INFINITY, f64::min);
            centre + lowest
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::FRAC_PI_2;

    #[test]
    fn the_lowest_point_of_each_shape() {
        let tilted = Isometry3::new(Vector3::new(0.0, 0.0, 1.0), Vector3::y() * FRAC_PI_2);
        let rod = Shape::Cylinder {
            radius: 0.1,
            length: 0.6,
        };
        // Lying down: the radius reaches lowest; standing: half the length.
        assert!((lowest_z(&tilted, &rod) - 0.9).abs() < 1e-12);
        let upright = Isometry3::translation(0.0, 0.0, 1.0);
        assert!((lowest_z(&upright, &rod) - 0.7).abs() < 1e-12);
        let capsule = Shape::Capsule {
            radius: 0.1,
            length: 0.6,
        };
        assert!((lowest_z(&upright, &capsule) - 0.6).abs() < 1e-12);
        let cube = Shape::Cuboid(Vector3::new(0.2, 0.2, 0.2));
        let on_edge = Isometry3::new(Vector3::new(0.0, 0.0, 1.0), Vector3::x() * FRAC_PI_2 * 0.5);
        assert!((lowest_z(&on_edge, &cube) - (1.0 - 0.1 * 2f64.sqrt())).abs() < 1e-12);
        assert!((lowest_z(&upright, &Shape::Sphere { radius: 0.3 }) - 0.7).abs() < 1e-12);
    }

    #[test]
    fn the_camera_of_the_zero_pose_hangs_above_the_default_floor() {
        let model = ArmModel::oscar6();
        let bodies: Vec<_> = (1..=6).map(|k| body_elements(&model, k)).collect();
        let low = lowest_point(&model, &bodies, &model.full_pose(&Vector3::zeros()));
        // The camera looks down from 0.1 m beyond the wrist, its 6 cm box below the lens
        // centre... the lowest point is the camera box's bottom edge.
        assert!(low > DEFAULT_FLOOR_Z && low < 0.55, "{low}");
    }

    #[test]
    fn no_point_of_the_arm_or_of_a_link_sinks_faster_than_the_bounds_assume() {
        use crate::robot::kinematic::wrist_gains::WristGains;
        use crate::robot::Controlled;
        use rand::{Rng, SeedableRng};
        let model = ArmModel::oscar6();
        let bodies: Vec<_> = (1..=6).map(|k| body_elements(&model, k)).collect();
        let reaches = reaches(&model, &bodies);
        let gains = WristGains::new(&model);
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(7);
        let (lower, upper): (Vec<f64>, Vec<f64>) = model
            .learned()
            .iter()
            .map(|&j| {
                let joint = &model.joints()[j];
                (joint.lower, joint.upper)
            })
            .unzip();
        let mut draw = || Controlled::from_fn(|i, _| rng.random_range(lower[i]..upper[i]));
        for _ in 0..200 {
            let (from, to) = (draw(), draw());
            let delta = to - from;
            let start = MoveStart::at(&model, model.pose_of(&from));
            let turns = gains.sweep(&model, &start, &delta, 1.0).turns;
            // The whole arm's bound, then each link's own (link k: `bodies[k - 1]`).
            let mut speeds = vec![sinking_speed(&model, &reaches, &turns)];
            speeds
                .extend((1..=6).map(|k| {
                    sinking_speeds(&turns, first_tilt(&model), k, |j| reaches.body[j][k])
                }));
            let lowest = |s: f64| {
                let frames = model.link_frames(&model.pose_of(&(from + delta * s)).joints);
                let mut lows = vec![lowest_of(&frames, &bodies)];
                lows.extend((0..6).map(|k| lowest_of_link(&frames[k], &bodies[k])));
                lows
            };
            let steps = 200;
            let mut before = lowest(0.0);
            for k in 1..=steps {
                let now = lowest(k as f64 / steps as f64);
                for (i, speed) in speeds.iter().enumerate() {
                    assert!(
                        before[i] - now[i] <= speed / steps as f64 + 1e-12,
                        "from {from:?} by {delta:?}: part {i} sank {} m in a step, bound {}",
                        before[i] - now[i],
                        speed / steps as f64
                    );
                }
                before = now;
            }
        }
    }

    #[test]
    fn no_link_reaches_below_its_frame_by_more_than_its_own_reach() {
        use rand::{Rng, SeedableRng};
        // The OSCAR-6 stretched, so a box and cylinders grown along links count too.
        let mut model = ArmModel::oscar6();
        model.stretch_link(2, 0.1).expect("link 2 stretches");
        let bodies: Vec<_> = (1..=6).map(|k| body_elements(&model, k)).collect();
        let reaches = reaches(&model, &bodies);
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(8);
        let mut tightest = f64::INFINITY;
        for _ in 0..2000 {
            let q = Joints::from_fn(model.dof(), |_| rng.random_range(-3.2..3.2));
            let frames = model.link_frames(&q);
            for k in 1..=6 {
                let loose = frames[k - 1].translation.vector.z - reaches.body[k - 1][k];
                let exact = lowest_of_link(&frames[k - 1], &bodies[k - 1]);
                assert!(loose <= exact, "link {k} at {q:?}: {loose} above {exact}");
                tightest = tightest.min(exact - loose);
            }
        }
        // The bound is not vacuous: somewhere it comes within a centimetre.
        assert!(tightest < 0.01, "{tightest}");
    }
}
