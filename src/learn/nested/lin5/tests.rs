//! Tests of lin5 on synthetic mappings: exact and curved fits, the pattern file, merges
//! and change detection.

use super::*;
use crate::learn::inputs::synthetic::{curved, linear, one_move_trial, random_start, Mapping};
use crate::learn::{Learner, MergeStrategy, ModelEvent};
use nalgebra::{Matrix3, Rotation3, Vector3};
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;

fn settings() -> Lin5Settings {
    let mut settings = Lin5Settings::default();
    settings.nested.seed = 11;
    settings
}

fn query(theta: &Vector3<f64>, c: &Vector3<f64>) -> Query {
    Query {
        c: *c,
        theta2_deg: theta.y,
        theta3_deg: theta.z,
    }
}

/// Mean and largest miss (degrees) of `learner` over fresh queries.
fn misses(learner: &mut Lin5, jacobian: Mapping, rng: &mut ChaCha8Rng) -> (f64, f64) {
    let n = 500;
    let (total, worst) = (0..n).fold((0.0, 0.0_f64), |(total, worst), _| {
        let (theta, c) = random_start(rng);
        let miss = (learner.propose(&query(&theta, &c)) - jacobian(&theta) * c).norm();
        (total + miss, worst.max(miss))
    });
    (total / f64::from(n), worst)
}

fn teach(learner: &mut Lin5, jacobian: Mapping, trials: usize, rng: &mut ChaCha8Rng) {
    for _ in 0..trials {
        learner.learn(&one_move_trial(jacobian, rng)).unwrap();
    }
}

#[test]
fn learns_a_linear_mapping_exactly() {
    let mut lin5 = Lin5::new(&settings(), None).unwrap();
    let mut rng = ChaCha8Rng::seed_from_u64(1);
    assert_eq!(
        lin5.propose(&query(&Vector3::zeros(), &Vector3::repeat(9.0))),
        Vector3::zeros()
    );
    teach(&mut lin5, linear, 300, &mut rng);
    assert!(misses(&mut lin5, linear, &mut rng).1 < 1e-8);
    let stats = lin5.stats();
    assert_eq!(stats.nodes, 1, "an exact fit needs no split");
    assert_eq!(stats.levels.len(), settings().nested.tree.max_depth + 1);
    assert!(stats.patterns > 250 && stats.patterns <= 300, "{stats:?}");
    assert!(!lin5.take_relearn_request());
}

#[test]
fn a_curved_mapping_grows_the_tree_and_is_learned_better_than_by_one_node() {
    let mut settings = settings();
    settings.nested.tree.min_pats_for_split = 25;
    settings.nested.tree.am_error_tresh = f64::INFINITY;
    let mut nested = Lin5::new(&settings, None).unwrap();
    settings.nested.tree.min_pats_for_split = usize::MAX;
    let mut single = Lin5::new(&settings, None).unwrap();
    let mut rng = ChaCha8Rng::seed_from_u64(2);
    for _ in 0..4000 {
        let trial = one_move_trial(curved, &mut rng);
        nested.learn(&trial).unwrap();
        single.learn(&trial).unwrap();
    }
    let stats = nested.stats();
    assert!(stats.nodes > 10, "{stats:?}");
    assert_eq!(single.stats().nodes, 1);
    let (nested_miss, _) = misses(&mut nested, curved, &mut ChaCha8Rng::seed_from_u64(3));
    let (single_miss, _) = misses(&mut single, curved, &mut ChaCha8Rng::seed_from_u64(3));
    assert!(
        nested_miss < 0.5 * single_miss,
        "{nested_miss} vs {single_miss}"
    );
}

#[test]
fn patterns_in_the_pat_file_learn_exactly_like_patterns_in_memory() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("pat_file");
    let mut settings = settings();
    settings.nested.tree.min_pats_for_split = 25;
    settings.nested.tree.am_error_tresh = f64::INFINITY;
    let mut in_memory = Lin5::new(&settings, None).unwrap();
    let mut in_file = Lin5::new(&settings, Some(path.clone())).unwrap();
    let mut rng = ChaCha8Rng::seed_from_u64(4);
    for _ in 0..1500 {
        let trial = one_move_trial(curved, &mut rng);
        in_memory.learn(&trial).unwrap();
        in_file.learn(&trial).unwrap();
    }
    let stats = in_file.stats();
    assert!(
        stats.nodes > 1,
        "splits read their patterns back: {stats:?}"
    );
    assert_eq!(stats, in_memory.stats());
    for _ in 0..100 {
        let (theta, c) = random_start(&mut rng);
        let q = query(&theta, &c);
        assert_eq!(in_file.propose(&q), in_memory.propose(&q));
    }
    let bytes = std::fs::metadata(&path).unwrap().len();
    assert!(
        bytes >= 64 * stats.patterns as u64 && bytes % 64 == 0,
        "{bytes}"
    );
}

#[test]
fn a_turned_mapping_throws_everything_away_and_asks_to_relearn_once() {
    let mut lin5 = Lin5::new(&settings(), None).unwrap();
    let mut rng = ChaCha8Rng::seed_from_u64(5);
    teach(&mut lin5, linear, 300, &mut rng);
    fn turned(theta: &Vector3<f64>) -> Matrix3<f64> {
        -linear(theta)
    }
    let mut trials = 0;
    while !lin5.take_relearn_request() {
        teach(&mut lin5, turned, 1, &mut rng);
        trials += 1;
        assert!(
            trials <= settings().nested.tree.am_error_iters,
            "no root merge"
        );
    }
    assert!(!lin5.take_relearn_request(), "asked once");
    let stats = lin5.stats();
    assert_eq!((stats.nodes, stats.bins, stats.patterns), (1, 0, 0));
    teach(&mut lin5, turned, 300, &mut rng);
    assert!(misses(&mut lin5, turned, &mut rng).1 < 1e-8);
}

#[test]
fn under_change_detection_a_turned_mapping_is_found_dated_and_relearned() {
    let mut settings = settings();
    settings.nested.merge_strategy = MergeStrategy::ChangeDetection;
    settings.nested.tree.min_pats_for_split = 25;
    let mut lin5 = Lin5::new(&settings, None).unwrap();
    let mut rng = ChaCha8Rng::seed_from_u64(7);
    fn turned(theta: &Vector3<f64>) -> Matrix3<f64> {
        curved(theta) * Rotation3::from_axis_angle(&Vector3::z_axis(), 0.5).matrix()
    }
    let mut trials = |lin5: &mut Lin5, jacobian: Mapping, from: usize, to: usize| {
        let mut events = Vec::new();
        for trial in from..to {
            lin5.start_trial(trial);
            lin5.learn(&one_move_trial(jacobian, &mut rng)).unwrap();
            lin5.drain_events(&mut events);
        }
        events
    };
    assert_eq!(
        trials(&mut lin5, curved, 0, 3000),
        [],
        "no change, no alarm"
    );
    let events = trials(&mut lin5, turned, 3000, 3100);
    assert_eq!(events.len(), 1, "{events:?}");
    let ModelEvent::Change { estimated_trial } = events[0] else {
        panic!("{events:?}");
    };
    assert!(estimated_trial.abs_diff(3000) <= 2, "{estimated_trial}");
    trials(&mut lin5, turned, 3100, 4000);
    let (turned_miss, _) = misses(&mut lin5, turned, &mut ChaCha8Rng::seed_from_u64(8));
    let mut fresh = Lin5::new(&settings, None).unwrap();
    teach(&mut fresh, turned, 1000, &mut ChaCha8Rng::seed_from_u64(9));
    let (fresh_miss, _) = misses(&mut fresh, turned, &mut ChaCha8Rng::seed_from_u64(8));
    assert!(
        turned_miss < 2.0 * fresh_miss,
        "{turned_miss} vs {fresh_miss} from scratch"
    );
}

#[test]
fn answers_are_finite_for_any_query() {
    let mut lin5 = Lin5::new(&settings(), None).unwrap();
    let mut rng = ChaCha8Rng::seed_from_u64(6);
    teach(&mut lin5, curved, 200, &mut rng);
    let odd = Vector3::new(f64::NAN, f64::INFINITY, -1e308);
    let answer = lin5.propose(&query(&odd, &odd));
    assert!(answer.iter().all(|v| v.is_finite()), "{answer}");
}
