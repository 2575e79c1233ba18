//! The net's gradient against finite differences, and Adam on a toy problem.

use super::adam::Adam;
use super::network::{Input, Network};
use super::replay_buffer::{Replay, Sample};
use nalgebra::Vector3;
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

/// The gradient of `loss` at the net's parameters by central differences.
fn numeric_gradient(net: &Network, loss: impl Fn(&mut Network) -> f64) -> Vec<f64> {
    let h = 1e-6;
    (0..net.params().len())
        .map(|i| {
            let at = |delta: f64| {
                let mut probe = net.clone();
                probe.params_mut()[i] += delta;
                loss(&mut probe)
            };
            (at(h) - at(-h)) / (2.0 * h)
        })
        .collect()
}

fn assert_close(analytic: &[f64], numeric: &[f64]) {
    for (i, (a, n)) in analytic.iter().zip(numeric).enumerate() {
        assert!(
            (a - n).abs() < 1e-7 * (1.0 + n.abs()),
            "parameter {i}: {a} against {n}"
        );
    }
}

/// A net with every parameter moved off its start value, an input and a target.
fn probe() -> (Network, Input, Vector3<f64>) {
    let mut rng = ChaCha8Rng::seed_from_u64(3);
    let mut net = Network::new(6, &mut rng);
    for p in net.params_mut() {
        *p += rng.random_range(-0.3..0.3);
    }
    let x = Input::from_fn(|_, _| rng.random_range(-1.0..1.0));
    (net, x, Vector3::new(0.4, -1.1, 0.7))
}

#[test]
fn the_gradient_matches_finite_differences() {
    let (mut net, x, target) = probe();
    let mut gradient = vec![0.0; net.params().len()];
    net.accumulate_gradient(&x, &target, &mut gradient);
    let numeric = numeric_gradient(&net, |n| 0.5 * (n.forward(&x) - target).norm_squared());
    assert_close(&gradient, &numeric);
}

#[test]
fn the_anchored_gradient_matches_finite_differences() {
    let (mut net, x, target) = probe();
    let rest = Input::new(x[0], x[1], -0.3, 0.2, 0.5);
    let mut gradient = vec![0.0; net.params().len()];
    net.accumulate_anchored_gradient(&x, &rest, &target, &mut gradient);
    let numeric = numeric_gradient(&net, |n| {
        let at_rest = n.forward(&rest);
        0.5 * (n.forward(&x) - at_rest - target).norm_squared()
    });
    assert_close(&gradient, &numeric);
}

#[test]
fn adam_finds_the_minimum_of_a_quadratic() {
    let mut adam = Adam::new(0.05, 2);
    let mut p = [3.0, -2.0];
    for _ in 0..2000 {
        let gradient = [2.0 * (p[0] - 1.0), 20.0 * (p[1] + 0.5)];
        adam.step(&mut p, &gradient);
    }
    assert!(
        (p[0] - 1.0).abs() < 1e-3 && (p[1] + 0.5).abs() < 1e-3,
        "{p:?}"
    );
}

#[test]
fn the_buffer_keeps_the_newest_and_drops_before_and_since_a_trial() {
    let sample = |trial| Sample {
        input: Input::zeros(),
        centred: Input::zeros(),
        target: Vector3::zeros(),
        trial,
    };
    let mut replay = Replay::new(3);
    (0..5).for_each(|trial| replay.push(sample(trial)));
    assert_eq!(replay.len(), 3);
    assert_eq!(replay.get(0).map(|s| s.trial), Some(2));
    replay.drop_before(3);
    assert_eq!(replay.len(), 2);
    assert_eq!(replay.get(0).map(|s| s.trial), Some(3));
    replay.drop_since(4);
    assert_eq!(replay.len(), 1);
    assert_eq!(replay.get(0).map(|s| s.trial), Some(3));
}

#[test]
fn an_anchored_learner_never_moves_for_a_centred_target() {
    use super::{Mlp, MlpSettings};
    use crate::learn::{Learner, Observation};
    let settings = MlpSettings {
        hidden: 8,
        anchored: true,
        ..MlpSettings::default()
    };
    let bounds = [
        (-10.0, 80.0),
        (40.0, 145.0),
        (-512.0, 256.0),
        (-512.0, 256.0),
        (-150.0, 300.0),
    ];
    let mut learner = Mlp::new(settings, bounds);
    let centred = Input::new(30.0, 90.0, 0.0, 0.0, 0.0);
    assert_eq!(learner.predict(&centred), Vector3::zeros(), "untrained");
    let pose = |theta: [f64; 3], c: [f64; 3]| Observation {
        theta_deg: Vector3::from(theta),
        c: Vector3::from(c),
    };
    let path = [
        pose([0.0, 30.0, 90.0], [40.0, -20.0, 30.0]),
        pose([3.0, 32.0, 87.0], [10.0, -5.0, 8.0]),
        pose([4.0, 33.0, 86.0], [0.0, 0.0, 0.0]),
    ];
    learner.learn(&path).unwrap();
    assert_eq!(learner.predict(&centred), Vector3::zeros(), "trained");
    assert_ne!(
        learner.predict(&Input::new(30.0, 90.0, 20.0, 0.0, 0.0)),
        Vector3::zeros()
    );
}
