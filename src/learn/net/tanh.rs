//! tanh as the C library computes it on x86_64 with FMA — glibc 2.36's `tanh` (fdlibm's
//! algorithm) over the FMA build of its `expm1` — written inline and without branches, so
//! that a batch's activations run four to a vector register instead of two calls each.
//! It gives the library's bits exactly (tested on millions of points, every branch of the
//! algorithm and the special values), so training gives the same results with it.
//!
//! The algorithm: tanh|x| = 1 − 2/(t + 2) with t = eˣ⁻¹ of 2|x| for |x| ≥ 1, and
//! −t/(t + 2) with t of −2|x| below; |x| ≥ 22 gives 1 and |x| < 2⁻⁵⁵ gives x(1 + x).
//! eᵘ − 1 splits u = k·ln 2 + r (ln 2 in a high part exact in multiples and a low part, r
//! carried as r − c), approximates eʳ − 1 by a rational function of r, and scales it by
//! 2ᵏ by one of five formulas chosen by k. Where the library's FMA build fuses a multiply
//! and an add (read off its machine code), this does too (`mul_add`), and nowhere else.

/// ln 2's high part (its last 32 bits are zero, so k·ln 2's high part is exact).
const LN2_HI: f64 = f64::from_bits(0x3fe6_2e42_fee0_0000);
/// ln 2 − `LN2_HI`.
const LN2_LO: f64 = f64::from_bits(0x3dea_39ef_3579_3c76);
/// 1/ln 2.
const INV_LN2: f64 = f64::from_bits(0x3ff7_1547_652b_82fe);
/// The rational approximation's coefficients (of powers of r²/2).
const Q1: f64 = f64::from_bits(0xbfa1_1111_1111_10f4);
const Q2: f64 = f64::from_bits(0x3f5a_01a0_19fe_5585);
const Q3: f64 = f64::from_bits(0xbf14_ce19_9eaa_dbb7);
const Q4: f64 = f64::from_bits(0x3ed0_cfca_86e6_5239);
const Q5: f64 = f64::from_bits(0xbe8a_fdb7_6e09_c32d);
/// |u| below this (high word ≤ 0x3fd62e42, about ln 2 / 2) is not reduced: k = 0.
const NO_REDUCTION_BELOW: u64 = 0x3fd6_2e43_0000_0000;
/// |u| below this (high word ≤ 0x3ff0a2b1, about 1.5 ln 2) has k = ±1.
const ONE_LN2_BELOW: u64 = 0x3ff0_a2b2_0000_0000;
/// 2⁻⁵⁵: below it tanh x is x(1 + x).
const TINY: f64 = f64::from_bits(0x3c80_0000_0000_0000);
/// From 22 on, tanh |x| rounds to 1.
const SATURATED: f64 = 22.0;

/// 2⁵² + 1023: an integer k (|k| < 1023) added to it leaves k + 1023 in the low bits.
const EXPONENT_BIAS: f64 = 4_503_599_627_371_519.0;

/// 2ᵏ for an integer-valued `k` within ±1022 (by float operations and a shift only, so a
/// vector register does four).
#[inline(always)]
fn two_to(k: f64) -> f64 {
    f64::from_bits((k + EXPONENT_BIAS).to_bits() << 52)
}

/// eᵘ − 1 for the arguments tanh gives it: −2 < u ≤ −2⁻⁵⁴ and 2 ≤ u ≤ 44. Any other `u`
/// gives some number, which tanh does not use. Every formula is computed and the one that
/// k asks for chosen (no branches, so that it vectorises).
#[inline(always)]
fn expm1(u: f64) -> f64 {
    let size = u.abs();
    let half = if u < 0.0 { -0.5 } else { 0.5 };
    // k: u/ln 2 rounded half away from zero (as a C conversion truncates u/ln 2 ± ½);
    // 0 near 0 and −1 up to about −1.5 ln 2 (tanh's positive arguments are 2 and more).
    let k = if size < f64::from_bits(NO_REDUCTION_BELOW) {
        0.0
    } else if size < f64::from_bits(ONE_LN2_BELOW) {
        -1.0
    } else {
        (u * INV_LN2 + half).trunc()
    };
    let hi = (-k).mul_add(LN2_HI, u);
    let lo = k * LN2_LO;
    let r = hi - lo;
    let c = (hi - r) - lo;
    let half_r = 0.5 * r;
    let hr2 = r * half_r;
    let h2 = hr2 * hr2;
    let h4 = h2 * h2;
    let r1 = h4.mul_add(
        hr2.mul_add(Q5, Q4),
        h2.mul_add(hr2.mul_add(Q3, Q2), hr2.mul_add(Q1, 1.0)),
    );
    let t = (-r1).mul_add(half_r, 3.0);
    let e = hr2 * ((r1 - t) / (-r).mul_add(t, 6.0));
    let ek = (e - c).mul_add(r, -c) - hr2;
    let (scale, unscale) = (two_to(k), two_to(-k));
    let unreduced = r - e.mul_add(r, -hr2);
    let minus_one = (r - ek).mul_add(0.5, -0.5);
    let far = (1.0 - (ek - r)) * scale - 1.0;
    let near = ((1.0 - unscale) - (ek - r)) * scale;
    let middle = ((r - (ek + unscale)) + 1.0) * scale;
    if k == 0.0 {
        unreduced
    } else if k == -1.0 {
        minus_one
    } else if !(2.0..=56.0).contains(&k) {
        far
    } else if k < 20.0 {
        near
    } else {
        middle
    }
}

/// tanh `x`, the library's bits.
#[inline(always)]
pub(super) fn tanh(x: f64) -> f64 {
    let size = x.abs();
    let large = size >= 1.0;
    // expm1's argument 2|x| from 1 on and −2|x| below (exact), as one value with its sign
    // set by bits (chosen by a select, the compiler would compute expm1 twice, once for
    // each); |x| is capped where tanh no longer uses expm1.
    let capped = size.min(SATURATED);
    let negative = u64::from(!large) << 63;
    let t = expm1(f64::from_bits((capped + capped).to_bits() | negative));
    // 1 − 2/(t + 2) from 1 on, −t/(t + 2) below: one division for both.
    let quotient = if large { 2.0 } else { -t } / (t + 2.0);
    let magnitude = if size >= SATURATED {
        1.0
    } else if large {
        1.0 - quotient
    } else {
        quotient
    };
    let signed = if x.is_sign_negative() {
        -magnitude
    } else {
        magnitude
    };
    let tiny = x * (1.0 + x);
    if x.is_nan() {
        x + x
    } else if size < TINY {
        tiny
    } else {
        signed
    }
}

/// tanh over every value of a slice, vectorised where the caller is compiled for FMA and
/// AVX2 (elsewhere each `mul_add` is a call, slow but exact). The slice's two halves go
/// side by side: one value's steps wait on each other (two divisions among them), and two
/// independent chains keep the core busy meanwhile.
#[inline(always)]
pub(super) fn tanh_all(values: &mut [f64]) {
    let half = values.len() / 2;
    let (first, rest) = values.split_at_mut(half);
    let (second, last) = rest.split_at_mut(half);
    for (a, b) in first.iter_mut().zip(second) {
        *a = tanh(*a);
        *b = tanh(*b);
    }
    for v in last {
        *v = tanh(*v);
    }
}

#[cfg(all(test, target_arch = "x86_64"))]
mod tests {
    use super::super::batch_passes::Build;
    use super::*;
    use rand::{Rng, SeedableRng};
    use rand_chacha::ChaCha8Rng;

    /// Whether the batch passes use the inline tanh on this machine.
    fn inline_tanh_used() -> bool {
        Build::for_this_cpu() != Build::Library
    }

    /// Points where the algorithm changes course, with their neighbours a few ulp away.
    fn boundaries() -> Vec<f64> {
        let mut points = vec![0.0, -0.0, f64::MIN_POSITIVE, 5e-324, f64::MAX, 1e300];
        points.extend([f64::INFINITY, f64::NEG_INFINITY, f64::NAN, -f64::NAN]);
        let edges = [TINY, 1.0, SATURATED, 0.5, 19.0, 19.5];
        // expm1's own: |u| of about ln 2 / 2 and 1.5 ln 2 (tanh's |x| half that), and the
        // rounding edges of k = (k ± ½) ln 2 (the five formulas' borders at k = 2, 20, 57).
        let halves = [NO_REDUCTION_BELOW, ONE_LN2_BELOW].map(|b| f64::from_bits(b) / 2.0);
        let ln2 = std::f64::consts::LN_2;
        let roundings = (2..=64).map(|k| (k as f64 - 0.5) * ln2 / 2.0);
        for edge in edges.into_iter().chain(halves).chain(roundings) {
            for ulps in -4_i64..=4 {
                let p = f64::from_bits((edge.to_bits() as i64 + ulps) as u64);
                points.extend([p, -p]);
            }
        }
        points
    }

    /// Every build of the inline tanh — plain (each `mul_add` a call of the library's
    /// correctly rounded `fma`) and vectorised for AVX2 and for AVX-512, as the batch runs
    /// it — against the library's. Only where the batch uses it (the CPU has AVX2 and FMA).
    fn assert_same_bits(points: &[f64]) {
        #[target_feature(enable = "avx2,fma")]
        fn tanh_all_avx2(values: &mut [f64]) {
            tanh_all(values);
        }
        #[target_feature(enable = "avx512f,avx2,fma")]
        fn tanh_all_avx512(values: &mut [f64]) {
            tanh_all(values);
        }
        assert!(inline_tanh_used());
        let (mut avx2, mut avx512) = (points.to_vec(), points.to_vec());
        // SAFETY: the CPU has AVX2 and FMA (`inline_tanh_used`), and AVX-512 where used.
        unsafe { tanh_all_avx2(&mut avx2) };
        if std::arch::is_x86_feature_detected!("avx512f") {
            unsafe { tanh_all_avx512(&mut avx512) };
        } else {
            avx512.copy_from_slice(&avx2);
        }
        for (&x, (a, b)) in points.iter().zip(avx2.into_iter().zip(avx512)) {
            let library = x.tanh().to_bits();
            for (build, ours) in [("plain", tanh(x)), ("AVX2", a), ("AVX-512", b)] {
                assert_eq!(ours.to_bits(), library, "{build} tanh {x:e}: {ours:e}");
            }
        }
    }

    #[test]
    fn the_inline_tanh_gives_the_librarys_bits_at_every_branch_and_special_value() {
        // (Where the batch calls the library's tanh, there is nothing to compare.)
        if inline_tanh_used() {
            assert_same_bits(&boundaries());
        }
    }

    #[test]
    fn the_inline_tanh_gives_the_librarys_bits_on_two_million_points() {
        if !inline_tanh_used() {
            return;
        }
        let mut rng = ChaCha8Rng::seed_from_u64(15);
        let uniform: Vec<f64> = (0..1_500_000)
            .map(|_| rng.random_range(-25.0..25.0))
            .collect();
        assert_same_bits(&uniform);
        // Spread over magnitudes too: sign, exponent 2^−60 … 2^6 and mantissa at random.
        let spread: Vec<f64> = (0..500_000)
            .map(|_| {
                let exponent = rng.random_range(1023 - 60..=1023 + 5_u64);
                let sign = rng.random::<u64>() & (1 << 63);
                f64::from_bits((exponent << 52) | (rng.random::<u64>() >> 12) | sign)
            })
            .collect();
        assert_same_bits(&spread);
    }
}
