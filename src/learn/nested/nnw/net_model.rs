//! The Nested Network's node model: a small feed-forward net, nudged by back-propagation
//! for every pattern it takes in and re-trained by conjugate gradients on a sample of its
//! box's stored patterns after a trial (study §3.2.2).

use crate::learn::baselines::net::{minimize, BatchLoss, DenseNet};
use crate::learn::nested::tree::{Approximator, Sample};
use nalgebra::{SVector, Vector3};
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;
use std::cell::RefCell;

/// The nets answer Δθ divided by this (degrees), so their targets stay within about ±1.
/// (10° gave twice the 3-step distance and more lost objects over 2,000 trials.)
const OUTPUT_SCALE_DEG: f64 = 30.0;
/// Learning rate of the back-propagation step for each pattern taken in.
const ONLINE_RATE: f64 = 0.02;
/// Conjugate-gradient iterations of a re-training. Over 2,000 trials and seeds 1–40, 50
/// leave the 3-step distance at 0.35 mm on average, 75 at 0.30 and 100 at 0.29 (with the
/// line search's 0.1 curvature test, 50 and 75; docs/RESULTS.md).
const CG_ITERATIONS: usize = 100;

/// A 5 → `hidden_units` (tanh) → 3 net over the node's local coordinates.
#[derive(Debug, Clone)]
pub struct NetModel {
    /// In a cell because a forward pass writes the net's activation buffers, and answers
    /// are asked for through a shared reference.
    net: RefCell<DenseNet<5, 3>>,
    /// Scratch for the back-propagation step.
    grad: Vec<f64>,
    wrange: f64,
    /// Whether the net has learned anything yet; it answers only then.
    trained: bool,
}

impl NetModel {
    /// A template for nets of `hidden` units whose weights are drawn in ±`wrange` when a
    /// node is made (a negative `wrange` counts as its size, a non-finite one as 0); the
    /// template's own weights are zero and never answer.
    pub(crate) fn template(hidden: usize, wrange: f64) -> Self {
        let wrange = if wrange.is_finite() {
            wrange.abs()
        } else {
            0.0
        };
        // (Every draw of an empty range is 0: the generator does not matter.)
        let net = DenseNet::new(hidden.max(1), 0.0, &mut ChaCha8Rng::seed_from_u64(0));
        NetModel {
            grad: vec![0.0; net.params().len()],
            net: RefCell::new(net),
            wrange,
            trained: false,
        }
    }
}

impl Approximator<5> for NetModel {
    const RETRAINED: bool = true;

    fn spawn(&self, rng: &mut ChaCha8Rng) -> Self {
        let hidden = self.net.borrow().hidden();
        NetModel {
            net: RefCell::new(DenseNet::new(hidden, self.wrange, rng)),
            grad: vec![0.0; self.grad.len()],
            wrange: self.wrange,
            trained: false,
        }
    }

    fn add(&mut self, input: &SVector<f64, 5>, target: &Vector3<f64>, _seq: u64) {
        let target = target / OUTPUT_SCALE_DEG;
        let net = self.net.get_mut();
        net.backprop_step(input, &target, ONLINE_RATE, &mut self.grad);
        self.trained = true;
    }

    fn refit(&mut self) {}

    fn answer(&self, input: &SVector<f64, 5>) -> Option<Vector3<f64>> {
        if !self.trained {
            return None;
        }
        let output = self.net.try_borrow_mut().ok()?.forward(input) * OUTPUT_SCALE_DEG;
        output.iter().all(|v| v.is_finite()).then_some(output)
    }

    fn retrain(&mut self, batch: &[Sample<5>]) {
        if batch.is_empty() {
            return;
        }
        let scaled: Vec<Sample<5>> = batch
            .iter()
            .map(|(x, t)| (*x, t / OUTPUT_SCALE_DEG))
            .collect();
        let net = self.net.get_mut();
        let mut params = net.params().to_vec();
        minimize(
            &mut BatchLoss::new(net, &scaled),
            &mut params,
            CG_ITERATIONS,
        );
        self.trained = true;
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::Rng;

    /// A smooth, curved mapping of the local box.
    fn smooth(u: &SVector<f64, 5>) -> Vector3<f64> {
        Vector3::new(
            8.0 * u[2] + 2.0 * u[0] * u[3],
            -5.0 * u[3] + (1.5 * u[1]).sin(),
            3.0 * u[4] - u[2] * u[2],
        )
    }

    fn batch(n: usize, rng: &mut ChaCha8Rng) -> Vec<Sample<5>> {
        (0..n)
            .map(|_| {
                let u = SVector::from_fn(|_, _| rng.random_range(-1.0..=1.0));
                (u, smooth(&u))
            })
            .collect()
    }

    fn rms_miss(model: &NetModel, samples: &[Sample<5>]) -> f64 {
        let sum: f64 = samples
            .iter()
            .map(|(u, t)| (model.answer(u).expect("trained") - t).norm_squared())
            .sum();
        (sum / samples.len() as f64).sqrt()
    }

    #[test]
    fn spawned_nets_draw_their_own_weights_in_wrange() {
        let template = NetModel::template(5, 0.1);
        assert!(template.net.borrow().params().iter().all(|&w| w == 0.0));
        let mut rng = ChaCha8Rng::seed_from_u64(1);
        let (a, b) = (template.spawn(&mut rng), template.spawn(&mut rng));
        let (a, b) = (a.net.into_inner(), b.net.into_inner());
        assert_eq!(a.hidden(), 5);
        assert!(a.params().iter().all(|w| w.abs() <= 0.1));
        assert_ne!(a.params(), b.params());
        assert_eq!(template.answer(&SVector::zeros()), None, "untrained");
    }

    #[test]
    fn online_steps_then_retraining_fit_a_smooth_mapping() {
        let mut rng = ChaCha8Rng::seed_from_u64(2);
        let mut model = NetModel::template(8, 0.1).spawn(&mut rng);
        let (train, test) = (batch(300, &mut rng), batch(200, &mut rng));
        for (u, t) in &train {
            model.add(u, t, 0);
        }
        let online = rms_miss(&model, &test);
        for _ in 0..10 {
            model.retrain(&train);
        }
        let retrained = rms_miss(&model, &test);
        // The targets' RMS is about 6°.
        assert!(
            retrained < 0.3,
            "RMS miss {retrained}° (online only: {online}°)"
        );
        assert!(retrained < 0.2 * online, "{retrained} vs {online}");
    }
}
