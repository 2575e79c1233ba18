//! The posterior against direct solves: the exact GP with the same kernel (many features)
//! and the batch Bayesian regression on the same features (any forgetting).

use super::features::{Features, Input};
use super::posterior::Posterior;
use nalgebra::{DMatrix, DVector, Vector3};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

/// `n` inputs in [−1, 1]⁵ and a smooth target of each.
fn data(n: usize, seed: u64) -> Vec<(Input, Vector3<f64>)> {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    (0..n)
        .map(|_| {
            let u = Input::from_fn(|_, _| rng.random_range(-1.0..1.0));
            let y = Vector3::new(u[0].sin() + u[1] * u[2], u[3] - 0.5 * u[4], u.norm());
            (u, y)
        })
        .collect()
}

fn features(count: usize, length_scales: &Input, signal: f64) -> Features {
    Features::new(
        count,
        length_scales,
        signal,
        &mut ChaCha8Rng::seed_from_u64(7),
    )
}

fn trained(
    features: &Features,
    noise: f64,
    forgetting: f64,
    data: &[(Input, Vector3<f64>)],
) -> Posterior {
    let mut posterior = Posterior::new(features.len(), noise, forgetting);
    let mut phi = DVector::zeros(features.len());
    for (u, y) in data {
        features.write(u, &mut phi);
        posterior.add(&phi, y);
    }
    posterior
}

/// The exact GP's posterior mean at `at`: k*ᵀ (K + σn² I)⁻¹ y.
fn exact_gp(
    data: &[(Input, Vector3<f64>)],
    at: &Input,
    ls: &Input,
    signal: f64,
    noise: f64,
) -> Vector3<f64> {
    let k = |a: &Input, b: &Input| {
        signal.powi(2) * (-0.5 * (a - b).component_div(ls).norm_squared()).exp()
    };
    let n = data.len();
    let gram = DMatrix::from_fn(n, n, |i, j| {
        k(&data[i].0, &data[j].0) + if i == j { noise * noise } else { 0.0 }
    });
    let targets = DMatrix::from_fn(n, 3, |i, j| data[i].1[j]);
    let alpha = gram.cholesky().unwrap().solve(&targets);
    let kstar = DVector::from_fn(n, |i, _| k(&data[i].0, at));
    Vector3::from_fn(|j, _| kstar.dot(&alpha.column(j)))
}

/// The largest gap, over a few inputs, between the answer with `count` features and the
/// exact GP's.
fn gap_to_the_exact_gp(count: usize) -> f64 {
    let (ls, signal, noise) = (Input::repeat(1.2), 1.0, 0.5);
    let train = data(12, 1);
    let features = features(count, &ls, signal);
    let mut posterior = trained(&features, noise, 1.0, &train);
    let mut phi = DVector::zeros(features.len());
    let mut worst: f64 = 0.0;
    for (u, _) in data(6, 2).iter().chain(&train[..3]) {
        features.write(u, &mut phi);
        let error = (posterior.predict(&phi) - exact_gp(&train, u, &ls, signal, noise)).amax();
        worst = worst.max(error);
    }
    worst
}

#[test]
fn with_many_features_the_answer_is_the_exact_gps() {
    let gaps = [30, 300, 3000].map(gap_to_the_exact_gp);
    println!("largest gaps to the exact GP with 30, 300, 3000 features: {gaps:.4?}");
    // Answers are of order 1; the gap is the features' Monte Carlo error, O(1/√D).
    assert!(
        gaps[2] < 0.05,
        "the sparse spectrum GP is off by {}",
        gaps[2]
    );
    assert!(
        gaps[2] < gaps[0] / 3.0,
        "more features come closer: {gaps:?}"
    );
}

#[test]
fn the_features_approximate_the_kernel() {
    let (ls, signal) = (Input::new(0.5, 1.0, 2.0, 0.7, 1.5), 1.3);
    let features = features(100_000, &ls, signal);
    let (mut a, mut b) = (
        DVector::zeros(features.len()),
        DVector::zeros(features.len()),
    );
    for ((u, _), (v, _)) in data(10, 5).iter().zip(&data(10, 6)) {
        features.write(u, &mut a);
        features.write(v, &mut b);
        let kernel = signal.powi(2) * (-0.5 * (u - v).component_div(&ls).norm_squared()).exp();
        assert!(
            (a.dot(&b) - kernel).abs() < 0.02,
            "{} against {kernel}",
            a.dot(&b)
        );
    }
}

#[test]
fn rank_one_updates_match_a_batch_solve() {
    for forgetting in [1.0, 0.97] {
        let (ls, noise) = (Input::repeat(0.8), 0.05);
        let train = data(60, 3);
        let features = features(40, &ls, 1.5);
        let mut posterior = trained(&features, noise, forgetting, &train);
        let batch = batch_weights(&features, &train, noise, forgetting, |_| true);
        let gap = (posterior.weights() - &batch).amax();
        assert!(
            gap < 1e-9 * batch.amax().max(1.0),
            "λ {forgetting}: off by {gap}"
        );
    }
}

/// The weights a batch solve gives the patterns of `train` that `kept(t)` keeps, each
/// weighed as the posterior forgets: A = λⁿ σn² I + Σ λⁿ⁻ᵗ φₜφₜᵀ, b = Σ λⁿ⁻ᵗ φₜ yₜᵀ, n
/// counting every pattern of `train`.
fn batch_weights(
    features: &Features,
    train: &[(Input, Vector3<f64>)],
    noise: f64,
    forgetting: f64,
    kept: impl Fn(usize) -> bool,
) -> DMatrix<f64> {
    let d = features.len();
    let n = train.len() as i32;
    let mut a = DMatrix::from_diagonal_element(d, d, forgetting.powi(n) * noise * noise);
    let mut b = DMatrix::zeros(d, 3);
    let mut phi = DVector::zeros(d);
    for (t, (u, y)) in train.iter().enumerate().filter(|&(t, _)| kept(t)) {
        features.write(u, &mut phi);
        let weight = forgetting.powi(n - 1 - t as i32);
        a += &phi * phi.transpose() * weight;
        b += &phi * y.transpose() * weight;
    }
    a.cholesky().unwrap().solve(&b)
}

#[test]
fn patterns_taken_out_again_leave_the_batch_solve_of_the_others() {
    for forgetting in [1.0, 0.97] {
        let (ls, noise) = (Input::repeat(0.8), 0.05);
        let train = data(60, 5);
        let features = features(40, &ls, 1.5);
        let d = features.len();
        let mut posterior = Posterior::new(d, noise, forgetting);
        let mut phi = DVector::zeros(d);
        let tickets: Vec<f64> = train
            .iter()
            .map(|(u, y)| {
                features.write(u, &mut phi);
                posterior.add(&phi, y)
            })
            .collect();
        // The last ten out again, and one from the middle.
        let out = |t: usize| t >= 50 || t == 20;
        for (t, (u, y)) in train.iter().enumerate().filter(|&(t, _)| out(t)) {
            features.write(u, &mut phi);
            assert!(posterior.remove(&phi, y, tickets[t]));
        }
        let batch = batch_weights(&features, &train, noise, forgetting, |t| !out(t));
        let gap = (posterior.weights() - &batch).amax();
        assert!(
            gap < 1e-8 * batch.amax().max(1.0),
            "λ {forgetting}: off by {gap}"
        );
    }
}

#[test]
fn a_restart_keeps_the_answer_and_forgets_the_evidence() {
    let ls = Input::repeat(0.8);
    let train = data(30, 4);
    let features = features(60, &ls, 1.0);
    let mut posterior = trained(&features, 0.05, 1.0, &train);
    let mut phi = DVector::zeros(features.len());
    features.write(&train[0].0, &mut phi);
    let before = posterior.predict(&phi);
    posterior.restart_from_mean();
    assert!((posterior.predict(&phi) - before).amax() < 1e-12);
    // One pattern now moves the answer almost all the way to its target.
    let target = before + Vector3::repeat(1.0);
    posterior.add(&phi, &target);
    assert!((posterior.predict(&phi) - target).amax() < 0.05);
}

#[test]
fn an_anchored_learner_never_moves_for_a_centred_target() {
    use super::{Issgp, IssgpSettings};
    let settings = IssgpSettings {
        features: 50,
        anchored: true,
        ..IssgpSettings::default()
    };
    let mut learner = Issgp::new(
        settings,
        [
            (-10.0, 80.0),
            (40.0, 145.0),
            (-512.0, 256.0),
            (-512.0, 256.0),
            (-150.0, 300.0),
        ],
    );
    for (u, y) in data(20, 8) {
        learner.train(&(u * 100.0), &(y * 10.0));
    }
    let centred = Input::new(30.0, 90.0, 0.0, 0.0, 0.0);
    assert_eq!(learner.predict(&centred), Vector3::zeros());
    assert_ne!(
        learner.predict(&Input::new(30.0, 90.0, 20.0, 0.0, 0.0)),
        Vector3::zeros()
    );
}
