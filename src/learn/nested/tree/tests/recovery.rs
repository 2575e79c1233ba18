//! Tests of what a detected change does to the tree: forgetting, stale fits, starved cuts.

use super::*;
use crate::learn::{MergeKind, ModelEvent};
use nalgebra::Matrix3;

/// A linear mapping every node fits exactly (no known patterns in these settings).
fn linear(x: &SVector<f64, 5>) -> Vector3<f64> {
    let m = Matrix3::new(0.5, -0.2, 0.1, 0.3, 0.0, 0.4, -0.1, 0.2, 0.6);
    m * x.fixed_rows::<3>(2) + Vector3::new(x[0], -x[1], 0.5 * x[0])
}

fn train_mapping(
    t: &mut Tree,
    n: usize,
    map: fn(&SVector<f64, 5>) -> Vector3<f64>,
    region: fn(f64) -> f64,
    rng: &mut ChaCha8Rng,
) {
    for _ in 0..n {
        let input = random_pattern(rng).input.map(region);
        t.train(&Pattern {
            input,
            target: map(&input),
        })
        .unwrap();
    }
}

/// A tree of three levels grown on the curved mapping, with some 3,000 patterns stored.
fn grown(rng: &mut ChaCha8Rng) -> Tree {
    let mut t = tree(still(3));
    train_random(&mut t, 3000, rng);
    let a = t.split(ROOT, 0).unwrap();
    t.split(a, 31).unwrap();
    t.split(ROOT, 31).unwrap();
    let b = t.split(ROOT, 7).unwrap();
    t.split(b, 3).unwrap();
    t
}

/// Every pattern a node answers from, and every pattern stored, is numbered `cutoff` or
/// later.
fn assert_nothing_older_than(t: &mut Tree, cutoff: u64) {
    for id in reachable(t) {
        let node = &t.nodes[id as usize];
        if let Some(oldest) = node.model.answering_oldest() {
            assert!(oldest >= cutoff, "node {id} answers from pattern {oldest}");
        }
        for &bin in &node.bins.clone() {
            t.store
                .for_each_pattern(bin, |_, seq| assert!(seq >= cutoff, "pattern {seq} kept"))
                .unwrap();
        }
    }
}

#[test]
fn after_a_change_no_node_answers_from_a_sum_set_older_than_it() {
    let mut rng = ChaCha8Rng::seed_from_u64(11);
    let mut t = grown(&mut rng);
    let nodes = reachable(&t).len();
    let cutoff = t.journal.next_seq();
    train_mapping(&mut t, 2000, linear, |x| x, &mut rng);
    t.forget_before(cutoff, 20).unwrap();
    assert_eq!(reachable(&t).len(), nodes, "forgetting cuts nothing");
    assert_eq!(recount(&t), counters(&t));
    assert_nothing_older_than(&mut t, cutoff);
    let probe = |rng: &mut ChaCha8Rng| random_pattern(rng).input;
    // Nodes with 20 new patterns answer the new mapping exactly; the others defer.
    let mut answering = 0;
    for id in reachable(&t) {
        let node = &t.nodes[id as usize];
        let x = node.region.low() + (node.region.high() - node.region.low()) * 0.5;
        match node.answer(&x) {
            Some(a) => {
                answering += 1;
                assert!((a - linear(&x)).amax() < 1e-8, "node {id}");
            }
            None => assert!(node.awaiting > 0, "node {id} has no fit"),
        }
    }
    assert!(answering > 1 && answering < nodes, "{answering} of {nodes}");
    for _ in 0..200 {
        let x = probe(&mut rng);
        assert!((t.answer(&x) - linear(&x)).amax() < 1e-8);
    }
    // Nodes that got enough new patterns later answer from them alone, too.
    train_mapping(&mut t, 4000, linear, |x| x, &mut rng);
    assert_nothing_older_than(&mut t, cutoff);
    for id in reachable(&t) {
        let node = &t.nodes[id as usize];
        assert_eq!(node.awaiting == 0, node.depth < 2, "node {id}");
        if node.awaiting == 0 {
            assert!(node.model.answering_oldest() >= Some(cutoff), "node {id}");
        }
    }
    assert_eq!(recount(&t), counters(&t));
}

#[test]
fn a_small_change_leaves_stale_fits_answering_and_a_large_one_does_not() {
    for (scale, stale_kept) in [(1.02, true), (-1.0, false)] {
        let mut rng = ChaCha8Rng::seed_from_u64(12);
        let mut t = grown(&mut rng);
        let cutoff = t.journal.next_seq();
        // Every node but the root awaits new patterns for good.
        t.forget_before(cutoff, usize::MAX).unwrap();
        for _ in 0..300 {
            let input = random_pattern(&mut rng).input;
            t.train(&Pattern {
                input,
                target: mapping(&input) * scale,
            })
            .unwrap();
        }
        assert_eq!(t.recovery.verdict().stale_ok(), stale_kept, "scale {scale}");
        let deep = reachable(&t)
            .into_iter()
            .find(|&id| t.nodes[id as usize].depth == 1)
            .unwrap();
        let node = &t.nodes[deep as usize];
        let x = node.region.low() + (node.region.high() - node.region.low()) * 0.5;
        assert_eq!(node.answer(&x), None, "no fit of its own yet");
        assert_eq!(
            node.answer_or_stale(&x, t.recovery.verdict()).is_some(),
            stale_kept,
            "scale {scale}"
        );
    }
}

#[test]
fn subtrees_starved_of_new_patterns_are_cut_and_booked_unless_their_stale_fits_do_better() {
    let small = |x: &SVector<f64, 5>| mapping(x) * 1.02;
    for (changed, cut) in [(linear as fn(&_) -> _, true), (small, false)] {
        let mut rng = ChaCha8Rng::seed_from_u64(13);
        let mut t = grown(&mut rng);
        train_random(&mut t, 3000, &mut rng);
        taken_events(&mut t);
        let cutoff = t.journal.next_seq();
        t.forget_before(cutoff, 20).unwrap();
        // New patterns only in the lower half of every input, sub-box 0 of the root: the
        // subtrees at 7 (two nodes) and 31 (one) get none.
        train_mapping(&mut t, 4000, changed, |x| 0.5 * x, &mut rng);
        let a = t.nodes[ROOT as usize].children[0];
        assert_eq!(t.nodes[a as usize].awaiting, 0);
        assert_eq!(t.cut_starved(), cut, "nothing awaits patterns any more");
        let mut events = taken_events(&mut t);
        events.sort_by_key(|e| match e {
            ModelEvent::Merge { nodes, .. } => *nodes,
            ModelEvent::Change { .. } => 0,
        });
        let starved = |nodes| ModelEvent::Merge {
            kind: MergeKind::Starved,
            depth: 1,
            nodes,
        };
        let expected = if cut {
            vec![starved(1), starved(2)]
        } else {
            vec![]
        };
        assert_eq!(events, expected);
        assert_eq!(reachable(&t).len(), if cut { 3 } else { 6 });
        assert_eq!(recount(&t), counters(&t));
        assert_nothing_older_than(&mut t, cutoff);
    }
}

#[test]
fn once_a_correction_is_fixed_a_sub_box_is_split_off_sooner_never_later() {
    let mut settings = still(3);
    settings.min_pats_for_split = 50;
    settings.split_error = 0.0;
    let mut t = tree(settings);
    let mut rng = ChaCha8Rng::seed_from_u64(5);
    // Every pattern in the root's sub-box 0 ([0, 4)⁵): 30 are not enough to split it.
    let mut train_low = |t: &mut Tree, n: usize| -> Vec<TreeEvent> {
        (0..n)
            .map(|_| {
                let input = random_pattern(&mut rng).input / 2.0;
                t.train(&Pattern {
                    input,
                    target: mapping(&input),
                })
                .unwrap()
            })
            .collect()
    };
    assert!(!train_low(&mut t, 30).contains(&TreeEvent::Split));
    t.after_correction(80);
    assert!(!train_low(&mut t, 10).contains(&TreeEvent::Split));
    t.after_correction(20);
    assert_eq!(train_low(&mut t, 1), [TreeEvent::Split]);
}

#[test]
fn once_a_correction_is_fixed_a_query_beyond_a_nodes_patterns_goes_to_its_ancestor() {
    let mut t = tree(still(5));
    let mut rng = ChaCha8Rng::seed_from_u64(9);
    // The root's patterns spread over its upper half-box and a corner of the lower one;
    // the root's sub-box 0 ([0, 4)⁵) holds only that corner ([0, 1)⁵).
    for i in 0..400 {
        let u = random_pattern(&mut rng).input;
        let input = if i % 2 == 0 {
            u / 8.0
        } else {
            u / 2.0 + SVector::repeat(4.0)
        };
        t.train(&Pattern {
            input,
            target: mapping(&input),
        })
        .unwrap();
    }
    let child = t.split(ROOT, 0).unwrap();
    let far = SVector::repeat(3.9);
    let near = SVector::repeat(0.5);
    let child_answer = t.nodes[child as usize]
        .answer(&far)
        .expect("the child has a fit");
    let root_answer = t.nodes[ROOT as usize].answer(&far).unwrap();
    assert_ne!(child_answer, root_answer);
    assert_eq!(t.answer(&far), child_answer);
    t.after_correction(20);
    assert_eq!(
        t.answer(&far),
        root_answer,
        "the child's fit does not reach that far"
    );
    let near_answer = t.nodes[child as usize].answer(&near).unwrap();
    assert_eq!(
        t.answer(&near),
        near_answer,
        "among its patterns the child answers"
    );
}
