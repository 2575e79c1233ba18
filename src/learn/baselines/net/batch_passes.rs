//! [`BatchLoss`]'s passes, in the builds a CPU can run: the loss (forward pass) and, only
//! when asked, the gradient (backward pass).
//!
//! The forward pass runs across patterns: every input, hidden unit and output is a row of
//! the batch's values, so a weight times a row is one vector operation per four (or eight)
//! patterns. The gradient's sums run across gradient entries instead, pattern after
//! pattern: each hidden unit's input weights and bias (and each output weight row) are a
//! padded row of accumulators that a pattern adds its products to. Each sum keeps the
//! pattern-by-pattern pass's order, so the results are the same to the bit.

use super::batch::BatchLoss;
use super::dense::DenseNet;
use super::tanh;
use nalgebra::SVector;

/// Lanes of a vector register (four f64 in 256 bits); accumulator rows are padded to them.
const LANES: usize = 4;

/// `len` rounded up to whole vector registers.
pub(super) fn padded(len: usize) -> usize {
    len.next_multiple_of(LANES)
}

/// The build of the passes a CPU runs. All give the same bits: they do the same
/// operations, only more of them at once.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Build {
    /// The platform's baseline (two lanes on x86_64).
    Plain,
    /// AVX2 (four lanes).
    #[cfg(target_arch = "x86_64")]
    Avx2,
    /// AVX-512F (eight lanes).
    #[cfg(target_arch = "x86_64")]
    Avx512,
}

impl Build {
    /// The fastest build this CPU runs.
    pub(super) fn for_this_cpu() -> Build {
        #[cfg(target_arch = "x86_64")]
        if std::arch::is_x86_feature_detected!("avx2") {
            return if std::arch::is_x86_feature_detected!("avx512f") {
                Build::Avx512
            } else {
                Build::Avx2
            };
        }
        Build::Plain
    }
}

impl<const I: usize, const O: usize> BatchLoss<'_, I, O> {
    /// The forward pass, row by row: hidden activations (tanh applied to all of them at
    /// once), output errors; returns the mean loss.
    #[inline(always)]
    pub(super) fn forward(&mut self) -> f64 {
        // (Rows of at least one value: an empty batch has no rows, not rows of none.)
        let (n, h) = (self.len.max(1), self.net.hidden());
        let (w1, b1, w2, b2) = DenseNet::<I, O>::layers(self.net.params(), h);
        for (j, sums) in self.activations.chunks_exact_mut(n).enumerate() {
            // Each unit's weighted sum in index order from −0 (as `Iterator::sum` starts),
            // then its bias.
            sums.fill(-0.0);
            let weights = &w1[j * I..(j + 1) * I];
            for (w, x) in weights.iter().zip(self.inputs.chunks_exact(n)) {
                add_times(sums, *w, x);
            }
            for s in sums.iter_mut() {
                *s += b1[j];
            }
        }
        tanh::tanh_all(&mut self.activations);
        let rows = self.errors.chunks_exact_mut(n);
        for (k, (errors, targets)) in rows.zip(self.targets.chunks_exact(n)).enumerate() {
            errors.fill(-0.0);
            let weights = &w2[k * h..(k + 1) * h];
            for (w, a) in weights.iter().zip(self.activations.chunks_exact(n)) {
                add_times(errors, *w, a);
            }
            for (e, t) in errors.iter_mut().zip(targets) {
                *e = (*e + b2[k]) - t;
            }
        }
        let mut loss = 0.0;
        for (p, row) in self.error_rows.chunks_exact_mut(padded(O)).enumerate() {
            for (k, e) in row[..O].iter_mut().enumerate() {
                *e = self.errors[k * n + p];
            }
            loss += 0.5 * SVector::<f64, O>::from_fn(|k, _| row[k]).norm_squared();
        }
        loss / self.len.max(1) as f64
    }

    /// The mean gradient at the point of the last forward pass: the hidden units' error
    /// signals, then the gradient's sums pattern after pattern (each entry gets one
    /// addition per pattern, from 0), written into `grad`.
    #[inline(always)]
    pub(super) fn backward(&mut self, grad: &mut [f64]) {
        let (n, h) = (self.len.max(1), self.net.hidden());
        let (_, _, w2, _) = DenseNet::<I, O>::layers(self.net.params(), h);
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
        let (wide_in, wide_out) = (padded(I + 1), padded(O));
        self.sums.fill(0.0);
        let (hidden_sums, output_sums) = self.sums.split_at_mut(h * wide_in);
        let (weight_sums, bias_sums) = output_sums.split_at_mut(h * wide_out);
        let rows = self.input_rows.chunks_exact(wide_in);
        for (p, (x_row, e_row)) in rows.zip(self.error_rows.chunks_exact(wide_out)).enumerate() {
            for (j, sums) in hidden_sums.chunks_exact_mut(wide_in).enumerate() {
                add_scaled(sums, self.deltas[j * n + p], x_row);
            }
            for (j, sums) in weight_sums.chunks_exact_mut(wide_out).enumerate() {
                add_scaled(sums, self.activations[j * n + p], e_row);
            }
            // (The bias's input is 1: adding 1·e adds e, as the pattern-by-pattern pass does.)
            add_scaled(bias_sums, 1.0, e_row);
        }
        let count = self.len.max(1) as f64;
        let (w1_grad, rest) = grad.split_at_mut(h * I);
        let (b1_grad, rest) = rest.split_at_mut(h);
        let (w2_grad, b2_grad) = rest.split_at_mut(O * h);
        for (j, sums) in hidden_sums.chunks_exact(wide_in).enumerate() {
            for (g, s) in w1_grad[j * I..(j + 1) * I].iter_mut().zip(&sums[..I]) {
                *g = s / count;
            }
            b1_grad[j] = sums[I] / count;
        }
        for (j, sums) in weight_sums.chunks_exact(wide_out).enumerate() {
            for (k, s) in sums[..O].iter().enumerate() {
                w2_grad[k * h + j] = s / count;
            }
        }
        for (g, s) in b2_grad.iter_mut().zip(bias_sums.iter()) {
            *g = s / count;
        }
    }

    /// [`Self::forward`] compiled for AVX2.
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2")]
    pub(super) fn forward_avx2(&mut self) -> f64 {
        self.forward()
    }

    /// [`Self::forward`] compiled for AVX-512F.
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx512f,avx2")]
    pub(super) fn forward_avx512(&mut self) -> f64 {
        self.forward()
    }

    /// [`Self::backward`] compiled for AVX2.
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2")]
    pub(super) fn backward_avx2(&mut self, grad: &mut [f64]) {
        self.backward(grad);
    }

    /// [`Self::backward`] compiled for AVX-512F.
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx512f,avx2")]
    pub(super) fn backward_avx512(&mut self, grad: &mut [f64]) {
        self.backward(grad);
    }
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
