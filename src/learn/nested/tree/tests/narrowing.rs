//! Tests of lin8's tree: a pattern whose reading after the move lies outside the narrowed
//! d box of the next depth stops there, is stored once, and never reaches deeper nodes.

use super::*;

type Tree8 = NestedTree<Tally<false, 8>, Narrowing, 8>;

/// (θ2, θ3, c) in [0, 8)⁵; d in [−100, 100]³, ±50 at depth 1, ±25 at 2, ±12.5 at 3.
fn tree8() -> Tree8 {
    let low = SVector::<f64, 8>::from([0.0, 0.0, 0.0, 0.0, 0.0, -100.0, -100.0, -100.0]);
    let high = SVector::<f64, 8>::from([8.0, 8.0, 8.0, 8.0, 8.0, 100.0, 100.0, 100.0]);
    NestedTree::new(
        still(3),
        Narrowing::new(Region::from_bounds(low, high), 0.5),
        Tally::default(),
        Records::in_memory(),
        ChaCha8Rng::seed_from_u64(9),
    )
}

fn pattern8(at: [f64; 5], d: [f64; 3]) -> Pattern<8> {
    let input = SVector::<f64, 8>::from([at[0], at[1], at[2], at[3], at[4], d[0], d[1], d[2]]);
    Pattern {
        input,
        target: Vector3::new(input.sum(), at[0], d[1]),
    }
}

/// Patterns taken in by each node of `ids`.
fn added(t: &Tree8, ids: &[u32]) -> Vec<usize> {
    ids.iter()
        .map(|&id| t.nodes[id as usize].model.added)
        .collect()
}

#[test]
fn patterns_with_d_off_stop_early_are_stored_once_and_never_sink() {
    let mut t = tree8();
    let mut rng = ChaCha8Rng::seed_from_u64(10);
    for _ in 0..600 {
        let at = std::array::from_fn(|_| rng.random_range(0.0..8.0));
        let d = std::array::from_fn(|_| rng.random_range(-10.0..10.0));
        t.train(&pattern8(at, d)).unwrap();
    }
    // The upper half of (θ2, θ3, c) at depth 1, its upper half at depth 2.
    let child = t.split(ROOT, 31).unwrap();
    let grandchild = t.split(child, 31).unwrap();
    let path = [ROOT, child, grandchild];
    let deep = [7.0; 5];
    let mut before = (added(&t, &path), counters(&t));

    // Outside the depth-1 d box (±50): branch 32 at every depth, trained to the root only,
    // kept in the root's one all-32 bin.
    for d in [[60.0, 0.0, 0.0], [0.0, -99.0, 0.0], [0.0, 0.0, 300.0]] {
        assert_eq!(t.train(&pattern8(deep, d)).unwrap(), TreeEvent::Trained);
    }
    let after = (added(&t, &path), counters(&t));
    assert_eq!(after.0, [before.0[0] + 3, before.0[1], before.0[2]]);
    assert_eq!(after.1[0].1, before.1[0].1 + 1, "one new bin");
    assert_eq!(after.1[0].2, before.1[0].2 + 3, "each pattern stored once");
    assert_eq!(after.1[1..], before.1[1..]);
    before = after;

    // Inside the depth-1 box, outside the depth-2 one (±25): root and child only.
    t.train(&pattern8(deep, [30.0, 0.0, 0.0])).unwrap();
    let after = (added(&t, &path), counters(&t));
    assert_eq!(after.0, [before.0[0] + 1, before.0[1] + 1, before.0[2]]);
    assert_eq!(
        (after.1[1].1, after.1[1].2),
        (before.1[1].1 + 1, before.1[1].2 + 1)
    );
    assert_eq!(after.1[2], before.1[2]);
    assert_eq!(recount(&t), counters(&t));

    // Cut and split again: the stopped patterns' bins stay where they stopped.
    t.cut(child);
    let child = t.split(ROOT, 31).unwrap();
    let grandchild = t.split(child, 31).unwrap();
    assert_eq!(recount(&t), counters(&t));
    let reach = |id: u32| {
        let node = &t.nodes[id as usize];
        node.bins
            .iter()
            .map(|&b| t.store.bins().key(b).reach())
            .min()
    };
    assert_eq!(reach(ROOT), Some(0));
    assert_eq!(reach(child), Some(1));
    assert_eq!(reach(grandchild), Some(3));
}

#[test]
fn queries_and_known_patterns_at_d_zero_lie_in_every_node_down_the_path() {
    let mut t = tree8();
    let mut rng = ChaCha8Rng::seed_from_u64(11);
    for _ in 0..300 {
        let at = std::array::from_fn(|_| rng.random_range(0.0..8.0));
        t.train(&pattern8(at, [0.0; 3])).unwrap();
    }
    // The lower half of (θ2, θ3, c) twice: boxes that hold the camera zero.
    let child = t.split(ROOT, 0).unwrap();
    let grandchild = t.split(child, 0).unwrap();
    let query = pattern8([0.5; 5], [0.0; 3]).input;
    assert_eq!(t.descend(t.rule().key(&query, 3)).deepest(), grandchild);
    for id in [ROOT, child, grandchild] {
        let anchor = t.nodes[id as usize].region.known_anchor();
        let anchor = anchor.expect("c = 0, d = 0 is in the box");
        assert_eq!(
            anchor.fixed_rows::<3>(5),
            Vector3::zeros(),
            "d = 0 in the middle"
        );
    }
}
