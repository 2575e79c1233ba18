//! Conjugate-gradient minimisation (Polak–Ribière+, restarted when the direction stops
//! descending). The line search keeps a bracket around the minimum along the direction
//! and steps to the minimum of the cubic through its ends' values and slopes (of the
//! parabola through the values where the far end's slope was not needed); it accepts only
//! points that satisfy the Armijo condition, so every accepted step lowers the loss, and
//! stops once the slope has shrunk to half. Each search starts from the step that would
//! change the loss as much as the last one did (Nocedal and Wright's guess), so most
//! searches end after one or two evaluations.

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
/// A step is good enough once the directional derivative has shrunk to this fraction (0.1
/// fitted `nnw`'s nets no better over 40 seeds and took a quarter more time:
/// docs/RESULTS.md).
const CURVATURE: f64 = 0.5;
const MAX_LINE_STEPS: usize = 30;

fn dot(a: &[f64], b: &[f64]) -> f64 {
    a.iter().zip(b).map(|(x, y)| x * y).sum()
}

/// A point on the search line: its step, the loss there and (where computed) the slope.
type LinePoint = (f64, f64, f64);

/// The step at the minimum of the cubic through `a` and `b`, or the secant step on their
/// slopes where the cubic has none (not finite if neither exists).
fn cubic_minimum((xa, fa, ga): LinePoint, (xb, fb, gb): LinePoint) -> f64 {
    let d1 = ga + gb - 3.0 * (fa - fb) / (xa - xb);
    let root = d1 * d1 - ga * gb;
    if root < 0.0 || !root.is_finite() {
        return xa - ga * (xb - xa) / (gb - ga);
    }
    let d2 = (xb - xa).signum() * root.sqrt();
    xb - (xb - xa) * (gb + d2 - d1) / (gb - ga + 2.0 * d2)
}

/// The step at the minimum of the parabola through `a` (with its slope) and the loss `fb`
/// at step `xb`.
fn quadratic_minimum((xa, fa, ga): LinePoint, (xb, fb): (f64, f64)) -> f64 {
    let width = xb - xa;
    xa - ga * width * width / (2.0 * (fb - fa - ga * width))
}

/// `guess` kept within `low..=high`; `fallback` (within them) where it is not finite.
fn safeguard(guess: f64, fallback: f64, low: f64, high: f64) -> f64 {
    if guess.is_finite() {
        guess.clamp(low, high)
    } else {
        fallback
    }
}

/// The far end of a bracket: its step, the loss there and its slope if computed.
type FarPoint = (f64, f64, Option<f64>);

/// The next step inside the bracket from `low` to `far`: the interpolated minimum, kept a
/// tenth of the bracket away from either end (its middle where the guess is not finite).
fn inside(low: LinePoint, far: FarPoint) -> f64 {
    let (h, h_value, h_slope) = far;
    let guess = match h_slope {
        Some(s) => cubic_minimum(low, (h, h_value, s)),
        None => quadratic_minimum(low, (h, h_value)),
    };
    let width = h - low.0;
    let (inner, outer) = (low.0 + 0.1 * width, h - 0.1 * width);
    safeguard(guess, low.0 + 0.5 * width, inner, outer)
}

/// Scratch space and the point reached by a line search.
#[derive(Debug)]
struct LineSearch {
    trial: Vec<f64>,
    grad: Vec<f64>,
    /// The lowest Armijo point so far (step, loss) and its gradient in `best_grad`.
    best: Option<(f64, f64)>,
    best_grad: Vec<f64>,
}

impl LineSearch {
    fn new(n: usize) -> Self {
        LineSearch {
            trial: vec![0.0; n],
            grad: vec![0.0; n],
            best: None,
            best_grad: vec![0.0; n],
        }
    }

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
        // The bracket: `low` passed the Armijo test and still descends (step 0 at first);
        // `high`, once found, lies past the minimum: its step, loss and slope if computed.
        let mut low: LinePoint = (0.0, value, slope);
        let mut high: Option<FarPoint> = None;
        let mut alpha = step;
        for _ in 0..MAX_LINE_STEPS {
            self.trial
                .iter_mut()
                .zip(x.iter().zip(direction))
                .for_each(|(t, (v, d))| *t = v + alpha * d);
            let f = objective.value(&self.trial);
            let armijo = f.is_finite() && f <= value + ARMIJO * alpha * slope;
            let far = if !armijo || f >= low.1 {
                // Past the minimum, whatever the slope there: it is not computed.
                (alpha, f, None)
            } else {
                objective.gradient(&mut self.grad);
                let f_slope = dot(&self.grad, direction);
                if self.best.is_none_or(|(_, b)| f < b) {
                    self.best = Some((alpha, f));
                    self.best_grad.copy_from_slice(&self.grad);
                }
                if f_slope.abs() <= CURVATURE * slope.abs() {
                    return Some((alpha, f));
                }
                if f_slope > 0.0 {
                    (alpha, f, Some(f_slope))
                } else {
                    let previous = std::mem::replace(&mut low, (alpha, f, f_slope));
                    let Some(far) = high else {
                        // Still descending and nothing past the minimum yet: step out.
                        let guess = cubic_minimum(previous, low);
                        alpha = safeguard(guess, 2.0 * alpha, 2.0 * alpha, 4.0 * alpha);
                        continue;
                    };
                    far
                }
            };
            high = Some(far);
            alpha = inside(low, far);
        }
        let (alpha, f) = self.best?;
        std::mem::swap(&mut self.grad, &mut self.best_grad);
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
    let mut search = LineSearch::new(n);
    let mut step = 1.0 / dot(&grad, &grad).sqrt().max(1e-12);
    // The last accepted step and the slope it started from.
    let mut last: Option<(f64, f64)> = None;
    for _ in 0..iterations {
        if crate::cancel::requested() {
            break; // a signal: the run ends after this trial
        }
        let mut slope = dot(&grad, &direction);
        if slope >= 0.0 {
            direction.iter_mut().zip(&grad).for_each(|(d, g)| *d = -g);
            slope = -dot(&grad, &grad);
        }
        if slope == 0.0 || !slope.is_finite() {
            break;
        }
        // First try the step whose first-order change of the loss equals the last one's.
        if let Some((last_alpha, last_slope)) = last {
            let guess = last_alpha * last_slope / slope;
            step = if guess.is_finite() && guess > 0.0 {
                guess
            } else {
                last_alpha
            };
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
        last = Some((alpha, slope));
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
    use crate::learn::baselines::net::{BatchLoss, DenseNet};
    use nalgebra::{SVector, Vector1};
    use rand::{Rng, SeedableRng};
    use rand_chacha::ChaCha8Rng;

    fn smooth(x: &SVector<f64, 5>) -> f64 {
        (1.5 * x[0]).sin() + 0.5 * x[1] * x[2] - 0.4 * x[3] * x[3] + 0.3 * x[4]
    }

    /// (Input, target) pairs of `smooth`.
    type Batch = Vec<(SVector<f64, 5>, SVector<f64, 1>)>;

    fn batch(n: usize, rng: &mut ChaCha8Rng) -> Batch {
        (0..n)
            .map(|_| {
                let x = SVector::<f64, 5>::from_fn(|_, _| rng.random_range(-1.0..1.0));
                (x, Vector1::new(smooth(&x)))
            })
            .collect()
    }

    /// The generator (seed 9), after drawing a training batch of `patterns` and a net of
    /// `hidden` units with weights in ±`wrange`.
    fn fixture(patterns: usize, hidden: usize, wrange: f64) -> (ChaCha8Rng, Batch, DenseNet<5, 1>) {
        let mut rng = ChaCha8Rng::seed_from_u64(9);
        let train = batch(patterns, &mut rng);
        let net = DenseNet::new(hidden, wrange, &mut rng);
        (rng, train, net)
    }

    #[test]
    fn cg_lowers_a_nets_batch_loss_at_every_step_and_fits_a_smooth_5d_function() {
        let (mut rng, train, mut net) = fixture(400, 20, 0.3);
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

    /// An objective that counts the values asked of it.
    struct Counted<'a, T>(&'a mut T, usize);

    impl<T: Objective> Objective for Counted<'_, T> {
        fn dimension(&self) -> usize {
            self.0.dimension()
        }
        fn value(&mut self, at: &[f64]) -> f64 {
            self.1 += 1;
            self.0.value(at)
        }
        fn gradient(&mut self, grad: &mut [f64]) {
            self.0.gradient(grad);
        }
    }

    #[test]
    fn a_cg_step_on_a_nets_batch_loss_takes_under_two_evaluations_on_average() {
        let (_, train, mut net) = fixture(300, 5, 0.1);
        let mut params = net.params().to_vec();
        let mut loss = BatchLoss::new(&mut net, &train);
        let mut counted = Counted(&mut loss, 0);
        let losses = minimize(&mut counted, &mut params, 100);
        // (Less the start's value and the end's.)
        let per_step = (counted.1 - 2) as f64 / (losses.len() - 1) as f64;
        println!(
            "{per_step} evaluations per step over {} steps",
            losses.len() - 1
        );
        assert_eq!(losses.len(), 101, "no search failed");
        assert!(per_step < 2.0, "{per_step} evaluations per step");
    }
}
