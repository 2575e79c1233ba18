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

use super::lin5::FIVE_INPUT_BOUNDS;
use super::perceptron::{Perceptron, PerceptronSettings};
use super::tree::{Narrowing, NestedLearner, NestedSettings, Region};
use crate::learn::nested::tree::tree_size;
use crate::learn::MethodFacts;
use crate::learn::{unadjusted_pattern, LearnError, Method, Query};
use nalgebra::SVector;
use std::path::PathBuf;

/// The stream of the run's seed that lin8's own draws (known patterns) come from.
const RNG_STREAM: u64 = 0x6c69_6e38;

/// Settings of `lin8`, the Nested Perceptron without input adjustment. The defaults are
/// those of the shipped `configs/lin8.conf`.
#[derive(Debug, Clone, PartialEq)]
pub struct Lin8Settings {
    /// The root box of the inputs (θ2, θ3, c, d) as (low, high) per input (`boundary_0` …
    /// `boundary_7`; degrees, pixels, the area measure); by default lin5's five, then
    /// (−256, 256), (−256, 256), (−200, 200) for d.
    pub bounds: [(f64, f64); 8],
    /// The factor by which the d box narrows around zero at each depth
    /// (`error_area_shrink`); 0.5 by default.
    pub error_area_shrink: f64,
    /// The tree, merges, change detection, `minimal_joint_move` and the seed.
    pub nested: NestedSettings,
    /// Each node's perceptron.
    pub perceptron: PerceptronSettings,
}

impl Default for Lin8Settings {
    fn default() -> Self {
        let [a, b, c, d, e] = FIVE_INPUT_BOUNDS;
        Lin8Settings {
            bounds: [
                a,
                b,
                c,
                d,
                e,
                (-256.0, 256.0),
                (-256.0, 256.0),
                (-200.0, 200.0),
            ],
            error_area_shrink: 0.5,
            nested: NestedSettings::default(),
            perceptron: PerceptronSettings::default(),
        }
    }
}

/// The `lin8` learner: a nested tree of perceptrons over the unadjusted 8-input patterns.
pub type Lin8 = NestedLearner<Perceptron<8, 9>, Narrowing, 8>;

impl Lin8 {
    /// A `lin8` learner set up by `settings`, keeping its patterns in `pat_file` when given
    /// (the file is created or emptied now), otherwise in memory.
    pub fn new(settings: &Lin8Settings, pat_file: Option<PathBuf>) -> Result<Self, LearnError> {
        let low = SVector::<f64, 8>::from_fn(|i, _| settings.bounds[i].0);
        let high = SVector::<f64, 8>::from_fn(|i, _| settings.bounds[i].1);
        let rule = Narrowing::new(Region::from_bounds(low, high), settings.error_area_shrink);
        NestedLearner::build(
            Method::Lin8,
            &settings.nested,
            (
                rule,
                Perceptron::new(settings.perceptron).asked_at_zero(5..8),
            ),
            (unadjusted_pattern, lin8_input),
            pat_file,
            RNG_STREAM,
        )
    }
}

/// The input of a query: the reading now, and d = 0 (the target reached).
fn lin8_input(query: &Query) -> SVector<f64, 8> {
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

/// What the program knows of `lin8` besides its learner (see [`Method::facts`](crate::learn::Method::facts)).
pub(crate) const LIN8_FACTS: MethodFacts = MethodFacts {
    name: "lin8",
    size: tree_size,
    counts_nodes: true,
    kb_per_trial: 2.6,
    bounded: true,
    watches_changes: true,
    slow_entries: "feedback_steps, bin_size, max_stored_patterns",
    // After a detected change its correction of its two readings is fixed after more
    // patterns than lin5's 300 (seeds 1-8, turns of 30° and 90° and links 2-3 ±10 cm: back
    // within 1.5x after more than 100 trials in 7 of 48 runs at 600, 8 at 300, 11 at 900;
    // learning during moves, a 30° turn on seed 1 takes 263 trials at 600 and 536 at 300).
    shared_defaults: &[("change_fit_patterns", "600")],
};

#[cfg(test)]
mod tests {
    use super::*;
    use crate::learn::{Learner, Lin5, Lin5Settings, Observation};
    use nalgebra::Matrix3;
    use nalgebra::Vector3;
    use rand::{Rng, SeedableRng};
    use rand_chacha::ChaCha8Rng;

    /// The shared settings of both learners, seed 12.
    fn nested() -> NestedSettings {
        NestedSettings {
            seed: 12,
            ..NestedSettings::default()
        }
    }

    fn settings() -> Lin8Settings {
        Lin8Settings {
            error_area_shrink: 0.2,
            nested: nested(),
            ..Lin8Settings::default()
        }
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
        let mut lin8 = Lin8::new(&settings(), None).unwrap();
        let lin5_settings = Lin5Settings {
            nested: nested(),
            ..Lin5Settings::default()
        };
        let mut lin5 = Lin5::new(&lin5_settings, None).unwrap();
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
        let mut lin8 = Lin8::new(&settings(), None).unwrap();
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
