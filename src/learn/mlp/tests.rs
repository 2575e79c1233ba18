//! The net's gradient against finite differences, and Adam on a toy problem.

use super::adam::Adam;
use super::network::{Input, Network};
use super::replay::{Replay, Sample};
use nalgebra::Vector3;
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

#[test]
fn the_gradient_matches_finite_differences() {
    let mut rng = ChaCha8Rng::seed_from_u64(3);
    let mut net = Network::new(6, &mut rng);
    // Biases away from zero, so that their gradients are checked off the start value too.
    for p in net.params_mut() {
        *p += rng.random_range(-0.3..0.3);
    }
    let x = Input::from_fn(|_, _| rng.random_range(-1.0..1.0));
    let target = Vector3::new(0.4, -1.1, 0.7);
    let mut gradient = vec![0.0; net.params().len()];
    net.accumulate_gradient(&x, &target, &mut gradient);
    let h = 1e-6;
    for (i, analytic) in gradient.iter().enumerate() {
        let loss_at = |delta: f64| {
            let mut probe = net.clone();
            probe.params_mut()[i] += delta;
            0.5 * (probe.forward(&x) - target).norm_squared()
        };
        let numeric = (loss_at(h) - loss_at(-h)) / (2.0 * h);
        assert!(
            (numeric - analytic).abs() < 1e-7 * (1.0 + numeric.abs()),
            "parameter {i}: {analytic} against {numeric}"
        );
    }
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
fn the_buffer_keeps_the_newest_and_drops_before_a_number() {
    let sample = |seq| Sample {
        input: Input::zeros(),
        target: Vector3::zeros(),
        seq,
    };
    let mut replay = Replay::new(3);
    (0..5).for_each(|seq| replay.push(sample(seq)));
    assert_eq!(replay.len(), 3);
    assert_eq!(replay.get(0).map(|s| s.seq), Some(2));
    replay.drop_before(4);
    assert_eq!(replay.len(), 1);
    assert_eq!(replay.get(0).map(|s| s.seq), Some(4));
}
