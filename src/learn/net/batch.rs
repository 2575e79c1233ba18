//! The mean loss of a net over a batch, [`BatchLoss`], laid out for vector instructions.
//!
//! The forward pass runs across patterns: every input, hidden unit and output is a row of
//! the batch's values, so a weight times a row is one vector operation per four patterns.
//! The gradient's sums run across gradient entries instead, pattern after pattern: each
//! hidden unit's input weights and bias (and each output weight row) are a padded row of
//! accumulators that a pattern adds its products to. Every number is made by the same
//! operations in the same order as the pattern-by-pattern pass
//! ([`DenseNet::accumulate_gradient`]), so loss and gradient are the same to the bit.

use super::dense::DenseNet;
use super::tanh;
use super::Objective;
use nalgebra::SVector;

/// Lanes of a vector register (four f64 in 256 bits); accumulator rows are padded to them.
const LANES: usize = 4;

/// `len` rounded up to whole vector registers.
fn padded(len: usize) -> usize {
    len.next_multiple_of(LANES)
}

/// The mean loss of a net over a batch of (input, target) pairs, as an [`Objective`] of
/// the net's parameters. Made once per training; its buffers are allocated then, so an
/// evaluation allocates nothing.
#[derive(Debug)]
pub struct BatchLoss<'a, const I: usize, const O: usize> {
    net: &'a mut DenseNet<I, O>,
    /// Patterns in the batch.
    len: usize,
    /// Input i of every pattern (I rows of `len`).
    inputs: Vec<f64>,
    /// Every pattern's inputs and a 1 (the bias's input), padded with zeros to whole
    /// registers (`len` rows of `padded(I + 1)`).
    input_rows: Vec<f64>,
    /// Target k of every pattern (O rows of `len`).
    targets: Vec<f64>,
    /// Hidden unit j's activation for every pattern (hidden rows of `len`).
    activations: Vec<f64>,
    /// Output k's error (output − target) for every pattern (O rows of `len`).
    errors: Vec<f64>,
    /// Hidden unit j's error signal for every pattern (hidden rows of `len`).
    deltas: Vec<f64>,
    /// Every pattern's errors, padded with zeros to whole registers (`len` rows of
    /// `padded(O)`; written after the forward pass, so that reading a row as a register
    /// does not wait for the stores of its parts).
    error_rows: Vec<f64>,
    /// Gradient sums: per hidden unit its input weights and bias (`padded(I + 1)` each),
    /// then per hidden unit and for the output biases the outputs' weights (`padded(O)`).
    sums: Vec<f64>,
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

    /// The forward pass, row by row: hidden activations (tanh applied to all of them at
    /// once: the inline one if `INLINE_TANH`, else the library's), output errors, and the
    /// hidden units' error signals. (A const parameter, not a function argument: the inline
    /// tanh must be inlined into the caller's `target_feature` code.)
    #[inline(always)]
    fn forward<const INLINE_TANH: bool>(&mut self) {
        // (Rows of at least one value: an empty batch has no rows, not rows of none.)
        let (n, h) = (self.len.max(1), self.net.hidden());
        let (w1, b1, w2, b2) = DenseNet::<I, O>::layers(self.net.params(), h);
        for (j, sums) in self.activations.chunks_exact_mut(n).enumerate() {
            // Each unit's weighted sum in index order from −0 (as `Iterator::sum` starts),
            // then its bias.
            sums.fill(-0.0);
            for (w, x) in w1[j * I..(j + 1) * I]
                .iter()
                .zip(self.inputs.chunks_exact(n))
            {
                add_times(sums, *w, x);
            }
            for s in sums.iter_mut() {
                *s += b1[j];
            }
        }
        if INLINE_TANH {
            tanh::tanh_all(&mut self.activations);
        } else {
            for a in self.activations.iter_mut() {
                *a = a.tanh();
            }
        }
        let rows = self.errors.chunks_exact_mut(n);
        for (k, (errors, targets)) in rows.zip(self.targets.chunks_exact(n)).enumerate() {
            errors.fill(-0.0);
            for (w, a) in w2[k * h..(k + 1) * h]
                .iter()
                .zip(self.activations.chunks_exact(n))
            {
                add_times(errors, *w, a);
            }
            for (e, t) in errors.iter_mut().zip(targets) {
                *e = (*e + b2[k]) - t;
            }
        }
        let rows = self.deltas.chunks_exact_mut(n);
        for (j, (deltas, a)) in rows.zip(self.activations.chunks_exact(n)).enumerate() {
            deltas.fill(-0.0);
            for (k, e) in self.errors.chunks_exact(n).enumerate() {
                // (w·e: the same product as the pattern-by-pattern pass's e·w.)
                add_times(deltas, w2[k * h + j], e);
            }
            for (d, a) in deltas.iter_mut().zip(a) {
                *d *= 1.0 - a * a;
            }
        }
        for (p, row) in self.error_rows.chunks_exact_mut(padded(O)).enumerate() {
            for (k, e) in row[..O].iter_mut().enumerate() {
                *e = self.errors[k * n + p];
            }
        }
    }

    /// The gradient's sums, pattern after pattern (each entry gets one addition per
    /// pattern, from 0), written into `grad`; returns the summed loss.
    #[inline(always)]
    fn backward(&mut self, grad: &mut [f64]) -> f64 {
        let (n, h) = (self.len, self.net.hidden());
        let (wide_in, wide_out) = (padded(I + 1), padded(O));
        self.sums.fill(0.0);
        let (hidden_sums, output_sums) = self.sums.split_at_mut(h * wide_in);
        let mut loss = 0.0;
        let rows = self.input_rows.chunks_exact(wide_in);
        for (p, (x_row, e_row)) in rows.zip(self.error_rows.chunks_exact(wide_out)).enumerate() {
            for (j, sums) in hidden_sums.chunks_exact_mut(wide_in).enumerate() {
                add_scaled(sums, self.deltas[j * n + p], x_row);
            }
            let (weight_sums, bias_sums) = output_sums.split_at_mut(h * wide_out);
            for (j, sums) in weight_sums.chunks_exact_mut(wide_out).enumerate() {
                add_scaled(sums, self.activations[j * n + p], e_row);
            }
            // (The bias's input is 1: adding 1·e adds e, as the pattern-by-pattern pass does.)
            add_scaled(bias_sums, 1.0, e_row);
            let error = SVector::<f64, O>::from_fn(|k, _| e_row[k]);
            loss += 0.5 * error.norm_squared();
        }
        let (w1_grad, rest) = grad.split_at_mut(h * I);
        let (b1_grad, rest) = rest.split_at_mut(h);
        let (w2_grad, b2_grad) = rest.split_at_mut(O * h);
        for (j, sums) in hidden_sums.chunks_exact(wide_in).enumerate() {
            w1_grad[j * I..(j + 1) * I].copy_from_slice(&sums[..I]);
            b1_grad[j] = sums[I];
        }
        let (weight_sums, bias_sums) = output_sums.split_at(h * wide_out);
        for (j, sums) in weight_sums.chunks_exact(wide_out).enumerate() {
            for (k, s) in sums[..O].iter().enumerate() {
                w2_grad[k * h + j] = *s;
            }
        }
        b2_grad.copy_from_slice(&bias_sums[..O]);
        loss
    }

    /// Loss and gradient at the net's current parameters (the inline tanh if
    /// `INLINE_TANH`).
    /// activation over a slice.
    #[inline(always)]
    fn passes<const INLINE_TANH: bool>(&mut self, grad: &mut [f64]) -> f64 {
        self.forward::<INLINE_TANH>();
        let loss = self.backward(grad);
        let n = self.len.max(1) as f64;
        for g in grad.iter_mut() {
            *g /= n;
        }
        loss / n
    }

    /// [`Self::passes`] compiled for AVX2 (four lanes) and FMA, with the inline tanh
    /// (the library's bits).
    #[cfg(all(target_arch = "x86_64", target_os = "linux", target_env = "gnu"))]
    #[target_feature(enable = "avx2,fma")]
    fn passes_fma(&mut self, grad: &mut [f64]) -> f64 {
        self.passes::<true>(grad)
    }

    /// [`Self::passes_fma`] compiled for AVX-512 (eight lanes).
    #[cfg(all(target_arch = "x86_64", target_os = "linux", target_env = "gnu"))]
    #[target_feature(enable = "avx512f,avx2,fma")]
    fn passes_avx512(&mut self, grad: &mut [f64]) -> f64 {
        self.passes::<true>(grad)
    }
}

/// Whether the batch passes use the inline tanh: where the library's is glibc's FMA build
/// (x86_64 Linux with glibc, on a CPU with AVX2 and FMA, as glibc itself chooses), whose
/// bits it gives. Elsewhere they call the library's.
#[cfg(all(target_arch = "x86_64", target_os = "linux", target_env = "gnu"))]
pub(super) fn inline_tanh_used() -> bool {
    std::arch::is_x86_feature_detected!("avx2") && std::arch::is_x86_feature_detected!("fma")
}

/// Whether the batch passes use the inline tanh: not on this platform.
#[cfg(not(all(target_arch = "x86_64", target_os = "linux", target_env = "gnu")))]
pub(super) fn inline_tanh_used() -> bool {
    false
}

/// `sums[p] += w * x[p]` for every pattern p (plain loops: they vectorise inside the
/// callers' `target_feature` code, where a library iterator's `for_each` might be left
/// uninlined).
#[inline(always)]
fn add_times(sums: &mut [f64], w: f64, x: &[f64]) {
    for (s, x) in sums.iter_mut().zip(x) {
        *s += w * x;
    }
}

/// `sums[l] += scale * row[l]` lane by lane (both a whole number of registers long).
#[inline(always)]
fn add_scaled(sums: &mut [f64], scale: f64, row: &[f64]) {
    for (s, r) in sums.chunks_exact_mut(LANES).zip(row.chunks_exact(LANES)) {
        let s: &mut [f64; LANES] = s.try_into().expect("whole registers");
        let r: &[f64; LANES] = r.try_into().expect("whole registers");
        // (Whole registers read, then written: one vector multiply and add.)
        *s = std::array::from_fn(|l| s[l] + scale * r[l]);
    }
}

impl<const I: usize, const O: usize> Objective for BatchLoss<'_, I, O> {
    fn dimension(&self) -> usize {
        self.net.params().len()
    }

    fn evaluate(&mut self, at: &[f64], grad: &mut [f64]) -> f64 {
        self.net.params_mut().copy_from_slice(at);
        #[cfg(all(target_arch = "x86_64", target_os = "linux", target_env = "gnu"))]
        if inline_tanh_used() {
            if std::arch::is_x86_feature_detected!("avx512f") {
                // SAFETY: the CPU has AVX-512F, AVX2 and FMA, checked just now.
                return unsafe { self.passes_avx512(grad) };
            }
            // SAFETY: the CPU has AVX2 and FMA, checked just now.
            return unsafe { self.passes_fma(grad) };
        }
        self.passes::<false>(grad)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::{Rng, SeedableRng};
    use rand_chacha::ChaCha8Rng;

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
    fn the_batch_loss_equals_the_pattern_by_pattern_pass_to_the_bit() {
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
            let mut grad = vec![f64::NAN; at.len()];
            let batch_loss = BatchLoss::new(&mut net, &batch).evaluate(&at, &mut grad);
            assert_eq!(
                batch_loss.to_bits(),
                loss.to_bits(),
                "{hidden} units, {len}"
            );
            let bits = |v: &[f64]| v.iter().map(|g| g.to_bits()).collect::<Vec<_>>();
            assert_eq!(bits(&grad), bits(&expected), "{hidden} units, {len}");
        }
    }
}
