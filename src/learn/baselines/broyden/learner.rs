//! The `broyden` controller behind the [`Learner`] trait: probes at the start, then a
//! damped least-squares step per query and a Jacobian update per move seen, each trial
//! starting from the estimate kept nearest its start.

use super::{BroydenSettings, ImageJacobian};
use crate::learn::inputs::finite_or_still;
use crate::learn::{LearnError, Learner, LearnerStats, Method, Observation, Query};
use nalgebra::{Matrix3, SVector, Vector3};
use std::collections::VecDeque;

/// Estimates kept, each with the place it was made at (the most recent moves').
const MEMORY: usize = 100;
/// Reading units that count as far as one degree when the place of a trial's start is
/// matched with the places of the estimates kept.
const READING_PER_DEG: f64 = 5.0;

/// Uncalibrated visual servoing on an image Jacobian estimated online.
#[derive(Debug, Clone)]
pub struct Broyden {
    settings: BroydenSettings,
    /// The estimate; `None` until the probes measured one.
    jacobian: Option<ImageJacobian>,
    /// The probes of the trial going on: moves (columns, degrees) and reading changes.
    probes: Probes,
    /// The query of the trial's last step and the move proposed there, until the next
    /// query (or the trial's path) shows what it did.
    last: Option<(Query, Vector3<f64>)>,
    /// The estimates after the recent moves, each with where its move began, oldest first.
    met: VecDeque<(SVector<f64, 5>, ImageJacobian)>,
}

/// The exploratory moves of a trial that started without a Jacobian.
#[derive(Debug, Clone, Default)]
struct Probes {
    moves: Matrix3<f64>,
    changes: Matrix3<f64>,
    done: usize,
}

impl Broyden {
    /// A controller that knows no Jacobian yet.
    pub fn new(settings: BroydenSettings) -> Broyden {
        Broyden {
            settings,
            jacobian: None,
            probes: Probes::default(),
            last: None,
            met: VecDeque::with_capacity(MEMORY),
        }
    }

    /// The current estimate of the image Jacobian (reading units per degree), once the
    /// probes gave one.
    pub fn jacobian(&self) -> Option<&Matrix3<f64>> {
        self.jacobian.as_ref().map(ImageJacobian::matrix)
    }

    /// Takes in a move of `moved` degrees from `at` that changed the reading by `changed`:
    /// a probe's column, or an update of the estimate, which is kept with the place.
    fn observe(&mut self, at: &Query, moved: &Vector3<f64>, changed: &Vector3<f64>) {
        match &mut self.jacobian {
            Some(jacobian) => {
                jacobian.update(moved, changed, &self.settings);
                if self.met.len() == MEMORY {
                    self.met.pop_front();
                }
                self.met.push_back((place(at), jacobian.clone()));
            }
            None => {
                let probes = &mut self.probes;
                probes.moves.set_column(probes.done, moved);
                probes.changes.set_column(probes.done, changed);
                probes.done += 1;
                if probes.done == 3 {
                    self.jacobian = ImageJacobian::from_probes(&probes.moves, &probes.changes);
                    self.probes = Probes::default();
                }
            }
        }
    }

    /// The move of the next step from `query`.
    fn next_move(&self, query: &Query) -> Vector3<f64> {
        match &self.jacobian {
            Some(jacobian) => {
                jacobian.step(&query.c, self.settings.damping, self.settings.max_step_deg)
            }
            None => Vector3::ith(self.probes.done, self.settings.probe_deg),
        }
    }

    /// At a trial's start: takes up the estimate kept from the place nearest `query`'s (the
    /// latest of equals), where the one the last trial ended with may be far off.
    fn recall(&mut self, query: &Query) {
        let here = place(query);
        let nearest = self.met.iter().rev().min_by(|a, b| {
            let (da, db) = ((a.0 - here).norm(), (b.0 - here).norm());
            da.total_cmp(&db)
        });
        if let Some((_, jacobian)) = nearest {
            self.jacobian = Some(jacobian.clone());
        }
    }

    /// Forgets the trial going on: its last move, and probes that did not finish.
    fn end_trial(&mut self) {
        self.last = None;
        self.probes = Probes::default();
    }
}

impl Learner for Broyden {
    fn name(&self) -> &str {
        Method::Broyden.name()
    }

    fn propose(&mut self, query: &Query) -> Vector3<f64> {
        match self.last.take() {
            Some((before, proposed)) => {
                let moved = Vector3::new(
                    proposed.x,
                    query.theta2_deg - before.theta2_deg,
                    query.theta3_deg - before.theta3_deg,
                );
                self.observe(&before, &moved, &(query.c - before.c));
            }
            None => self.recall(query),
        }
        let step = finite_or_still(self.next_move(query));
        self.last = Some((*query, step));
        step
    }

    /// Takes the trial's last move from its path (the poses it went between, θ1 as read),
    /// when the path ends with it, and forgets the trial.
    fn learn(&mut self, path: &[Observation]) -> Result<(), LearnError> {
        if let (Some((before, _)), [.., from, to]) = (self.last, path) {
            if from.query() == before {
                self.observe(&before, &(to.theta_deg - from.theta_deg), &(to.c - from.c));
            }
        }
        self.end_trial();
        Ok(())
    }

    fn stats(&self) -> LearnerStats {
        LearnerStats {
            nodes: usize::from(self.jacobian.is_some()),
            ..LearnerStats::default()
        }
    }

    fn start_trial(&mut self, _trial: usize) {
        self.end_trial();
    }
}

/// Where a query is, for matching: its angles, and its reading counted in degrees.
fn place(query: &Query) -> SVector<f64, 5> {
    let x = query.five_inputs();
    SVector::from([
        x[0],
        x[1],
        x[2] / READING_PER_DEG,
        x[3] / READING_PER_DEG,
        x[4] / READING_PER_DEG,
    ])
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A linear camera: c = M (θ − θ*).
    fn map() -> Matrix3<f64> {
        Matrix3::new(-14.0, 2.0, 0.5, 1.0, 11.0, -6.0, 0.5, -1.0, 8.0)
    }

    fn query(theta: &Vector3<f64>, goal: &Vector3<f64>) -> Query {
        Query {
            c: map() * (theta - goal),
            theta2_deg: theta.y,
            theta3_deg: theta.z,
        }
    }

    #[test]
    fn it_probes_each_joint_then_servos_to_the_goal_of_a_linear_camera() {
        let mut broyden = Broyden::new(BroydenSettings::default());
        let goal = Vector3::new(4.0, -3.0, 2.0);
        let mut theta = Vector3::zeros();
        for step in 0..10 {
            let moved = broyden.propose(&query(&theta, &goal));
            if step < 3 {
                assert_eq!(moved, Vector3::ith(step, 1.0), "probe {step}");
            }
            theta += moved;
        }
        assert!((broyden.jacobian().expect("probed") - map()).amax() < 1e-9);
        assert!((theta - goal).amax() < 1e-6, "{theta}");
    }

    #[test]
    fn the_jacobian_is_carried_to_the_next_trial_and_probes_are_not_repeated() {
        let mut broyden = Broyden::new(BroydenSettings {
            damping: 0.0,
            ..BroydenSettings::default()
        });
        let goal = Vector3::new(1.0, 1.0, 1.0);
        let mut theta = Vector3::zeros();
        let mut path = Vec::new();
        for _ in 0..5 {
            let q = query(&theta, &goal);
            path.push(Observation {
                theta_deg: theta,
                c: q.c,
            });
            theta += broyden.propose(&q);
        }
        broyden.learn(&path).expect("learns");
        broyden.start_trial(2);
        let far = Vector3::new(-5.0, 6.0, 0.0);
        let first = broyden.propose(&query(&far, &goal));
        assert!((far + first - goal).amax() < 1e-6, "one step home: {first}");
    }

    /// A camera linear on either side of θ2 = 50°, with a different map on each.
    fn map_at(theta: &Vector3<f64>) -> Matrix3<f64> {
        if theta.y < 50.0 {
            Matrix3::new(-14.0, 2.0, 0.5, 1.0, 11.0, -6.0, 0.5, -1.0, 8.0)
        } else {
            Matrix3::new(6.0, 9.0, -1.0, -12.0, 3.0, 2.0, 1.0, 0.5, -7.0)
        }
    }

    /// Servos 10 steps toward `goal` from `theta` as one trial.
    fn servo(broyden: &mut Broyden, trial: usize, mut theta: Vector3<f64>, goal: Vector3<f64>) {
        broyden.start_trial(trial);
        for _ in 0..10 {
            let q = Query {
                c: map_at(&theta) * (theta - goal),
                theta2_deg: theta.y,
                theta3_deg: theta.z,
            };
            theta += broyden.propose(&q);
        }
    }

    #[test]
    fn a_trial_starts_from_the_estimate_kept_nearest_its_start() {
        let mut broyden = Broyden::new(BroydenSettings::default());
        let low = Vector3::new(0.0, 20.0, 30.0);
        let high = Vector3::new(0.0, 80.0, 30.0);
        servo(&mut broyden, 1, low, low + Vector3::new(1.0, 1.0, 1.0));
        servo(&mut broyden, 2, high, high + Vector3::new(1.0, 1.0, 1.0));
        // The last trial ended with the map of θ2 ≥ 50°; one starting at θ2 = 21° takes up
        // the estimate made there.
        broyden.start_trial(3);
        let start = Vector3::new(0.0, 21.0, 30.0);
        broyden.propose(&Query {
            c: Vector3::zeros(),
            theta2_deg: start.y,
            theta3_deg: start.z,
        });
        let recalled = broyden.jacobian().expect("estimated");
        assert!((recalled - map_at(&start)).amax() < 1e-6, "{recalled}");
    }
}
