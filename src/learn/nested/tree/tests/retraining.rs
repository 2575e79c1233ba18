//! Tests of re-training (nnw): which nodes are due, and what they are re-trained on.

use super::*;

type Counted = NestedTree<Tally<true, 5>, Halving<5>, 5>;

fn counted(limit: usize, delay: usize) -> Counted {
    let mut settings = still(3);
    settings.retrain_limit = limit;
    settings.retrain_delay = delay;
    let root = Region::from_bounds(SVector::zeros(), SVector::repeat(8.0));
    NestedTree::new(
        settings,
        Halving::new(root),
        Tally::default(),
        Records::in_memory(),
        ChaCha8Rng::seed_from_u64(12),
    )
}

/// Point `k` of 64, each in a bin of its own: the centres of a 4×4×4 grid of depth-3
/// cells (cells are 1 wide), alternating between the upper and lower half of the rest.
fn point(k: usize) -> SVector<f64, 5> {
    let (a, b, c) = ((k % 4) as f64, ((k / 4) % 4) as f64, (k / 16) as f64);
    let rest = if k % 2 == 0 { 6.5 } else { 1.5 };
    SVector::from([2.0 * a + 0.5, 2.0 * b + 0.5, 2.0 * c + 0.5, rest, rest])
}

/// Trains point `k` three times, with targets (k, 1, 0), (k, 2, 0), (k, 3, 0).
fn train_thrice(t: &mut Counted, k: usize) {
    for i in 1..=3 {
        let target = Vector3::new(k as f64, f64::from(i), 0.0);
        t.train(&Pattern {
            input: point(k),
            target,
        })
        .unwrap();
    }
}

/// The newest pattern of each point in `points`, in node `id`'s local coordinates.
fn newest(t: &Counted, id: u32, points: impl Iterator<Item = usize>) -> Vec<Sample<5>> {
    let region = t.nodes[id as usize].region;
    points
        .map(|k| (region.local(&point(k)), Vector3::new(k as f64, 3.0, 0.0)))
        .collect()
}

fn sorted(mut batch: Vec<Sample<5>>) -> Vec<Sample<5>> {
    batch.sort_by(|a, b| a.1.x.total_cmp(&b.1.x));
    batch
}

fn last_batch(t: &Counted, id: u32) -> Vec<Sample<5>> {
    let batches = &t.nodes[id as usize].model.batches;
    sorted(batches.last().expect("re-trained").clone())
}

#[test]
fn retraining_takes_the_newest_pattern_of_every_bin_in_the_subtree() {
    let mut t = counted(1000, 1);
    (0..64).for_each(|k| train_thrice(&mut t, k));
    assert_eq!(t.stats().bins, 64);
    // Sub-box 31 (the upper half everywhere) holds the even points with a, b, c ≥ 2.
    let in_31 = |k: &usize| k % 2 == 0 && point(*k).iter().all(|&x| x >= 4.0);
    let child = t.split(ROOT, 31).unwrap();
    // A new child is re-trained at once on its own bins.
    let expected = newest(&t, child, (0..64).filter(in_31));
    assert_eq!(expected.len(), 4);
    assert_eq!(last_batch(&t, child), expected);
    // After the trial the root, fed 192 patterns, is due; its batch spans the child's
    // bins too. The child took in nothing new since its split.
    assert_eq!(t.retrain_due().unwrap(), 1);
    assert_eq!(last_batch(&t, ROOT), newest(&t, ROOT, 0..64));
    assert_eq!(t.nodes[child as usize].model.batches.len(), 1);
    assert_eq!(t.retrain_due().unwrap(), 0, "nothing new since");
}

#[test]
fn at_most_the_limit_of_bins_is_sampled_at_random() {
    let mut t = counted(10, 1);
    (0..64).for_each(|k| train_thrice(&mut t, k));
    assert_eq!(t.retrain_due().unwrap(), 1);
    let all = newest(&t, ROOT, 0..64);
    let first = last_batch(&t, ROOT);
    assert_eq!(first.len(), 10);
    assert!(
        first.windows(2).all(|w| w[0].1.x < w[1].1.x),
        "distinct bins"
    );
    assert!(
        first.iter().all(|s| all.contains(s)),
        "newest patterns only"
    );
    (0..64).for_each(|k| train_thrice(&mut t, k));
    t.retrain_due().unwrap();
    assert_ne!(last_batch(&t, ROOT), first, "a fresh draw each time");
}

#[test]
fn a_node_waits_for_the_delay_of_new_patterns() {
    let mut t = counted(1000, 7);
    train_thrice(&mut t, 0);
    train_thrice(&mut t, 2);
    assert_eq!(t.retrain_due().unwrap(), 0, "6 new patterns");
    let child = t.split(ROOT, 31).unwrap();
    assert_eq!(t.nodes[child as usize].model.batches.len(), 1);
    train_thrice(&mut t, 62); // in sub-box 31: 9 for the root, 3 for the child
    assert_eq!(t.retrain_due().unwrap(), 1);
    assert_eq!(t.nodes[ROOT as usize].model.batches.len(), 1);
    train_thrice(&mut t, 62);
    assert_eq!(
        t.retrain_due().unwrap(),
        0,
        "root 3 new, child 6 over two trials"
    );
    train_thrice(&mut t, 62);
    // The child counts its patterns across trials until it is re-trained.
    assert_eq!(t.retrain_due().unwrap(), 1);
    assert_eq!(t.nodes[child as usize].model.batches.len(), 2);
    assert_eq!(t.nodes[ROOT as usize].model.batches.len(), 1);
}

#[test]
fn learners_that_are_not_retrained_book_nothing() {
    let mut t = tree(still(3));
    let mut rng = ChaCha8Rng::seed_from_u64(13);
    train_random(&mut t, 200, &mut rng);
    assert!(t.retraining.is_idle());
    assert_eq!(t.retrain_due().unwrap(), 0);
}
