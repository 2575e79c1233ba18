//! Numbers written into the data files' lines without the formatting machinery: a float as
//! `{:.6}` writes it (the same bytes, proved by a test against `format!`), an integer as
//! `{}` does. The data files write several per trial, and `write!` costs several times the
//! arithmetic.

/// Finite non-negative values below this are written by the fast path (2³³).
const FAST_BELOW: f64 = 8_589_934_592.0;
/// 10⁶: six decimals.
const MICRO: u128 = 1_000_000;

/// Appends `x` with six decimals, exactly as `format!("{x:.6}")` writes it: the exact
/// binary value rounded to the nearest millionth, a tie to the even one.
pub(crate) fn push_six_decimals(out: &mut Vec<u8>, x: f64) {
    if !(x.is_sign_positive() && x < FAST_BELOW) {
        // Negative, −0, NaN, infinite or large: the library's formatting.
        out.extend_from_slice(format!("{x:.6}").as_bytes());
        return;
    }
    let bits = x.to_bits();
    let exponent = ((bits >> 52) & 0x7ff) as i32;
    let fraction = bits & ((1 << 52) - 1);
    // x = mantissa · 2^−shift exactly; below 2³³ a normal x has shift ≥ 20.
    let (mantissa, shift) = match exponent {
        0 => (fraction, 1074),
        _ => (fraction | 1 << 52, 1075 - exponent),
    };
    let scaled = u128::from(mantissa) * MICRO;
    let millionths: u128 = if shift >= 128 {
        // scaled < 2⁷³ is below half of 2^shift: rounds to 0.
        0
    } else {
        let whole = scaled >> shift;
        let rest = scaled & ((1 << shift) - 1);
        let half = 1u128 << (shift - 1);
        let up = rest > half || (rest == half && whole & 1 == 1);
        whole + u128::from(up)
    };
    // Below 2³³ · 10⁶ < 2⁵³.
    let millionths = millionths as u64;
    push_integer(out, millionths / MICRO as u64);
    out.push(b'.');
    let decimals = millionths % MICRO as u64;
    let mut digits = [b'0'; 6];
    let mut rest = decimals;
    for digit in digits.iter_mut().rev() {
        *digit = b'0' + (rest % 10) as u8;
        rest /= 10;
    }
    out.extend_from_slice(&digits);
}

/// Appends `n` in decimal, as `format!("{n}")` writes it.
pub(crate) fn push_integer(out: &mut Vec<u8>, n: impl itoa::Integer) {
    out.extend_from_slice(itoa::Buffer::new().format(n).as_bytes());
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::{Rng, SeedableRng};
    use rand_chacha::ChaCha8Rng;

    fn ours(x: f64) -> String {
        let mut out = Vec::new();
        push_six_decimals(&mut out, x);
        String::from_utf8(out).expect("ASCII digits")
    }

    fn check(x: f64) {
        assert_eq!(ours(x), format!("{x:.6}"), "{x:e} ({:#x})", x.to_bits());
    }

    #[test]
    fn six_decimals_are_the_librarys_bytes() {
        let mut rng = ChaCha8Rng::seed_from_u64(6);
        for _ in 0..2_000_000 {
            // Every binade from subnormals to beyond the fast path.
            let exponent = rng.random_range(-1074.0..40.0f64);
            check(rng.random_range(1.0..2.0) * exponent.exp2());
            check(f64::from_bits(rng.random_range(0..0x4210_0000_0000_0000)));
        }
        // Ties (a 5 in the seventh decimal, exactly) round to even; numbers a hair off them.
        for k in 0..200_000u64 {
            let tie = k as f64 / 128.0;
            for x in [tie, tie.next_up(), tie.next_down()] {
                check(x);
            }
        }
        for x in [
            0.0,
            -0.0,
            5e-7,
            4.999_999_999_999_999e-7,
            0.999_999_5,
            999_999.999_999_5,
            FAST_BELOW.next_down(),
            FAST_BELOW,
            f64::MIN_POSITIVE,
            f64::from_bits(1),
            f64::MAX,
            -1.5,
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::NAN,
        ] {
            check(x);
        }
    }

    #[test]
    fn integers_are_the_librarys_bytes() {
        let mut out = Vec::new();
        for n in [0usize, 7, 10, 99_999, usize::MAX] {
            out.clear();
            push_integer(&mut out, n);
            assert_eq!(out, n.to_string().as_bytes());
        }
    }
}
