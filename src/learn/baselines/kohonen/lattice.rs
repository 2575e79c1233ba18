//! A D-dimensional lattice of neurons (side n in every dimension) with weight vectors in a
//! D-dimensional input space: winner search and the Gaussian neighbourhood update.

use nalgebra::SVector;

/// A self-organising map on a D-dimensional lattice.
#[derive(Debug, Clone, PartialEq)]
pub struct Lattice<const D: usize> {
    side: usize,
    weights: Vec<SVector<f64, D>>,
}

impl<const D: usize> Lattice<D> {
    /// A lattice of `side`^D neurons whose weights lie on a regular grid over [−1, 1]^D.
    pub fn regular(side: usize) -> Self {
        let count = side.pow(D as u32);
        let weights = (0..count)
            .map(|index| {
                let coords = Self::coords_of(side, index);
                SVector::from_fn(|d, _| -1.0 + 2.0 * (coords[d] as f64 + 0.5) / side as f64)
            })
            .collect();
        Lattice { side, weights }
    }

    /// A lattice with the given weights (`side`^D of them).
    pub fn with_weights(side: usize, weights: Vec<SVector<f64, D>>) -> Self {
        assert_eq!(weights.len(), side.pow(D as u32), "one weight per neuron");
        Lattice { side, weights }
    }

    fn coords_of(side: usize, mut index: usize) -> [usize; D] {
        let mut coords = [0; D];
        for c in coords.iter_mut() {
            *c = index % side;
            index /= side;
        }
        coords
    }

    /// Neurons on each side.
    pub fn side(&self) -> usize {
        self.side
    }

    /// Number of neurons.
    pub fn len(&self) -> usize {
        self.weights.len()
    }

    /// True when the lattice has no neurons.
    pub fn is_empty(&self) -> bool {
        self.weights.is_empty()
    }

    /// The weight vector of neuron `index`.
    pub fn weight(&self, index: usize) -> &SVector<f64, D> {
        &self.weights[index]
    }

    /// The lattice coordinates of neuron `index`.
    pub fn coords(&self, index: usize) -> [usize; D] {
        Self::coords_of(self.side, index)
    }

    /// The neuron whose weight is closest to `x`.
    pub fn winner(&self, x: &SVector<f64, D>) -> usize {
        let mut best = (0, f64::INFINITY);
        for (i, w) in self.weights.iter().enumerate() {
            let d = (w - x).norm_squared();
            if d < best.1 {
                best = (i, d);
            }
        }
        best.0
    }

    /// Every neuron within 3σ (per lattice axis) of `centre`, with its neighbourhood
    /// weight h = exp(−‖r − s‖² / 2σ²) in lattice distance. The iterator owns what it needs,
    /// so the lattice can be changed while it runs.
    pub fn neighbourhood(&self, centre: usize, sigma: f64) -> Neighbourhood<D> {
        let centre = self.coords(centre);
        let reach = (3.0 * sigma).ceil() as usize;
        let low: [usize; D] = std::array::from_fn(|d| centre[d].saturating_sub(reach));
        let high: [usize; D] = std::array::from_fn(|d| (centre[d] + reach).min(self.side - 1));
        Neighbourhood {
            side: self.side,
            centre,
            low,
            high,
            at: Some(low),
            inverse_two_sigma2: 1.0 / (2.0 * sigma * sigma),
        }
    }

    /// Moves the winner's neighbours towards `x`: w ← w + rate·h·(x − w).
    pub fn adapt(&mut self, x: &SVector<f64, D>, winner: usize, sigma: f64, rate: f64) {
        for (i, h) in self.neighbourhood(winner, sigma) {
            let w = &mut self.weights[i];
            *w += (x - *w) * (rate * h);
        }
    }
}

/// The neurons around a centre with their neighbourhood weights; see
/// [`Lattice::neighbourhood`].
#[derive(Debug, Clone)]
pub struct Neighbourhood<const D: usize> {
    side: usize,
    centre: [usize; D],
    low: [usize; D],
    high: [usize; D],
    at: Option<[usize; D]>,
    inverse_two_sigma2: f64,
}

impl<const D: usize> Iterator for Neighbourhood<D> {
    type Item = (usize, f64);

    fn next(&mut self) -> Option<(usize, f64)> {
        let at = self.at?;
        let (mut index, mut distance) = (0, 0.0);
        for d in (0..D).rev() {
            index = index * self.side + at[d];
            distance += (at[d] as f64 - self.centre[d] as f64).powi(2);
        }
        let mut next = at;
        self.at = (0..D)
            .find(|&d| {
                if next[d] < self.high[d] {
                    next[d] += 1;
                    true
                } else {
                    next[d] = self.low[d];
                    false
                }
            })
            .map(|_| next);
        Some((index, (-distance * self.inverse_two_sigma2).exp()))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::Vector2;
    use rand::{Rng, SeedableRng};
    use rand_chacha::ChaCha8Rng;

    #[test]
    fn the_winner_is_the_closest_neuron() {
        let lattice: Lattice<2> = Lattice::regular(4);
        let w = *lattice.weight(6);
        assert_eq!(lattice.winner(&(w + Vector2::new(0.01, -0.02))), 6);
        assert_eq!(lattice.coords(6), [2, 1]);
    }

    #[test]
    fn the_neighbourhood_is_gaussian_in_lattice_distance() {
        let lattice: Lattice<2> = Lattice::regular(9);
        let centre = 4 + 9 * 4;
        let seen: Vec<(usize, f64)> = lattice.neighbourhood(centre, 1.0).collect();
        assert_eq!(seen.len(), 49, "3σ = 3 lattice steps each way");
        let h_of = |i| seen.iter().find(|(j, _)| *j == i).unwrap().1;
        assert_eq!(h_of(centre), 1.0);
        assert!((h_of(centre + 1) - (-0.5f64).exp()).abs() < 1e-12);
        assert!((h_of(centre + 9 + 1) - (-1.0f64).exp()).abs() < 1e-12);
    }

    #[test]
    fn adapting_moves_each_neighbour_by_its_share() {
        let mut lattice: Lattice<2> = Lattice::regular(5);
        let before = lattice.clone();
        let x = Vector2::new(0.9, 0.9);
        let winner = lattice.winner(&x);
        lattice.adapt(&x, winner, 1.0, 0.5);
        // Each neuron moves the fraction rate·h of its way to x: h = 1, e^(−1/2), 0.
        let fraction = |i: usize| {
            (lattice.weight(i) - before.weight(i)).norm() / (x - before.weight(i)).norm()
        };
        assert!((fraction(winner) - 0.5).abs() < 1e-12);
        assert!((fraction(winner - 1) - 0.5 * (-0.5f64).exp()).abs() < 1e-12);
        assert_eq!(fraction(0), 0.0, "beyond 3σ nothing moves");
    }

    /// The fraction of lattice rows and columns whose weights run monotonically along the
    /// input coordinate they spread over most (1: the map is untangled, in any orientation).
    fn ordered(lattice: &Lattice<2>) -> f64 {
        let n = lattice.side();
        let monotonic = |line: Vec<Vector2<f64>>| {
            let spread = |c: usize| {
                line.iter().map(|w| w[c]).fold(f64::MIN, f64::max)
                    - line.iter().map(|w| w[c]).fold(f64::MAX, f64::min)
            };
            let c = if spread(0) > spread(1) { 0 } else { 1 };
            line.windows(2).all(|w| w[1][c] > w[0][c]) || line.windows(2).all(|w| w[1][c] < w[0][c])
        };
        let mut good = 0;
        for k in 0..n {
            good += monotonic((0..n).map(|i| *lattice.weight(i + n * k)).collect()) as usize;
            good += monotonic((0..n).map(|j| *lattice.weight(k + n * j)).collect()) as usize;
        }
        good as f64 / (2 * n) as f64
    }

    #[test]
    fn a_random_map_orders_itself_on_a_2d_toy() {
        let mut rng = ChaCha8Rng::seed_from_u64(5);
        let n = 8;
        let weights = (0..n * n)
            .map(|_| Vector2::new(rng.random_range(-0.1..0.1), rng.random_range(-0.1..0.1)))
            .collect();
        let mut lattice = Lattice::with_weights(n, weights);
        assert!(ordered(&lattice) < 0.5, "random weights are tangled");
        let steps = 20_000;
        for t in 0..steps {
            let f = t as f64 / steps as f64;
            let sigma = 3.0 * (0.5f64 / 3.0).powf(f);
            let rate = 0.5 * (0.02f64 / 0.5).powf(f);
            let x = Vector2::new(rng.random_range(-1.0..1.0), rng.random_range(-1.0..1.0));
            let winner = lattice.winner(&x);
            lattice.adapt(&x, winner, sigma, rate);
        }
        assert!(
            ordered(&lattice) > 0.9,
            "ordered fraction {}",
            ordered(&lattice)
        );
    }
}
