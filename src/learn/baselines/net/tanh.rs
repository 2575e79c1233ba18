//! The nets' tanh, written out in plain arithmetic: within 3 ulp of the C library's, with
//! no branch and no call, so a batch's activations run four or eight to a vector register,
//! and the same bits on every CPU and platform (no library, no fused multiply-add), so a
//! seed gives the same run wherever it runs.
//!
//! tanh|x| = −m/(2 + m) with m = e^(−2|x|) − 1. The exponent is split −2|x| = k·ln 2 + r
//! with |r| ≤ ½ ln 2 (ln 2 in a high part, exact in its multiples, and a low part), e^r − 1
//! comes from its Taylor series, and m = 2ᵏ(e^r − 1) + (2ᵏ − 1).

/// ln 2's high part: 31 significant bits, so k·`LN2_HIGH` is exact for every k used here
/// (|k| ≤ 58).
const LN2_HIGH: f64 = 0.693_147_180_136_293_2;
/// ln 2 − `LN2_HIGH`.
const LN2_LOW: f64 = 4.236_521_365_809_284e-10;
/// Adding and subtracting 1.5·2⁵² rounds a double of magnitude below 2⁵¹ to an integer.
const ROUNDING: f64 = 6_755_399_441_055_744.0;
/// tanh is 1 within rounding beyond 19.1; larger magnitudes are clamped to this.
const SATURATION: f64 = 20.0;

/// 1/n! for n = 2…13: e^r − 1 = r + r²·Σ rⁿ⁻²/n!, whose first term left out is below
/// 10⁻¹⁷ of r for |r| ≤ ½ ln 2.
const INVERSE_FACTORIALS: [f64; 12] = [
    0.5,
    0.166_666_666_666_666_66,
    0.041_666_666_666_666_664,
    0.008_333_333_333_333_333,
    0.001_388_888_888_888_889,
    0.000_198_412_698_412_698_4,
    2.480_158_730_158_73e-5,
    2.755_731_922_398_589_3e-6,
    2.755_731_922_398_589e-7,
    2.505_210_838_544_172e-8,
    2.087_675_698_786_81e-9,
    1.605_904_383_682_161_3e-10,
];

/// tanh `x` within 3 ulp; odd (−0 stays −0), ±1 beyond |x| ≈ 19, NaN for NaN.
#[inline(always)]
pub(crate) fn tanh(x: f64) -> f64 {
    // (Written so that NaN passes through the clamp.)
    let magnitude = x.abs();
    let magnitude = if magnitude > SATURATION {
        SATURATION
    } else {
        magnitude
    };
    let y = -2.0 * magnitude;
    let shifted = y * std::f64::consts::LOG2_E + ROUNDING;
    let k = shifted - ROUNDING;
    let r = (y - k * LN2_HIGH) - k * LN2_LOW;
    // Estrin's scheme (pairs, then pairs of pairs): a short chain of dependent steps.
    let c = &INVERSE_FACTORIALS;
    let (r2, r4) = (r * r, r * r * (r * r));
    let pair = |i: usize| c[i] + c[i + 1] * r;
    let quad = |i: usize| pair(i) + r2 * pair(i + 2);
    let tail = quad(0) + r4 * (quad(4) + r4 * quad(8));
    let exp_r_minus_one = r + r2 * tail;
    // 2ᵏ for the integer k in −58..=0 from its exponent bits; k is the difference of the
    // last bits of `shifted` and `ROUNDING`, whose ulp is 1.
    let k_bits = shifted.to_bits().wrapping_sub(ROUNDING.to_bits());
    let scale = f64::from_bits(k_bits.wrapping_add(1023) << 52);
    let m = scale * exp_r_minus_one + (scale - 1.0);
    (-m / (2.0 + m)).copysign(x)
}

/// tanh over every value of a slice (vectorised where the caller is compiled for wide
/// registers). The slice's two halves go side by side: one value's steps wait on each
/// other, and a second independent chain keeps the core busy meanwhile.
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

#[cfg(test)]
mod tests {
    use super::*;
    use rand::{Rng, SeedableRng};
    use rand_chacha::ChaCha8Rng;

    /// How many doubles lie between `a` and `b` (of the same sign).
    fn ulps(a: f64, b: f64) -> u64 {
        (a.to_bits() as i64 - b.to_bits() as i64).unsigned_abs()
    }

    /// Two million points: uniform in ±25, and sign, exponent (2⁻⁶⁰ … 2⁶) and mantissa
    /// at random.
    fn points() -> Vec<f64> {
        let mut rng = ChaCha8Rng::seed_from_u64(15);
        let uniform = (0..1_500_000).map(|_| rng.random_range(-25.0..25.0));
        let mut points: Vec<f64> = uniform.collect();
        points.extend((0..500_000).map(|_| {
            let exponent = rng.random_range(1023 - 60..=1023 + 5_u64);
            let sign = rng.random::<u64>() & (1 << 63);
            f64::from_bits((exponent << 52) | (rng.random::<u64>() >> 12) | sign)
        }));
        points
    }

    #[test]
    fn tanh_is_within_three_ulp_of_the_librarys_and_odd() {
        let mut worst = (0, 0.0);
        for x in points() {
            let ours = tanh(x);
            assert_eq!(ours.to_bits(), (-tanh(-x)).to_bits(), "odd at {x:e}");
            let miss = ulps(ours, x.tanh());
            if miss > worst.0 {
                worst = (miss, x);
            }
        }
        assert!(worst.0 <= 3, "{} ulp at x = {:e}", worst.0, worst.1);
    }

    #[test]
    fn tanh_of_special_values() {
        assert_eq!(tanh(0.0).to_bits(), 0.0f64.to_bits());
        assert_eq!(tanh(-0.0).to_bits(), (-0.0f64).to_bits());
        assert_eq!(tanh(1e-300), 1e-300);
        assert_eq!(tanh(f64::MIN_POSITIVE), f64::MIN_POSITIVE);
        assert_eq!(tanh(5e-324), 5e-324);
        assert_eq!((tanh(19.5), tanh(40.0), tanh(1e300)), (1.0, 1.0, 1.0));
        assert_eq!((tanh(f64::INFINITY), tanh(f64::NEG_INFINITY)), (1.0, -1.0));
        assert!(tanh(f64::NAN).is_nan());
    }

    /// The vector builds give the scalar function's bits (the batch passes run them).
    #[cfg(target_arch = "x86_64")]
    #[test]
    fn every_vector_build_of_tanh_gives_the_scalar_bits() {
        #[target_feature(enable = "avx2")]
        fn tanh_all_avx2(values: &mut [f64]) {
            tanh_all(values);
        }
        #[target_feature(enable = "avx512f,avx2")]
        fn tanh_all_avx512(values: &mut [f64]) {
            tanh_all(values);
        }
        let points = points();
        let scalar: Vec<u64> = points.iter().map(|&x| tanh(x).to_bits()).collect();
        let mut plain = points.clone();
        tanh_all(&mut plain);
        let mut builds = vec![("plain", plain)];
        if std::arch::is_x86_feature_detected!("avx2") {
            let mut values = points.clone();
            // SAFETY: the CPU has AVX2.
            unsafe { tanh_all_avx2(&mut values) };
            builds.push(("AVX2", values));
        }
        if std::arch::is_x86_feature_detected!("avx512f") {
            let mut values = points.clone();
            // SAFETY: the CPU has AVX-512F and AVX2.
            unsafe { tanh_all_avx512(&mut values) };
            builds.push(("AVX-512", values));
        }
        for (build, values) in builds {
            let bits: Vec<u64> = values.iter().map(|v| v.to_bits()).collect();
            assert!(bits == scalar, "the {build} build differs from the scalar");
        }
    }
}
