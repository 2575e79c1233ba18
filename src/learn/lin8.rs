//! `lin8`: the Nested Perceptron without input adjustment (study §4.3).
//!
//! A pattern is the move between two poses of a trial as it was made: input (θ2, θ3, c, d)
//! with c the reading before and d the reading after the move, target Δθ (see
//! [`unadjusted_pattern`]); it is exact whatever d is. A query asks for the move that ends
//! at d = 0: (θ2, θ3, c, 0, 0, 0). Every tree node holds a [`Perceptron`] over the eight
//! inputs (a 9×9 system); the tree branches by [`Narrowing`]: (θ2, θ3, c) are halved as in
//! lin5, d is narrowed around zero by `error_area_shrink` per depth, so each node still has
//! 32 sub-boxes. Known patterns have c = d = 0.
//!
//! Input boundaries are `boundary_0` … `boundary_7`; those of d (5–7) should hold zero well
//! inside, as queries and known patterns live at d = 0.

use super::perceptron::Perceptron;
use super::tree::{learner_on_nested_tree, Narrowing, NestedLearner, Region, TreeSettings};
use super::{LearnError, Method};
use crate::experiment::Config;
use crate::learn::{unadjusted_pattern, Query};
use nalgebra::SVector;
use std::path::PathBuf;

/// The stream of the run's seed that lin8's own draws (known patterns) come from.
const RNG_STREAM: u64 = 0x6c69_6e38;

/// The `lin8` learner: a nested tree of perceptrons over the unadjusted 8-input patterns.
#[derive(Debug)]
pub struct Lin8 {
    nested: NestedLearner<Perceptron<8, 9>, Narrowing, 8>,
}

impl Lin8 {
    /// A `lin8` learner set up by `config` (boundaries 0–7, `error_area_shrink`, tree,
    /// perceptron and split and merge entries, `seed`), keeping its patterns in `pat_file`
    /// when given (the file is created or emptied now), otherwise in memory.
    pub fn new(config: &Config, pat_file: Option<PathBuf>) -> Result<Self, LearnError> {
        let low = SVector::<f64, 8>::from_fn(|i, _| config.boundary(i).0);
        let high = SVector::<f64, 8>::from_fn(|i, _| config.boundary(i).1);
        let rule = Narrowing::new(Region::from_bounds(low, high), config.error_area_shrink);
        let nested = NestedLearner::new(
            config,
            TreeSettings::from_config(config),
            rule,
            Perceptron::new(config.nr_of_matrices, config.max_pats_in_mat).asked_at_zero(5..8),
            unadjusted_pattern,
            pat_file,
            RNG_STREAM,
        )?;
        Ok(Lin8 { nested })
    }

    /// The input of a query: the reading now, and d = 0 (the target reached).
    fn input(query: &Query) -> SVector<f64, 8> {
        let c = query.c;
        SVector::<f64, 8>::from([
            query.theta2_deg,
            query.theta3_deg,
            c.x,
            c.y,
            c.z,
            0.0,
            0.0,
            0.0,
        ])
    }
}

learner_on_nested_tree!(Lin8, Method::Lin8, Lin8::input);

#[cfg(test)]
mod tests {
    use super::*;
    use crate::learn::Observation;
    use crate::learn::{Learner, Lin5};
    use nalgebra::Matrix3;
    use nalgebra::Vector3;
    use rand::{Rng, SeedableRng};
    use rand_chacha::ChaCha8Rng;

    fn config() -> Config {
        let mut config = Config::default_config();
        config.method = Method::Lin8;
        config.seed = 12;
        config
    }

    /// A mapping both learners fit exactly: Δθ = J·(c − d), the base never turning (the
    /// first row of J is zero), so lin5's adjusted input c − d is exact and linear too.
    fn jacobian() -> Matrix3<f64> {
        Matrix3::new(0.0, 0.0, 0.0, 0.01, 0.03, 0.04, -0.02, 0.0, 0.06)
    }

    /// A trial of one move from a random pose and reading that ends at reading d.
    fn one_move(rng: &mut ChaCha8Rng) -> [Observation; 2] {
        let theta = Vector3::new(
            0.0,
            rng.random_range(0.0..70.0),
            rng.random_range(50.0..135.0),
        );
        let c = Vector3::new(
            rng.random_range(-200.0..200.0),
            rng.random_range(-200.0..200.0),
            rng.random_range(-90.0..250.0),
        );
        let d = c.map(|v| v * rng.random_range(-0.3..0.3));
        let start = Observation {
            theta_deg: theta,
            c,
        };
        let end = Observation {
            theta_deg: theta + jacobian() * (c - d),
            c: d,
        };
        [start, end]
    }

    fn query(rng: &mut ChaCha8Rng) -> Query {
        one_move(rng)[0].query()
    }

    #[test]
    fn the_lin8_answer_equals_the_lin5_answer_where_both_are_exact() {
        let mut lin8 = Lin8::new(&config(), None).unwrap();
        let mut lin5 = Lin5::new(&config(), None).unwrap();
        let mut rng = ChaCha8Rng::seed_from_u64(1);
        for _ in 0..300 {
            let trial = one_move(&mut rng);
            lin8.learn(&trial).unwrap();
            lin5.learn(&trial).unwrap();
        }
        for _ in 0..200 {
            let q = query(&mut rng);
            let exact = jacobian() * q.c;
            let (a8, a5) = (lin8.propose(&q), lin5.propose(&q));
            assert!((a8 - exact).amax() < 1e-8, "{a8} vs {exact}");
            assert!((a8 - a5).amax() < 1e-8, "{a8} vs {a5}");
        }
        assert_eq!(lin8.stats().nodes, 1, "an exact fit needs no split");
    }

    #[test]
    fn answers_are_finite_for_any_query() {
        let mut lin8 = Lin8::new(&config(), None).unwrap();
        let mut rng = ChaCha8Rng::seed_from_u64(3);
        for _ in 0..100 {
            lin8.learn(&one_move(&mut rng)).unwrap();
        }
        let odd = Vector3::new(f64::NAN, f64::INFINITY, -1e308);
        let q = Query {
            c: odd,
            theta2_deg: f64::NAN,
            theta3_deg: 1e300,
        };
        assert!(lin8.propose(&q).iter().all(|v| v.is_finite()));
    }
}
