//! Synthetic arms for the learners' unit tests: a mapping Δθ = J(θ)·c given by its
//! Jacobian, and trials drawn from it.

use crate::learn::Observation;
use nalgebra::{Matrix3, Vector3};
use rand::Rng;
use rand_chacha::ChaCha8Rng;

/// A synthetic arm's mapping Δθ = J(θ)·c, given by its Jacobian J.
pub(crate) type Mapping = fn(&Vector3<f64>) -> Matrix3<f64>;

/// A linear mapping: J is constant.
pub(crate) fn linear(_theta: &Vector3<f64>) -> Matrix3<f64> {
    Matrix3::new(0.05, -0.02, 0.0, 0.01, 0.03, 0.04, -0.02, 0.0, 0.06)
}

/// A curved mapping: J changes with the arm's pose.
pub(crate) fn curved(theta: &Vector3<f64>) -> Matrix3<f64> {
    let (s2, s3) = (theta.y.to_radians().sin(), theta.z.to_radians().cos());
    linear(theta) * (1.0 + 0.4 * s2 * s3) + Matrix3::from_diagonal_element(0.01 * s3)
}

/// A random pose and reading inside the config's boundaries.
pub(crate) fn random_start(rng: &mut ChaCha8Rng) -> (Vector3<f64>, Vector3<f64>) {
    let theta = Vector3::new(
        rng.random_range(-90.0..90.0),
        rng.random_range(-5.0..75.0),
        rng.random_range(45.0..140.0),
    );
    let c = Vector3::new(
        rng.random_range(-500.0..250.0),
        rng.random_range(-500.0..250.0),
        rng.random_range(-140.0..290.0),
    );
    (theta, c)
}

/// A trial that hits the target in one move: one exact pattern.
pub(crate) fn one_move_trial(jacobian: Mapping, rng: &mut ChaCha8Rng) -> [Observation; 2] {
    let (theta, c) = random_start(rng);
    let start = Observation {
        theta_deg: theta,
        c,
    };
    let target = Observation {
        theta_deg: theta + jacobian(&theta) * c,
        c: Vector3::zeros(),
    };
    [start, target]
}
