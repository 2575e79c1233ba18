//! Tests of the perceptron: exact fits, forgetting, singular systems, idle inputs.

use super::*;
use nalgebra::{DMatrix, SVector};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

/// Perceptron settings of `sum_sets` sets of `set_size` patterns.
fn sets(sum_sets: usize, set_size: usize) -> PerceptronSettings {
    PerceptronSettings { sum_sets, set_size }
}

type P5 = Perceptron<5, 6>;

type P8 = Perceptron<8, 9>;

fn random_input<const N: usize>(rng: &mut ChaCha8Rng) -> SVector<f64, N> {
    SVector::from_fn(|_, _| rng.random_range(-1.0..=1.0))
}

fn random_map<const M: usize>(rng: &mut ChaCha8Rng) -> SMatrix<f64, 3, M> {
    SMatrix::from_fn(|_, _| rng.random_range(-10.0..=10.0))
}

fn apply<const N: usize, const M: usize>(
    map: &SMatrix<f64, 3, M>,
    u: &SVector<f64, N>,
) -> Vector3<f64> {
    map * Perceptron::<N, M>::augmented(u)
}

fn train(p: &mut P5, map: &SMatrix<f64, 3, 6>, n: usize, rng: &mut ChaCha8Rng) {
    for _ in 0..n {
        let u = random_input(rng);
        p.add(&u, &apply(map, &u), 0);
    }
    p.refit();
}

fn max_miss(p: &P5, map: &SMatrix<f64, 3, 6>, rng: &mut ChaCha8Rng) -> f64 {
    (0..50)
        .map(|_| {
            let u = random_input(rng);
            (p.answer(&u).expect("fitted") - apply(map, &u)).amax()
        })
        .fold(0.0, f64::max)
}

#[test]
fn recovers_a_linear_map_exactly() {
    let mut rng = ChaCha8Rng::seed_from_u64(1);
    let map = random_map(&mut rng);
    let mut p = P5::new(sets(5, 1000));
    train(&mut p, &map, 40, &mut rng);
    assert!(max_miss(&p, &map, &mut rng) < 1e-9);
}

#[test]
fn incremental_sums_equal_a_batch_least_squares_fit() {
    let mut rng = ChaCha8Rng::seed_from_u64(2);
    let map = random_map::<6>(&mut rng);
    let mut p = P5::new(sets(3, 10_000));
    let n = 300;
    let mut a = DMatrix::<f64>::zeros(n, 6);
    let mut b = DMatrix::<f64>::zeros(n, 3);
    for row in 0..n {
        let u = random_input(&mut rng);
        // A curved target, so the fit has residuals to balance.
        let t = apply(&map, &u) + Vector3::repeat(3.0 * u[0] * u[1] + u[4].powi(3));
        p.add(&u, &t, 0);
        a.row_mut(row).copy_from(&P5::augmented(&u).transpose());
        b.row_mut(row).copy_from(&t.transpose());
    }
    p.refit();
    let batch = a.svd(true, true).solve(&b, 1e-12).unwrap();
    let fitted = p.weights.expect("fitted");
    for joint in 0..3 {
        for k in 0..6 {
            let (inc, bat) = (fitted[(joint, k)], batch[(k, joint)]);
            assert!(
                (inc - bat).abs() < 1e-9 * (1.0 + bat.abs()),
                "{inc} vs {bat}"
            );
        }
    }
}

#[test]
fn forgets_an_old_map_within_one_set_size() {
    let mut rng = ChaCha8Rng::seed_from_u64(3);
    let (old, new) = (random_map(&mut rng), random_map(&mut rng));
    let mut p = P5::new(sets(5, 1000));
    train(&mut p, &old, 1000, &mut rng);
    assert!(max_miss(&p, &old, &mut rng) < 1e-9);
    train(&mut p, &new, 500, &mut rng);
    // The current set (started at pattern 601) still holds 400 old patterns.
    assert!(max_miss(&p, &new, &mut rng) > 1e-3);
    train(&mut p, &new, 500, &mut rng);
    assert!(max_miss(&p, &new, &mut rng) < 1e-9);
}

#[test]
fn a_singular_system_has_no_answer() {
    let mut rng = ChaCha8Rng::seed_from_u64(4);
    let map = random_map::<6>(&mut rng);
    let fit = |inputs: &mut dyn FnMut(&mut ChaCha8Rng) -> SVector<f64, 5>, n: usize| {
        let mut rng = ChaCha8Rng::seed_from_u64(5);
        let mut p = P5::new(sets(2, 1000));
        for _ in 0..n {
            let u = inputs(&mut rng);
            p.add(&u, &apply(&map, &u), 0);
        }
        p.refit();
        p.answer(&SVector::zeros())
    };
    assert_eq!(
        P5::new(sets(1, 10)).answer(&SVector::zeros()),
        None,
        "no patterns"
    );
    assert_eq!(
        fit(&mut random_input, 5),
        None,
        "fewer patterns than unknowns"
    );
    let mut flat = |rng: &mut ChaCha8Rng| {
        let mut u = random_input::<5>(rng);
        u[2] = 0.25;
        u
    };
    assert_eq!(fit(&mut flat, 100), None, "an input that never varies");
    let mut tied = |rng: &mut ChaCha8Rng| {
        let mut u = random_input::<5>(rng);
        u[3] = 0.5 * u[1] - 0.2 * u[0];
        u
    };
    assert_eq!(fit(&mut tied, 100), None, "inputs that move together");
    assert!(fit(&mut random_input, 100).is_some());
}

#[test]
fn recovers_a_linear_8_input_map_exactly() {
    let mut rng = ChaCha8Rng::seed_from_u64(6);
    let map = random_map::<9>(&mut rng);
    let mut p = P8::new(sets(5, 1000));
    for _ in 0..60 {
        let u = random_input::<8>(&mut rng);
        p.add(&u, &apply(&map, &u), 0);
    }
    p.refit();
    for _ in 0..50 {
        let u = random_input::<8>(&mut rng);
        let miss = (p.answer(&u).expect("fitted") - apply(&map, &u)).amax();
        assert!(miss < 1e-9, "{miss}");
    }
}

#[test]
fn inputs_asked_at_zero_that_stayed_there_get_no_weight_and_the_rest_is_exact() {
    // lin8 before its first trial: every pattern ends at d = 0 (give or take rounding).
    let mut rng = ChaCha8Rng::seed_from_u64(7);
    let map = random_map::<9>(&mut rng);
    let mut p = P8::new(sets(2, 1000)).asked_at_zero(5..8);
    let at_d_zero = |rng: &mut ChaCha8Rng| {
        let mut u = random_input::<8>(rng);
        u.fixed_rows_mut::<3>(5).fill(0.0);
        u[6] = 1e-15;
        u
    };
    let mut plain = P8::new(sets(2, 1000));
    for _ in 0..30 {
        let u = at_d_zero(&mut rng);
        p.add(&u, &apply(&map, &u), 0);
        plain.add(&u, &apply(&map, &u), 0);
    }
    p.refit();
    plain.refit();
    assert_eq!(
        plain.answer(&SVector::zeros()),
        None,
        "idle inputs are singular"
    );
    let u = at_d_zero(&mut rng);
    assert!((p.answer(&u).expect("fitted") - apply(&map, &u)).amax() < 1e-9);
    let weights = p.weights.expect("fitted");
    assert!(weights.columns(5, 3).iter().all(|&w| w == 0.0));
    // Once d varies, it is fitted like any input.
    for _ in 0..30 {
        let u = random_input::<8>(&mut rng);
        p.add(&u, &apply(&map, &u), 0);
    }
    p.refit();
    let u = random_input::<8>(&mut rng);
    // The current set still holds the d = 0 patterns, which the map fits too.
    assert!((p.answer(&u).expect("fitted") - apply(&map, &u)).amax() < 1e-9);
}

/// Trains patterns numbered `seqs` of `map`, then refits.
fn train_numbered(
    p: &mut P5,
    map: &SMatrix<f64, 3, 6>,
    seqs: std::ops::Range<u64>,
    rng: &mut ChaCha8Rng,
) {
    for seq in seqs {
        let u = random_input(rng);
        p.add(&u, &apply(map, &u), seq);
    }
    p.refit();
}

#[test]
fn a_change_drops_every_set_that_holds_an_older_pattern() {
    let mut rng = ChaCha8Rng::seed_from_u64(8);
    let (old, new) = (random_map(&mut rng), random_map(&mut rng));
    let mut p = P5::new(sets(5, 1000));
    train_numbered(&mut p, &old, 0..700, &mut rng);
    train_numbered(&mut p, &new, 700..760, &mut rng);
    assert_eq!(p.answering_oldest(), Some(0));
    assert!(
        p.forget_before(700),
        "sets from before pattern 700 are stale"
    );
    assert_eq!(
        p.answer(&SVector::zeros()),
        None,
        "nothing left to answer from"
    );
    let u = random_input(&mut rng);
    let stale = p
        .stale_answer(&u)
        .expect("the fit before the change is kept");
    assert!((stale - apply(&old, &u)).amax() < 0.5 * (apply(&new, &u) - apply(&old, &u)).amax());
    assert_eq!(p.answering_oldest(), None);
    assert!(!p.forget_before(700), "nothing stale is left");
    train_numbered(&mut p, &new, 760..800, &mut rng);
    assert_eq!(p.answering_oldest(), Some(760));
    assert!(max_miss(&p, &new, &mut rng) < 1e-9);
    assert!(
        !p.forget_before(760),
        "a set of patterns from after the change stays"
    );
    // The schedule started over: set 1 opens after 200 of the new patterns.
    train_numbered(&mut p, &new, 800..1000, &mut rng);
    assert_eq!(p.stagger.counts(), [240, 40, 0, 0, 0]);
}

#[test]
fn a_fit_supports_the_inputs_among_its_patterns_not_those_far_beyond() {
    let mut rng = ChaCha8Rng::seed_from_u64(12);
    let map = random_map(&mut rng);
    // Patterns spread over the whole box: every input in it is supported.
    let mut p = P5::new(sets(5, 1000));
    train(&mut p, &map, 200, &mut rng);
    assert!(p.supports(&SVector::repeat(1.0)) && p.supports(&SVector::repeat(-1.0)));
    // 40 patterns in the middle tenth of the box: the middle is supported, a corner is not.
    let mut q = P5::new(sets(5, 1000));
    for _ in 0..40 {
        let u = random_input::<5>(&mut rng) * 0.1;
        q.add(&u, &apply(&map, &u), 0);
    }
    q.refit();
    assert!(q.supports(&SVector::zeros()));
    assert!(q.supports(&SVector::repeat(0.05)));
    assert!(!q.supports(&SVector::repeat(1.0)));
}
