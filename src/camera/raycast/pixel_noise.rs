//! Pixel noise that depends only on the seed, the frame and the pixel, so every read is
//! reproducible and no generator is shared.

/// A standard normal value that depends only on the seed, frame and pixel (two hashed
/// uniforms through Box–Muller).
pub(super) fn pixel_gaussian(seed: u64, frame: u64, column: usize, row: usize) -> f64 {
    let key = seed ^ frame.rotate_left(40) ^ ((column as u64) << 20) ^ row as u64;
    let (a, b) = (splitmix(key), splitmix(key ^ 0x9e37_79b9_7f4a_7c15));
    let uniform = |x: u64| ((x >> 11) as f64 + 0.5) / (1u64 << 53) as f64;
    (-2.0 * uniform(a).ln()).sqrt() * (std::f64::consts::TAU * uniform(b)).cos()
}

/// The SplitMix64 finaliser: a well-mixed 64-bit hash of `x`.
fn splitmix(x: u64) -> u64 {
    let mut z = x.wrapping_add(0x9e37_79b9_7f4a_7c15);
    z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
    z ^ (z >> 31)
}
