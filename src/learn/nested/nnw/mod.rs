//! `nnw`: the Nested Network (study §3.2, §5.1) — lin5's tree with a net in every node.
//!
//! Inputs, patterns, queries, boundaries and the tree (splits, merges, bins) are lin5's:
//! the adjusted 5-input patterns (θ2, θ3, c*) → Δθ over boxes halved at every depth. Each
//! node holds a [`NetModel`]: `hidden_units` tanh units, weights drawn in ±`wrange` when
//! the node is made, inputs in the node's local coordinates. A net takes one
//! back-propagation step for every pattern trained to it; after a trial, each node that
//! took in at least `nnw_train_delay` patterns since it was last re-trained is re-trained
//! by conjugate gradients on the newest pattern of up to `nnw_train_limit` bins of its
//! box, drawn at random (see the tree's re-training); a node split off is re-trained at
//! once. Known patterns are lin5's and lin8's only (the study's `known_pattern_perc` is
//! not an nnw entry): nnw trains none.

mod net_model;

use super::lin5::FIVE_INPUT_BOUNDS;
use super::tree::{Halving, NestedLearner, NestedSettings, Region};
use crate::learn::nested::tree::tree_size;
use crate::learn::MethodFacts;
use crate::learn::{adjusted_pattern, LearnError, Method, Query};
use nalgebra::SVector;
use net_model::NetModel;
use std::path::PathBuf;

/// The stream of the run's seed that nnw's own draws (weights, re-training samples) come
/// from.
const RNG_STREAM: u64 = 0x006e_6e77;

/// Settings of `nnw`, the Nested Network. The defaults are those of the shipped
/// `configs/nnw.conf`.
#[derive(Debug, Clone, PartialEq)]
pub struct NnwSettings {
    /// The root box of the inputs (θ2, θ3, cx*, cy*, cz*), as lin5's
    /// ([`Lin5Settings::bounds`](crate::learn::Lin5Settings::bounds)).
    pub bounds: [(f64, f64); 5],
    /// The tree (its `known_pattern_perc` is not used: nnw trains no known patterns),
    /// merges, change detection, `minimal_joint_move` and the seed.
    pub nested: NestedSettings,
    /// Hidden tanh units of each node's net (`hidden_units`); 5 by default.
    pub hidden_units: usize,
    /// A new net's weights are drawn in ±this (`wrange`); 0.1 by default.
    pub wrange: f64,
}

impl Default for NnwSettings {
    fn default() -> Self {
        NnwSettings {
            bounds: FIVE_INPUT_BOUNDS,
            nested: NestedSettings::default(),
            hidden_units: 5,
            wrange: 0.1,
        }
    }
}

/// The `nnw` learner: a nested tree of feed-forward nets over the adjusted 5-input
/// patterns.
pub type Nnw = NestedLearner<NetModel, Halving<5>, 5>;

impl Nnw {
    /// An `nnw` learner set up by `settings`, keeping its patterns in `pat_file` when given
    /// (the file is created or emptied now), otherwise in memory.
    pub fn new(settings: &NnwSettings, pat_file: Option<PathBuf>) -> Result<Self, LearnError> {
        let low = SVector::<f64, 5>::from_fn(|i, _| settings.bounds[i].0);
        let high = SVector::<f64, 5>::from_fn(|i, _| settings.bounds[i].1);
        let mut nested = settings.nested.clone();
        nested.tree.known_pattern_perc = 0.0;
        NestedLearner::build(
            Method::Nnw,
            &nested,
            (
                Halving::new(Region::from_bounds(low, high)),
                NetModel::template(settings.hidden_units, settings.wrange),
            ),
            (adjusted_pattern, Query::five_inputs),
            pat_file,
            RNG_STREAM,
        )
    }
}

/// What the program knows of `nnw` besides its learner (see [`Method::facts`](crate::learn::Method::facts)).
pub(crate) const NNW_FACTS: MethodFacts = MethodFacts {
    name: "nnw",
    size: tree_size,
    counts_nodes: true,
    kb_per_trial: 2.6,
    bounded: true,
    watches_changes: true,
    slow_entries: "hidden_units, nnw_train_limit, feedback_steps",
    // Its nets are trained after every trial: 1,000 trials take about as long as 100,000
    // of lin5.
    shared_defaults: &[("trials", "1000")],
};

#[cfg(test)]
mod tests {
    use super::*;
    use crate::learn::inputs::synthetic::{curved, one_move_trial};
    use crate::learn::Learner;
    use crate::learn::Observation;
    use nalgebra::Vector3;
    use rand::SeedableRng;
    use rand_chacha::ChaCha8Rng;

    fn settings() -> NnwSettings {
        NnwSettings {
            nested: NestedSettings {
                seed: 13,
                ..NestedSettings::default()
            },
            ..NnwSettings::default()
        }
    }

    /// A trial of one move on the curved synthetic arm that hits the target.
    fn one_move(rng: &mut ChaCha8Rng) -> [Observation; 2] {
        one_move_trial(curved, rng)
    }

    /// Mean miss (degrees) over fresh queries, and the mean move asked for.
    fn misses(nnw: &mut Nnw, rng: &mut ChaCha8Rng) -> (f64, f64) {
        let n = 300;
        let (miss, size) = (0..n).fold((0.0, 0.0), |(miss, size), _| {
            let [start, end] = one_move(rng);
            let wanted = end.theta_deg - start.theta_deg;
            let got = nnw.propose(&start.query());
            (miss + (got - wanted).norm(), size + wanted.norm())
        });
        (miss / f64::from(n), size / f64::from(n))
    }

    #[test]
    fn learns_a_smooth_mapping_and_grows_its_tree() {
        let mut nnw = Nnw::new(&settings(), None).unwrap();
        let mut rng = ChaCha8Rng::seed_from_u64(1);
        assert_eq!(
            nnw.propose(&one_move(&mut rng)[0].query()),
            Vector3::zeros()
        );
        for _ in 0..2000 {
            nnw.learn(&one_move(&mut rng)).unwrap();
        }
        let (miss, size) = misses(&mut nnw, &mut rng);
        assert!(miss < 0.06 * size, "mean miss {miss}° on moves of {size}°");
        let stats = nnw.stats();
        assert!(stats.nodes > 1, "{stats:?}");
        assert!(!nnw.take_relearn_request());
    }

    #[test]
    fn answers_are_finite_for_any_query() {
        let mut nnw = Nnw::new(&settings(), None).unwrap();
        let mut rng = ChaCha8Rng::seed_from_u64(2);
        for _ in 0..30 {
            nnw.learn(&one_move(&mut rng)).unwrap();
        }
        let odd = Vector3::new(f64::NAN, f64::INFINITY, -1e308);
        let q = Query {
            c: odd,
            theta2_deg: f64::NAN,
            theta3_deg: 1e300,
        };
        assert!(nnw.propose(&q).iter().all(|v| v.is_finite()));
    }
}
