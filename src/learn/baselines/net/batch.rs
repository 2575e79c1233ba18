//! The mean loss of a net over a batch, [`BatchLoss`]: its data laid out for vector
//! instructions, and the build of its passes (see `batch_passes.rs`) chosen for the CPU.
//!
//! Every number is made by the same operations in the same order as the pattern-by-pattern
//! pass ([`DenseNet::accumulate_gradient`]), so loss and gradient are the same to the bit
//! whichever build runs.

use super::batch_passes::{padded, Build};
use super::dense::DenseNet;
use super::Objective;
use nalgebra::SVector;

/// The mean loss of a net over a batch of (input, target) pairs, as an [`Objective`] of
/// the net's parameters. Made once per training; its buffers are allocated then, so an
/// evaluation allocates nothing.
#[derive(Debug)]
pub struct BatchLoss<'a, const I: usize, const O: usize> {
    pub(super) net: &'a mut DenseNet<I, O>,
    /// The passes' build for this CPU.
    build: Build,
    /// Patterns in the batch.
    pub(super) len: usize,
    /// Input i of every pattern (I rows of `len`).
    pub(super) inputs: Vec<f64>,
    /// Every pattern's inputs and a 1 (the bias's input), padded with zeros to whole
    /// registers (`len` rows of `padded(I + 1)`).
    pub(super) input_rows: Vec<f64>,
    /// Target k of every pattern (O rows of `len`).
    pub(super) targets: Vec<f64>,
    /// Hidden unit j's activation for every pattern (hidden rows of `len`).
    pub(super) activations: Vec<f64>,
    /// Output k's error (output − target) for every pattern (O rows of `len`).
    pub(super) errors: Vec<f64>,
    /// Hidden unit j's error signal for every pattern (hidden rows of `len`).
    pub(super) deltas: Vec<f64>,
    /// Every pattern's errors, padded with zeros to whole registers (`len` rows of
    /// `padded(O)`; copied from `errors` at the forward pass's end, so that reading a row
    /// as a register does not wait for the stores of its parts).
    pub(super) error_rows: Vec<f64>,
    /// Gradient sums: per hidden unit its input weights and bias (`padded(I + 1)` each),
    /// then per hidden unit and for the output biases the outputs' weights (`padded(O)`).
    pub(super) sums: Vec<f64>,
}

impl<'a, const I: usize, const O: usize> BatchLoss<'a, I, O> {
    /// The loss of `net` over `batch`.
    pub fn new(net: &'a mut DenseNet<I, O>, batch: &[(SVector<f64, I>, SVector<f64, O>)]) -> Self {
        let (len, hidden) = (batch.len(), net.hidden());
        let column = |i: usize| batch.iter().map(move |(x, _)| x[i]);
        let inputs = (0..I).flat_map(column).collect();
        let targets = (0..O)
            .flat_map(|k| batch.iter().map(move |(_, t)| t[k]))
            .collect();
        let mut input_rows = vec![0.0; len * padded(I + 1)];
        for (row, (x, _)) in input_rows.chunks_exact_mut(padded(I + 1)).zip(batch) {
            row[..I].copy_from_slice(x.as_slice());
            row[I] = 1.0;
        }
        BatchLoss {
            net,
            build: Build::for_this_cpu(),
            len,
            inputs,
            input_rows,
            targets,
            activations: vec![0.0; hidden * len],
            errors: vec![0.0; O * len],
            deltas: vec![0.0; hidden * len],
            error_rows: vec![0.0; len * padded(O)],
            sums: vec![0.0; hidden * padded(I + 1) + (hidden + 1) * padded(O)],
        }
    }

    /// The same loss computed by `build` (one this CPU runs).
    #[cfg(test)]
    fn with_build(self, build: Build) -> Self {
        BatchLoss { build, ..self }
    }
}

impl<const I: usize, const O: usize> Objective for BatchLoss<'_, I, O> {
    fn dimension(&self) -> usize {
        self.net.params().len()
    }

    fn value(&mut self, at: &[f64]) -> f64 {
        self.net.params_mut().copy_from_slice(at);
        match self.build {
            Build::Plain => self.forward(),
            #[cfg(target_arch = "x86_64")]
            // SAFETY: the CPU has AVX2 (`Build::for_this_cpu`).
            Build::Avx2 => unsafe { self.forward_avx2() },
            #[cfg(target_arch = "x86_64")]
            // SAFETY: the CPU has AVX-512F and AVX2 (`Build::for_this_cpu`).
            Build::Avx512 => unsafe { self.forward_avx512() },
        }
    }

    fn gradient(&mut self, grad: &mut [f64]) {
        match self.build {
            Build::Plain => self.backward(grad),
            #[cfg(target_arch = "x86_64")]
            // SAFETY: as in `value`.
            Build::Avx2 => unsafe { self.backward_avx2(grad) },
            #[cfg(target_arch = "x86_64")]
            // SAFETY: as in `value`.
            Build::Avx512 => unsafe { self.backward_avx512(grad) },
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::{Rng, SeedableRng};
    use rand_chacha::ChaCha8Rng;

    /// Every build this CPU runs, down to the plain one.
    fn builds_of_this_cpu() -> Vec<Build> {
        let mut builds = vec![Build::Plain];
        #[cfg(target_arch = "x86_64")]
        {
            let fastest = Build::for_this_cpu();
            if fastest != Build::Plain {
                builds.push(Build::Avx2);
            }
            if fastest == Build::Avx512 {
                builds.push(Build::Avx512);
            }
        }
        builds
    }

    /// The batch loss against the pattern-by-pattern pass it must equal to the bit.
    fn pattern_by_pattern(
        net: &mut DenseNet<5, 3>,
        batch: &[(SVector<f64, 5>, SVector<f64, 3>)],
        grad: &mut [f64],
    ) -> f64 {
        grad.fill(0.0);
        let mut loss = 0.0;
        for (x, t) in batch {
            loss += net.accumulate_gradient(x, t, grad);
        }
        let n = batch.len().max(1) as f64;
        grad.iter_mut().for_each(|g| *g /= n);
        loss / n
    }

    #[test]
    fn every_build_of_the_batch_loss_equals_the_pattern_by_pattern_pass_to_the_bit() {
        let mut rng = ChaCha8Rng::seed_from_u64(11);
        for (hidden, len) in [(5, 300), (3, 7), (25, 41), (1, 1), (4, 0)] {
            let mut net: DenseNet<5, 3> = DenseNet::new(hidden, 2.0, &mut rng);
            let batch: Vec<_> = (0..len)
                .map(|_| {
                    let x = SVector::from_fn(|_, _| rng.random_range(-3.0..3.0));
                    (x, SVector::from_fn(|_, _| rng.random_range(-1.0..1.0)))
                })
                .collect();
            let at = net.params().to_vec();
            let mut expected = vec![0.0; at.len()];
            let loss = pattern_by_pattern(&mut net, &batch, &mut expected);
            let bits = |v: &[f64]| v.iter().map(|g| g.to_bits()).collect::<Vec<_>>();
            for build in builds_of_this_cpu() {
                let mut grad = vec![f64::NAN; at.len()];
                let mut objective = BatchLoss::new(&mut net, &batch).with_build(build);
                let batch_loss = objective.evaluate(&at, &mut grad);
                let case = format!("{build:?}, {hidden} units, {len} patterns");
                assert_eq!(batch_loss.to_bits(), loss.to_bits(), "{case}");
                assert_eq!(bits(&grad), bits(&expected), "{case}");
            }
        }
    }
}
