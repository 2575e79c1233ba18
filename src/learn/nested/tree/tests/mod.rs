//! Tests of the tree's structure: splits, merges, bins and the per-depth counters.

mod events;
mod narrowing;
mod recovery;
mod retraining;
mod tally;

use super::*;
use crate::learn::nested::perceptron::{Perceptron, PerceptronSettings};
use crate::learn::Pattern;
use nalgebra::{SVector, Vector3};
use proptest::prelude::*;
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use std::collections::BTreeSet;
use tally::Tally;

type Tree = NestedTree<Perceptron<5, 6>, Halving<5>, 5>;

/// Settings under which nothing splits or merges by itself.
fn still(max_depth: usize) -> TreeSettings {
    TreeSettings {
        max_depth,
        bin_size: 4,
        max_stored_patterns: 0,
        min_pats_for_split: usize::MAX,
        split_error: f64::INFINITY,
        am_error_tresh: f64::INFINITY,
        am_error_iters: 20,
        merge_error: f64::INFINITY,
        monitor_ave: 50,
        known_pattern_perc: 0.0,
        retrain_limit: 300,
        retrain_delay: 15,
    }
}

/// A tree over [0, 8]⁵.
fn tree(settings: TreeSettings) -> Tree {
    let root = Region::from_bounds(SVector::zeros(), SVector::repeat(8.0));
    NestedTree::new(
        settings,
        Halving::new(root),
        Perceptron::new(PerceptronSettings {
            sum_sets: 2,
            set_size: 200,
        }),
        Records::in_memory(),
        ChaCha8Rng::seed_from_u64(7),
    )
}

/// A smooth, curved mapping, so deeper nodes fit better.
fn mapping(x: &SVector<f64, 5>) -> Vector3<f64> {
    Vector3::new(
        x[0] * x[1] / 8.0 + x[2],
        (x[3] / 3.0).sin() * 4.0 - x[4],
        x[0] - 0.05 * x[2] * x[2],
    )
}

fn random_pattern(rng: &mut ChaCha8Rng) -> Pattern<5> {
    let input = SVector::from_fn(|_, _| rng.random_range(0.0..8.0));
    Pattern {
        input,
        target: mapping(&input),
    }
}

fn train_random(tree: &mut Tree, n: usize, rng: &mut ChaCha8Rng) -> Vec<TreeEvent> {
    (0..n)
        .map(|_| tree.train(&random_pattern(rng)).unwrap())
        .collect()
}

/// Nodes reachable from the root, root first.
fn reachable<A: Approximator<N>, R: BranchRule<N>, const N: usize>(
    tree: &NestedTree<A, R, N>,
) -> Vec<u32> {
    let mut found = vec![ROOT];
    let mut i = 0;
    while i < found.len() {
        let node = &tree.nodes[found[i] as usize];
        found.extend(node.children.iter().copied().filter(|&c| c != NONE));
        i += 1;
    }
    found
}

/// Counts per depth by walking the tree, and checks every bin hangs where it should.
fn recount<A: Approximator<N>, R: BranchRule<N>, const N: usize>(
    tree: &NestedTree<A, R, N>,
) -> Vec<(usize, usize, usize)> {
    let mut counts = vec![(0, 0, 0); tree.settings().max_depth + 1];
    let mut seen_bins = 0;
    for id in reachable(tree) {
        let node = &tree.nodes[id as usize];
        let mut per_box = [0; BRANCHES];
        let mut patterns = 0;
        for &bin in &node.bins {
            let key = tree.store.bins().key(bin);
            assert_eq!(
                tree.descend(key).deepest(),
                id,
                "bin on the deepest covering node"
            );
            let n = tree.store.bins().len(bin);
            patterns += n;
            if let Some(b) = key.branch(node.depth + 1) {
                per_box[usize::from(b)] += n;
            }
        }
        assert_eq!(node.patterns(), patterns);
        assert_eq!(node.box_patterns(), per_box);
        let c = &mut counts[node.depth];
        *c = (c.0 + 1, c.1 + node.bins.len(), c.2 + patterns);
        seen_bins += node.bins.len();
    }
    assert_eq!(
        seen_bins,
        tree.store.bins().count(),
        "every bin hangs on one node"
    );
    counts
}

fn counters<A: Approximator<N>, R: BranchRule<N>, const N: usize>(
    tree: &NestedTree<A, R, N>,
) -> Vec<(usize, usize, usize)> {
    let stats = tree.stats();
    stats
        .levels
        .iter()
        .map(|l| (l.nodes, l.bins, l.patterns))
        .collect()
}

fn bins_of(tree: &Tree, id: u32) -> BTreeSet<u32> {
    tree.nodes[id as usize].bins.iter().copied().collect()
}

/// The merges and detected changes the tree booked since they were last taken.
fn taken_events<A: Approximator<N>, R: BranchRule<N>, const N: usize>(
    tree: &mut NestedTree<A, R, N>,
) -> Vec<crate::learn::ModelEvent> {
    let mut events = Vec::new();
    tree.journal.drain_into(&mut events);
    events
}

#[test]
fn a_split_makes_the_right_half_and_sinks_exactly_the_covered_bins() {
    let mut t = tree(still(3));
    let mut rng = ChaCha8Rng::seed_from_u64(1);
    train_random(&mut t, 3000, &mut rng);
    let branch = 0b10101;
    let all = bins_of(&t, ROOT);
    let covered: BTreeSet<u32> = all
        .iter()
        .copied()
        .filter(|&b| t.store.bins().key(b).branch(1) == Some(branch))
        .collect();
    assert!(!covered.is_empty() && covered.len() < all.len());

    let child = t.split(ROOT, branch).unwrap();
    let region = t.nodes[child as usize].region;
    assert_eq!(region.low(), SVector::from([4.0, 0.0, 4.0, 0.0, 4.0]));
    assert_eq!(region.high(), SVector::from([8.0, 4.0, 8.0, 4.0, 8.0]));
    assert_eq!(t.nodes[ROOT as usize].children[usize::from(branch)], child);
    assert_eq!(bins_of(&t, child), covered);
    assert_eq!(bins_of(&t, ROOT), &all - &covered);
    assert_eq!(recount(&t), counters(&t));
    // The child was trained with its patterns at once.
    let inside = SVector::from([6.0, 1.0, 5.0, 3.0, 7.0]);
    assert!(t.nodes[child as usize].answer(&inside).is_some());
}

#[test]
fn a_merge_returns_every_bin_of_the_cut_subtree_to_the_parent() {
    let mut t = tree(still(3));
    let mut rng = ChaCha8Rng::seed_from_u64(2);
    train_random(&mut t, 3000, &mut rng);
    let all = bins_of(&t, ROOT);
    let before = counters(&t);
    let child = t.split(ROOT, 31).unwrap();
    let grandchild = t.split(child, 0).unwrap();
    t.split(grandchild, 5).unwrap();
    t.split(child, 7).unwrap();
    t.split(ROOT, 2).unwrap();
    assert!(!bins_of(&t, grandchild).is_empty());
    assert_eq!(recount(&t), counters(&t));

    t.cut(child);
    assert_eq!(t.nodes[ROOT as usize].children[31], NONE);
    let at_root_or_2 = &bins_of(&t, ROOT) | &bins_of(&t, t.nodes[0].children[2]);
    assert_eq!(at_root_or_2, all);
    assert_eq!(recount(&t), counters(&t));
    assert_eq!(
        counters(&t)[2..],
        before[2..],
        "nothing is left below depth 1"
    );
    // The freed nodes are reused.
    t.split(ROOT, 31).unwrap();
    assert_eq!(t.nodes.len(), 6);
    assert_eq!(recount(&t), counters(&t));
}

#[test]
fn a_capped_store_drops_the_least_recently_used_bins_and_keeps_splitting() {
    let mut settings = still(4);
    settings.min_pats_for_split = 20;
    settings.split_error = 0.0;
    settings.max_stored_patterns = 300;
    let mut t = tree(settings);
    let mut rng = ChaCha8Rng::seed_from_u64(3);
    let events = train_random(&mut t, 3000, &mut rng);
    assert_eq!(t.store.bins().stored(), 300, "full, and no fuller");
    assert_eq!(recount(&t), counters(&t));
    assert!(events.contains(&TreeEvent::Split));
    // A pattern in a bin just stored to stays; the bin of the oldest pattern is gone.
    let last = random_pattern(&mut rng);
    t.train(&last).unwrap();
    let key = t.rule().key(&last.input, 4);
    let holder = &t.nodes[t.descend(key).deepest() as usize];
    let bins = t.store.bins();
    let bin = holder.bins.iter().copied().find(|&b| bins.key(b) == key);
    let bin = bin.expect("the bin just stored to is kept");
    assert_eq!(t.store.latest(bin).unwrap(), last);
    assert_eq!(t.stats().patterns, 300);
}

#[test]
fn an_answer_falls_back_to_the_nearest_ancestor_when_a_fit_is_singular() {
    let mut t = tree(still(2));
    let mut rng = ChaCha8Rng::seed_from_u64(3);
    // Many patterns outside the sub-box 31 (upper half everywhere) ...
    for _ in 0..2000 {
        let mut p = random_pattern(&mut rng);
        p.input[0] = p.input[0].min(3.9);
        p.target = mapping(&p.input);
        t.train(&p).unwrap();
    }
    // ... and in it, one point over and over: its own fit is singular.
    let point = SVector::repeat(6.0);
    for _ in 0..60 {
        t.train(&Pattern {
            input: point,
            target: mapping(&point),
        })
        .unwrap();
    }
    let child = t.split(ROOT, 31).unwrap();
    let query = SVector::from([5.0, 7.0, 6.5, 4.5, 5.5]);
    assert_eq!(t.descend(t.rule().key(&query, 2)).deepest(), child);
    assert_eq!(t.nodes[child as usize].answer(&query), None);
    let root_answer = t.nodes[ROOT as usize].answer(&query).unwrap();
    assert_eq!(t.answer(&query), root_answer);
}

#[test]
fn an_empty_tree_answers_zero_and_never_nan() {
    let t = tree(still(3));
    assert_eq!(t.answer(&SVector::repeat(1.0)), Vector3::zeros());
    let mut t = tree(still(3));
    let mut rng = ChaCha8Rng::seed_from_u64(4);
    train_random(&mut t, 200, &mut rng);
    let odd = SVector::from([f64::NAN, 1.0, f64::INFINITY, -1e300, 3.0]);
    assert!(t.answer(&odd).iter().all(|v| v.is_finite()));
    let bad = Pattern {
        input: odd,
        target: Vector3::zeros(),
    };
    assert_eq!(t.train(&bad).unwrap(), TreeEvent::Ignored);
}

#[derive(Debug, Clone)]
enum Op {
    Train(u8),
    Split(u32, u8),
    Cut(u32),
}

fn op() -> impl Strategy<Value = Op> {
    prop_oneof![
        (1u8..60).prop_map(Op::Train),
        (any::<u32>(), 0u8..32).prop_map(|(n, b)| Op::Split(n, b)),
        any::<u32>().prop_map(Op::Cut),
    ]
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]

    #[test]
    fn counters_equal_a_full_recount_after_any_splits_and_merges(
        ops in prop::collection::vec(op(), 1..40),
        seed in any::<u64>(),
        cap in prop_oneof![Just(0usize), 2usize..120],
    ) {
        // Training splits, merges and resets by itself too: with these settings 1,000
        // patterns give some 50 splits, 30 relative merges and a few root merges.
        let mut settings = still(3);
        settings.min_pats_for_split = 8;
        settings.split_error = 0.0;
        settings.am_error_tresh = 1.6;
        settings.am_error_iters = 10;
        settings.merge_error = -0.9;
        settings.bin_size = 2;
        // (With a cap, the least recently used bins are dropped along the way too.)
        settings.max_stored_patterns = cap;
        let mut t = tree(settings);
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        for op in ops {
            let nodes = reachable(&t);
            match op {
                Op::Train(n) => {
                    train_random(&mut t, usize::from(n), &mut rng);
                }
                Op::Split(pick, branch) => {
                    let id = nodes[pick as usize % nodes.len()];
                    let node = &t.nodes[id as usize];
                    if node.depth < 3 && node.children[usize::from(branch)] == NONE {
                        t.split(id, branch).unwrap();
                    }
                }
                Op::Cut(pick) => {
                    if nodes.len() > 1 {
                        t.cut(nodes[1 + pick as usize % (nodes.len() - 1)]);
                    }
                }
            }
            prop_assert_eq!(recount(&t), counters(&t));
            prop_assert!(cap == 0 || t.store.bins().stored() <= cap);
        }
    }
}
