//! The network: I inputs, one layer of tanh hidden units, O linear outputs. Its weights are
//! one flat parameter vector (for conjugate gradients); the hidden buffers are allocated
//! once, so a forward or backward pass allocates nothing.

use super::tanh::tanh;
use nalgebra::SVector;
use rand::Rng;

/// A dense I → hidden (tanh) → O (linear) network.
#[derive(Debug, Clone, PartialEq)]
pub struct DenseNet<const I: usize, const O: usize> {
    hidden: usize,
    /// Layout: W1 (hidden × I, row-major), b1 (hidden), W2 (O × hidden, row-major), b2 (O).
    params: Vec<f64>,
    activations: Vec<f64>,
}

impl<const I: usize, const O: usize> DenseNet<I, O> {
    /// A net with `hidden` units and every weight drawn uniformly in ±`wrange`.
    pub fn new(hidden: usize, wrange: f64, rng: &mut impl Rng) -> Self {
        let count = hidden * (I + 1) + O * (hidden + 1);
        let params = (0..count)
            .map(|_| rng.random_range(-wrange..=wrange))
            .collect();
        DenseNet {
            hidden,
            params,
            activations: vec![0.0; hidden],
        }
    }

    /// Hidden units.
    pub fn hidden(&self) -> usize {
        self.hidden
    }

    /// The weights as one vector.
    pub fn params(&self) -> &[f64] {
        &self.params
    }

    /// The weights, to change in place.
    pub fn params_mut(&mut self) -> &mut [f64] {
        &mut self.params
    }

    /// The parameters as (W1, b1, W2, b2).
    pub(super) fn layers(params: &[f64], hidden: usize) -> (&[f64], &[f64], &[f64], &[f64]) {
        let (w1, rest) = params.split_at(hidden * I);
        let (b1, rest) = rest.split_at(hidden);
        let (w2, b2) = rest.split_at(O * hidden);
        (w1, b1, w2, b2)
    }

    /// Writes the hidden units' activations for `x` into `activations` (one per unit):
    /// the tanh of each unit's weighted sum (in index order from −0, as `Iterator::sum`
    /// does) plus its bias.
    fn hidden_layer(params: &[f64], x: &SVector<f64, I>, activations: &mut [f64]) {
        let (w1, b1, _, _) = Self::layers(params, activations.len());
        for ((a, row), b) in activations.iter_mut().zip(w1.chunks_exact(I)).zip(b1) {
            let row: &[f64; I] = row.try_into().expect("rows of I weights");
            let mut sum = -0.0;
            for i in 0..I {
                sum += row[i] * x[i];
            }
            *a = tanh(sum + b);
        }
    }

    /// The output layer's answer to the hidden `activations`.
    fn output_layer(params: &[f64], activations: &[f64]) -> SVector<f64, O> {
        let h = activations.len();
        let (_, _, w2, b2) = Self::layers(params, h);
        let mut out = [-0.0; O];
        for (j, a) in activations.iter().enumerate() {
            for (k, o) in out.iter_mut().enumerate() {
                *o += w2[k * h + j] * a;
            }
        }
        SVector::from_fn(|k, _| out[k] + b2[k])
    }

    /// The net's output for `x`.
    pub fn forward(&mut self, x: &SVector<f64, I>) -> SVector<f64, O> {
        Self::hidden_layer(&self.params, x, &mut self.activations);
        Self::output_layer(&self.params, &self.activations)
    }

    /// Adds ∂(½‖y − t‖²)/∂params for one pattern to `grad`; returns ½‖y − t‖².
    pub fn accumulate_gradient(
        &mut self,
        x: &SVector<f64, I>,
        target: &SVector<f64, O>,
        grad: &mut [f64],
    ) -> f64 {
        Self::hidden_layer(&self.params, x, &mut self.activations);
        Self::back_propagate(&self.params, &self.activations, x, target, grad)
    }

    /// Adds ∂(½‖y − t‖²)/∂params for the pattern (`x`, `target`) whose hidden activations
    /// are `activations` to `grad`; returns ½‖y − t‖².
    fn back_propagate(
        params: &[f64],
        activations: &[f64],
        x: &SVector<f64, I>,
        target: &SVector<f64, O>,
        grad: &mut [f64],
    ) -> f64 {
        let error = Self::output_layer(params, activations) - target;
        let h = activations.len();
        let (_, _, w2, _) = Self::layers(params, h);
        let (w1_grad, rest) = grad.split_at_mut(h * I);
        let (b1_grad, rest) = rest.split_at_mut(h);
        let (w2_grad, b2_grad) = rest.split_at_mut(O * h);
        // Unit by unit: its share of the error (summed over the outputs in order, from −0
        // as `Iterator::sum` starts), then its weights' gradients. Each gradient entry gets
        // one addition per pattern, so the order of units does not change a bit.
        let rows = w1_grad.chunks_exact_mut(I).zip(b1_grad);
        for (j, ((row, bias), a)) in rows.zip(activations).enumerate() {
            let mut back = -0.0;
            for (k, e) in error.iter().enumerate() {
                back += e * w2[k * h + j];
                w2_grad[k * h + j] += e * a;
            }
            let delta = back * (1.0 - a * a);
            for (g, v) in row.iter_mut().zip(x.iter()) {
                *g += delta * v;
            }
            *bias += delta;
        }
        for (b, e) in b2_grad.iter_mut().zip(error.iter()) {
            *b += e;
        }
        0.5 * error.norm_squared()
    }

    /// One online back-propagation step on one pattern with learning `rate`; returns the
    /// pattern's loss before the step. `grad` is scratch space of the parameters' length.
    pub fn backprop_step(
        &mut self,
        x: &SVector<f64, I>,
        target: &SVector<f64, O>,
        rate: f64,
        grad: &mut [f64],
    ) -> f64 {
        grad.fill(0.0);
        let loss = self.accumulate_gradient(x, target, grad);
        for (p, g) in self.params.iter_mut().zip(grad.iter()) {
            *p -= rate * g;
        }
        loss
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::{Vector2, Vector3};
    use rand::SeedableRng;
    use rand_chacha::ChaCha8Rng;

    #[test]
    fn the_gradient_matches_finite_differences() {
        let mut rng = ChaCha8Rng::seed_from_u64(1);
        let mut net: DenseNet<3, 2> = DenseNet::new(4, 0.8, &mut rng);
        let x = Vector3::new(0.3, -0.7, 0.5);
        let t = Vector2::new(0.2, -0.4);
        let mut grad = vec![0.0; net.params().len()];
        net.accumulate_gradient(&x, &t, &mut grad);
        let loss = |net: &mut DenseNet<3, 2>| 0.5 * (net.forward(&x) - t).norm_squared();
        for (i, analytic) in grad.iter().enumerate() {
            let h = 1e-6;
            let keep = net.params()[i];
            net.params_mut()[i] = keep + h;
            let up = loss(&mut net);
            net.params_mut()[i] = keep - h;
            let down = loss(&mut net);
            net.params_mut()[i] = keep;
            let numeric = (up - down) / (2.0 * h);
            assert!(
                (numeric - analytic).abs() < 1e-8,
                "parameter {i}: {numeric} vs {analytic}"
            );
        }
    }

    #[test]
    fn weights_start_inside_wrange() {
        let mut rng = ChaCha8Rng::seed_from_u64(2);
        let net: DenseNet<5, 3> = DenseNet::new(25, 0.1, &mut rng);
        assert_eq!(net.params().len(), 25 * 6 + 3 * 26);
        assert!(net.params().iter().all(|w| w.abs() <= 0.1));
    }

    #[test]
    fn backprop_steps_reduce_the_error_on_a_pattern() {
        let mut rng = ChaCha8Rng::seed_from_u64(3);
        let mut net: DenseNet<3, 2> = DenseNet::new(5, 0.5, &mut rng);
        let (x, t) = (Vector3::new(0.1, 0.2, 0.3), Vector2::new(0.5, -0.5));
        let mut grad = vec![0.0; net.params().len()];
        let first = net.backprop_step(&x, &t, 0.1, &mut grad);
        let mut last = first;
        for _ in 0..50 {
            last = net.backprop_step(&x, &t, 0.1, &mut grad);
        }
        assert!(last < first * 0.01, "{first} → {last}");
    }
}
