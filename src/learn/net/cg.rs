//! Conjugate-gradient minimisation (Polak–Ribière+, restarted when the direction stops
//! descending). The line search brackets the minimum along the direction by secant steps on
//! the directional derivative and accepts only points that satisfy the Armijo condition, so
//! every accepted step lowers the loss; on a quadratic it is exact and CG converges in as
//! many steps as there are dimensions.

/// A differentiable function of a parameter vector, evaluated in two steps: the value at
/// a point, then (when the search needs it) the gradient there.
pub trait Objective {
    /// The number of parameters.
    fn dimension(&self) -> usize;
    /// The value at `at`.
    fn value(&mut self, at: &[f64]) -> f64;
    /// Writes the gradient at the point of the last [`Objective::value`] into `grad`.
    fn gradient(&mut self, grad: &mut [f64]);
    /// The value at `at`; writes the gradient there into `grad`.
    fn evaluate(&mut self, at: &[f64], grad: &mut [f64]) -> f64 {
        let value = self.value(at);
        self.gradient(grad);
        value
    }
}

const ARMIJO: f64 = 1e-4;
/// A step is good enough once the directional derivative has shrunk to this fraction.
const CURVATURE: f64 = 0.1;
const MAX_LINE_STEPS: usize = 30;

fn dot(a: &[f64], b: &[f64]) -> f64 {
    a.iter().zip(b).map(|(x, y)| x * y).sum()
}

/// Scratch space and the point reached by a line search.
#[derive(Debug)]
struct LineSearch {
    trial: Vec<f64>,
    grad: Vec<f64>,
    best: Option<(f64, f64, Vec<f64>)>,
}

impl LineSearch {
    /// Searches from `x` along `direction` (slope `slope` < 0, value `value`) starting with
    /// step `step`; on success `self.grad` holds the gradient at `x + α·direction` and the
    /// result is (α, loss).
    fn run(
        &mut self,
        objective: &mut impl Objective,
        x: &[f64],
        direction: &[f64],
        value: f64,
        slope: f64,
        step: f64,
    ) -> Option<(f64, f64)> {
        self.best = None;
        let (mut low, mut low_slope) = (0.0, slope);
        let mut high: Option<f64> = None;
        let mut alpha = step;
        for _ in 0..MAX_LINE_STEPS {
            self.trial
                .iter_mut()
                .zip(x.iter().zip(direction))
                .for_each(|(t, (v, d))| *t = v + alpha * d);
            let f = objective.value(&self.trial);
            let armijo = f.is_finite() && f <= value + ARMIJO * alpha * slope;
            // (A step that does not lower the loss enough is halved without its gradient.)
            let f_slope = if armijo {
                objective.gradient(&mut self.grad);
                dot(&self.grad, direction)
            } else {
                f64::NAN
            };
            if armijo && self.best.as_ref().is_none_or(|b| f < b.1) {
                self.best = Some((alpha, f, self.grad.clone()));
            }
            if !armijo {
                high = Some(alpha);
            } else if f_slope.abs() <= CURVATURE * slope.abs() {
                return Some((alpha, f));
            } else if f_slope > 0.0 {
                high = Some(alpha);
            } else {
                (low, low_slope) = (alpha, f_slope);
            }
            let secant = |a: f64, sa: f64, b: f64, sb: f64| a - sa * (b - a) / (sb - sa);
            alpha = match high {
                Some(h) if !armijo => low + 0.5 * (h - low),
                Some(h) => secant(low, low_slope, alpha, f_slope)
                    .clamp(low + 0.1 * (h - low), h - 0.1 * (h - low)),
                None if f_slope < low_slope => secant(low, low_slope, alpha, f_slope)
                    .min(4.0 * alpha)
                    .max(2.0 * alpha),
                None => 2.0 * alpha,
            };
        }
        let (alpha, f, grad) = self.best.take()?;
        self.grad = grad;
        Some((alpha, f))
    }
}

/// Runs up to `iterations` conjugate-gradient steps from `x` (updated in place); returns
/// the loss after each accepted step, starting with the initial loss. Stops early once no
/// step lowers the loss.
pub fn minimize(objective: &mut impl Objective, x: &mut [f64], iterations: usize) -> Vec<f64> {
    let n = objective.dimension();
    let mut grad = vec![0.0; n];
    let mut loss = objective.evaluate(x, &mut grad);
    let mut losses = vec![loss];
    let mut direction: Vec<f64> = grad.iter().map(|g| -g).collect();
    let mut search = LineSearch {
        trial: vec![0.0; n],
        grad: vec![0.0; n],
        best: None,
    };
    let mut step = 1.0 / dot(&grad, &grad).sqrt().max(1e-12);
    for _ in 0..iterations {
        let mut slope = dot(&grad, &direction);
        if slope >= 0.0 {
            direction.iter_mut().zip(&grad).for_each(|(d, g)| *d = -g);
            slope = -dot(&grad, &grad);
        }
        if slope == 0.0 || !slope.is_finite() {
            break;
        }
        let Some((alpha, value)) = search.run(objective, x, &direction, loss, slope, step) else {
            break;
        };
        x.iter_mut()
            .zip(&direction)
            .for_each(|(v, d)| *v += alpha * d);
        let next = &search.grad;
        let beta = ((dot(next, next) - dot(next, &grad)) / dot(&grad, &grad).max(1e-300)).max(0.0);
        direction
            .iter_mut()
            .zip(next)
            .for_each(|(d, g)| *d = -g + beta * *d);
        grad.copy_from_slice(next);
        step = alpha;
        loss = value;
        losses.push(loss);
    }
    // Leave the objective's state at the accepted point.
    objective.value(x);
    losses
}

#[cfg(test)]
mod tests {
    use super::*;

    /// f(x) = Σ cᵢ (xᵢ − i)², an ill-conditioned quadratic (coefficients, last point).
    #[derive(Debug)]
    struct Quadratic(Vec<f64>, Vec<f64>);

    impl Quadratic {
        fn new(coefficients: Vec<f64>) -> Self {
            Quadratic(coefficients, Vec::new())
        }
    }

    impl Objective for Quadratic {
        fn dimension(&self) -> usize {
            self.0.len()
        }
        fn value(&mut self, at: &[f64]) -> f64 {
            self.1 = at.to_vec();
            let terms = self.0.iter().zip(at).enumerate();
            terms.map(|(i, (&c, &x))| c * (x - i as f64).powi(2)).sum()
        }
        fn gradient(&mut self, grad: &mut [f64]) {
            for (i, (&c, &x)) in self.0.iter().zip(&self.1).enumerate() {
                grad[i] = 2.0 * c * (x - i as f64);
            }
        }
    }

    #[test]
    fn cg_finds_the_minimum_of_a_quadratic() {
        let mut objective = Quadratic::new(vec![1.0, 10.0, 100.0, 0.5]);
        let mut x = vec![0.0; 4];
        let losses = minimize(&mut objective, &mut x, 200);
        assert!(*losses.last().unwrap() < 1e-10, "{losses:?}");
        for (i, v) in x.iter().enumerate() {
            assert!((v - i as f64).abs() < 1e-4, "{x:?}");
        }
    }

    #[test]
    fn every_cg_step_lowers_the_loss() {
        let mut objective = Quadratic::new(vec![3.0, 0.1, 30.0]);
        let mut x = vec![5.0, -5.0, 5.0];
        let losses = minimize(&mut objective, &mut x, 20);
        assert!(losses.windows(2).all(|w| w[1] < w[0]), "{losses:?}");
    }
}

#[cfg(test)]
mod net_tests {
    use super::*;
    use crate::learn::net::{BatchLoss, DenseNet};
    use nalgebra::{SVector, Vector1};
    use rand::{Rng, SeedableRng};
    use rand_chacha::ChaCha8Rng;

    fn smooth(x: &SVector<f64, 5>) -> f64 {
        (1.5 * x[0]).sin() + 0.5 * x[1] * x[2] - 0.4 * x[3] * x[3] + 0.3 * x[4]
    }

    fn batch(n: usize, rng: &mut ChaCha8Rng) -> Vec<(SVector<f64, 5>, SVector<f64, 1>)> {
        (0..n)
            .map(|_| {
                let x = SVector::<f64, 5>::from_fn(|_, _| rng.random_range(-1.0..1.0));
                (x, Vector1::new(smooth(&x)))
            })
            .collect()
    }

    #[test]
    fn cg_lowers_a_nets_batch_loss_at_every_step_and_fits_a_smooth_5d_function() {
        let mut rng = ChaCha8Rng::seed_from_u64(9);
        let train = batch(400, &mut rng);
        let mut net: DenseNet<5, 1> = DenseNet::new(20, 0.3, &mut rng);
        let mut params = net.params().to_vec();
        let losses = minimize(&mut BatchLoss::new(&mut net, &train), &mut params, 400);
        assert!(
            losses.windows(2).all(|w| w[1] < w[0]),
            "the loss falls at every step"
        );
        let test = batch(200, &mut rng);
        let mse = test
            .iter()
            .map(|(x, t)| (net.forward(x) - t).norm_squared())
            .sum::<f64>()
            / test.len() as f64;
        assert!(mse.sqrt() < 0.05, "RMS error on new points {}", mse.sqrt());
    }
}
