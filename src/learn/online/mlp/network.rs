//! The network: 5 inputs, two layers of tanh units, 3 linear outputs, with its weights in
//! one flat vector (for Adam) and its activations in buffers allocated once, so a forward
//! or backward pass allocates nothing.

use crate::learn::baselines::net::tanh;
use nalgebra::{SVector, Vector3};
use rand::Rng;

/// A network input (already scaled).
pub(super) type Input = SVector<f64, 5>;

const INPUTS: usize = 5;
const OUTPUTS: usize = 3;

/// A 5 → hidden → hidden → 3 perceptron.
#[derive(Debug, Clone, PartialEq)]
pub(super) struct Network {
    hidden: usize,
    /// W1 (hidden × 5), b1, W2 (hidden × hidden), b2, W3 (3 × hidden), b3; matrices
    /// row-major.
    params: Vec<f64>,
    /// Each hidden layer's activations, then its error signals.
    first: Vec<f64>,
    second: Vec<f64>,
    first_delta: Vec<f64>,
    second_delta: Vec<f64>,
}

/// The parameters of one layer: its row-major weights and its biases.
type Layer<'a> = (&'a [f64], &'a [f64]);

impl Network {
    /// A net with `hidden` units per layer: the hidden layers' weights drawn uniformly in
    /// ±√(6/(fan-in + fan-out)) (Glorot), the output layer's and every bias zero, so the
    /// untrained net proposes no move (a random one would lose the target in most of the
    /// first trials, as a learner with no data should not).
    pub(super) fn new(hidden: usize, rng: &mut impl Rng) -> Network {
        let mut params = Vec::with_capacity(Self::param_count(hidden));
        for (inputs, outputs) in [(INPUTS, hidden), (hidden, hidden)] {
            let limit = (6.0 / (inputs + outputs) as f64).sqrt();
            params.extend((0..inputs * outputs).map(|_| rng.random_range(-limit..=limit)));
            params.extend(std::iter::repeat_n(0.0, outputs));
        }
        params.resize(Self::param_count(hidden), 0.0);
        Network {
            hidden,
            params,
            first: vec![0.0; hidden],
            second: vec![0.0; hidden],
            first_delta: vec![0.0; hidden],
            second_delta: vec![0.0; hidden],
        }
    }

    /// The weights and biases of a net with `hidden` units per layer.
    pub(super) fn param_count(hidden: usize) -> usize {
        hidden * (INPUTS + 1) + hidden * (hidden + 1) + OUTPUTS * (hidden + 1)
    }

    /// The parameters as one vector.
    pub(super) fn params(&self) -> &[f64] {
        &self.params
    }

    /// The parameters, to change in place.
    pub(super) fn params_mut(&mut self) -> &mut [f64] {
        &mut self.params
    }

    /// The three layers' parameters of `params`.
    fn layers(params: &[f64], hidden: usize) -> [Layer<'_>; 3] {
        let (w1, rest) = params.split_at(hidden * INPUTS);
        let (b1, rest) = rest.split_at(hidden);
        let (w2, rest) = rest.split_at(hidden * hidden);
        let (b2, rest) = rest.split_at(hidden);
        let (w3, b3) = rest.split_at(OUTPUTS * hidden);
        [(w1, b1), (w2, b2), (w3, b3)]
    }

    /// The net's output at `x` (the hidden activations stay in the buffers).
    pub(super) fn forward(&mut self, x: &Input) -> Vector3<f64> {
        let [first, second, out] = Self::layers(&self.params, self.hidden);
        dense(first, x.as_slice(), &mut self.first, true);
        dense(second, &self.first, &mut self.second, true);
        let mut y = [0.0; OUTPUTS];
        dense(out, &self.second, &mut y, false);
        Vector3::from(y)
    }

    /// Adds the gradient of ½‖f(x) − t‖² with respect to the parameters to `gradient`
    /// (laid out as the parameters); returns that loss.
    pub(super) fn accumulate_gradient(
        &mut self,
        x: &Input,
        target: &Vector3<f64>,
        gradient: &mut [f64],
    ) -> f64 {
        let error = self.forward(x) - target;
        self.backward(x, &error, gradient);
        0.5 * error.norm_squared()
    }

    /// Adds the gradient of ½‖f(x) − f(rest) − t‖² to `gradient`; returns that loss.
    pub(super) fn accumulate_anchored_gradient(
        &mut self,
        x: &Input,
        rest: &Input,
        target: &Vector3<f64>,
        gradient: &mut [f64],
    ) -> f64 {
        let at_rest = self.forward(rest);
        let error = self.forward(x) - at_rest - target;
        self.backward(x, &error, gradient);
        self.forward(rest);
        self.backward(rest, &-error, gradient);
        0.5 * error.norm_squared()
    }

    /// Adds the gradient of `error`·f(x) to `gradient`, from the activations of the last
    /// forward pass, which must have been at `x`.
    fn backward(&mut self, x: &Input, error: &Vector3<f64>, gradient: &mut [f64]) {
        let hidden = self.hidden;
        let [_, (w2, _), (w3, _)] = Self::layers(&self.params, hidden);
        let (g1, rest) = gradient.split_at_mut(hidden * (INPUTS + 1));
        let (g2, g3) = rest.split_at_mut(hidden * (hidden + 1));
        outer(g3, error.as_slice(), &self.second);
        back(w3, error.as_slice(), &self.second, &mut self.second_delta);
        outer(g2, &self.second_delta, &self.first);
        back(w2, &self.second_delta, &self.first, &mut self.first_delta);
        outer(g1, &self.first_delta, x.as_slice());
    }
}

/// `out` = W·`input` + b, through tanh if `squash`.
fn dense((weights, biases): Layer<'_>, input: &[f64], out: &mut [f64], squash: bool) {
    for ((o, row), b) in out
        .iter_mut()
        .zip(weights.chunks_exact(input.len()))
        .zip(biases)
    {
        let sum = row.iter().zip(input).map(|(w, x)| w * x).sum::<f64>() + b;
        *o = if squash { tanh(sum) } else { sum };
    }
}

/// Adds a layer's gradient to `gradient` (its weights row-major, then its biases): the
/// outer product of its error signals `delta` and its `input`, and `delta`.
fn outer(gradient: &mut [f64], delta: &[f64], input: &[f64]) {
    let (weights, biases) = gradient.split_at_mut(delta.len() * input.len());
    for (row, d) in weights.chunks_exact_mut(input.len()).zip(delta) {
        for (g, x) in row.iter_mut().zip(input) {
            *g += d * x;
        }
    }
    for (g, d) in biases.iter_mut().zip(delta) {
        *g += d;
    }
}

/// The error signals of a tanh layer with activations `below` under a layer of `weights`
/// (row-major, one row per unit above) whose error signals are `delta`.
fn back(weights: &[f64], delta: &[f64], below: &[f64], out: &mut [f64]) {
    out.fill(0.0);
    for (row, d) in weights.chunks_exact(below.len()).zip(delta) {
        for (o, w) in out.iter_mut().zip(row) {
            *o += w * d;
        }
    }
    for (o, a) in out.iter_mut().zip(below) {
        *o *= 1.0 - a * a;
    }
}
