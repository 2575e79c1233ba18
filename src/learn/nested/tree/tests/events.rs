//! Tests of what training does by itself: splits, relative merges and root merges.

use super::*;
use crate::learn::{MergeKind, ModelEvent};

#[test]
fn sub_boxes_with_enough_patterns_and_error_are_split_off() {
    let mut settings = still(3);
    settings.min_pats_for_split = 30;
    settings.split_error = 1e-4;
    let mut t = tree(settings);
    let mut rng = ChaCha8Rng::seed_from_u64(5);
    let events = train_random(&mut t, 20_000, &mut rng);
    let splits = events.iter().filter(|&&e| e == TreeEvent::Split).count();
    let stats = t.stats();
    assert_eq!(stats.nodes, 1 + splits);
    assert!(stats.levels[2].nodes > 0, "{:?}", stats.levels);
    assert_eq!(recount(&t), counters(&t));
    // Deeper nodes fit the curved mapping better.
    let errors: Vec<f64> = stats.levels.iter().filter_map(|l| l.error).collect();
    assert!(errors[1] < 0.5 * errors[0], "{errors:?}");
}

#[test]
fn a_root_absolute_merge_throws_everything_away() {
    let mut settings = still(2);
    settings.am_error_tresh = 0.05;
    settings.min_pats_for_split = 10;
    settings.split_error = 0.0;
    let mut t = tree(settings);
    let mut rng = ChaCha8Rng::seed_from_u64(6);
    // The curved mapping misses by more than 0.05° on average, even split.
    let mut trained = 0;
    let nodes = loop {
        let nodes = t.stats().nodes;
        if t.train(&random_pattern(&mut rng)).unwrap() == TreeEvent::Reset {
            break nodes;
        }
        trained += 1;
        assert!(trained < 5000, "no reset");
    };
    let merge = ModelEvent::Merge {
        kind: MergeKind::Absolute,
        depth: 0,
        nodes,
    };
    assert_eq!(
        taken_events(&mut t),
        [merge],
        "every node there was, logged once"
    );
    let stats = t.stats();
    assert_eq!((stats.nodes, stats.bins, stats.patterns), (1, 0, 0));
    assert!(stats.levels.iter().all(|l| l.error.is_none()));
    assert_eq!(t.store.bins().count(), 0);
    assert_eq!(t.answer(&SVector::repeat(2.0)), Vector3::zeros());
}

#[test]
fn a_relative_merge_compares_a_child_with_its_parent_on_the_same_patterns() {
    let mut settings = still(2);
    // Any child is worse than its parent plus −∞: merged once both windows are full.
    settings.merge_error = f64::NEG_INFINITY;
    let window = settings.am_error_iters;
    let mut t = tree(settings);
    let mut rng = ChaCha8Rng::seed_from_u64(8);
    train_random(&mut t, 3000, &mut rng);
    let child = t.split(ROOT, 31).unwrap();
    let moved = |rng: &mut ChaCha8Rng, to: fn(f64) -> f64| {
        let input = random_pattern(rng).input.map(to);
        Pattern {
            input,
            target: mapping(&input),
        }
    };
    // Sub-box 31 is [4, 8)⁵; elsewhere here means the lower half of every dimension.
    let in_box = |rng: &mut ChaCha8Rng| moved(rng, |x| 4.0 + 0.5 * x);
    let elsewhere = |rng: &mut ChaCha8Rng| moved(rng, |x| 0.5 * x);
    // The child watches its running error once it has taken in a window of patterns.
    for i in 1..2 * window {
        assert_eq!(t.train(&in_box(&mut rng)).unwrap(), TreeEvent::Trained);
        let watched = i.saturating_sub(window);
        assert_eq!(t.nodes[child as usize].errors.len(), watched, "pattern {i}");
        // Patterns elsewhere fill neither window.
        t.train(&elsewhere(&mut rng)).unwrap();
    }
    assert_eq!(t.nodes[child as usize].errors.len(), window - 1);
    let grandchild = t.split(child, 0).unwrap();
    assert_eq!(t.nodes[grandchild as usize].depth, 2);
    assert_eq!(t.train(&in_box(&mut rng)).unwrap(), TreeEvent::Merged);
    assert_eq!(t.nodes[ROOT as usize].children[31], NONE);
    let merge = ModelEvent::Merge {
        kind: MergeKind::Relative,
        depth: 1,
        nodes: 2,
    };
    assert_eq!(
        taken_events(&mut t),
        [merge],
        "the child and its own child, logged once"
    );
    assert_eq!(recount(&t), counters(&t));
}

#[test]
fn a_nodes_running_error_is_the_trees_miss_on_monitored_patterns_after_a_full_window() {
    let mut t = tree(still(2));
    let window = t.settings().am_error_iters;
    let mut rng = ChaCha8Rng::seed_from_u64(9);
    for _ in 0..window {
        t.train_monitored(&random_pattern(&mut rng), true).unwrap();
    }
    assert_eq!(t.nodes[ROOT as usize].errors.len(), 0, "not yet watched");
    for _ in 0..10 {
        t.train_monitored(&random_pattern(&mut rng), false).unwrap();
    }
    assert_eq!(t.nodes[ROOT as usize].errors.len(), 0, "not monitored");
    let pattern = random_pattern(&mut rng);
    let miss = (t.answer(&pattern.input) - pattern.target).norm();
    t.train_monitored(&pattern, true).unwrap();
    let root = &t.nodes[ROOT as usize].errors;
    assert_eq!(root.len(), 1);
    assert!((root.mean().unwrap() - miss).abs() <= 1e-6 * miss, "{miss}");
}
