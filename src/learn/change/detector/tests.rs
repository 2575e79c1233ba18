//! The detector on synthetic streams shaped like a learning tree's per-trial errors.

use super::*;
use proptest::prelude::*;
use proptest::test_runner::RngSeed;
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

/// The spread of the synthetic noise (a real stream's is about 0.5).
const SPREAD: f64 = 0.52;

/// A value around `level`: near-normal noise of spread [`SPREAD`], and one time in 1,000 a
/// wild value four spreads up. (The real stream is tamer: 0.03% of its trials are more
/// than three spreads above the baseline, none more than four.)
fn value(rng: &mut ChaCha8Rng, level: f64) -> f64 {
    let noise: f64 = (0..4).map(|_| rng.random_range(-1.0..1.0)).sum::<f64>() * 0.45;
    let wild = if rng.random_range(0.0..1.0) < 0.001 {
        4.0 * SPREAD
    } else {
        0.0
    };
    level + noise + wild
}

/// A level that falls as a tree learns: fast at first, then slowly for ever.
fn improving(n: u64) -> f64 {
    -3.5 + 2.0 * (-(n as f64) / 300.0).exp() - 0.3 * (n as f64 / 10_000.0).ln_1p()
}

proptest! {
    // A fixed seed, so the run is the same every time: streams of this kind raise about
    // one false alarm in 20,000,000 values (measured), so random seeds would fail now and
    // then.
    #![proptest_config(ProptestConfig {
        cases: 24,
        rng_seed: RngSeed::Fixed(2024),
        ..ProptestConfig::default()
    })]

    #[test]
    fn a_step_rise_is_found_soon_and_dated_near_the_change(
        seed in 0u64..1000,
        rise in 2.0f64..8.0,
        at in 300u64..6000,
    ) {
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        let mut detector = ChangeDetector::new(DetectorSettings::default());
        for n in 1..at {
            prop_assert_eq!(detector.observe(n, value(&mut rng, improving(n))), None, "false alarm at {}", n);
        }
        let alarm = (at..at + 200)
            .find_map(|n| detector.observe(n, value(&mut rng, improving(n) + rise * SPREAD)))
            .expect("the rise is found");
        prop_assert!(alarm.raised_at - at < 40, "delay {}", alarm.raised_at - at);
        // (99% of such rises are dated within 6 values; noise just before a change can
        // make it some 25 early.)
        prop_assert!(alarm.changed_at.abs_diff(at) <= 30, "dated {} for {}", alarm.changed_at, at);
    }

    #[test]
    fn a_long_stationary_or_improving_stream_raises_no_alarm(seed in 0u64..1000, slope in 0.0f64..1.0) {
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        let mut detector = ChangeDetector::new(DetectorSettings::default());
        for n in 1..100_000u64 {
            let level = slope * improving(n) - 3.0 * (1.0 - slope);
            prop_assert_eq!(detector.observe(n, value(&mut rng, level)), None, "false alarm at {}", n);
        }
    }
}

#[test]
fn no_alarm_comes_within_the_warmup_and_after_an_alarm_the_detector_starts_over() {
    let settings = DetectorSettings::default();
    let mut detector = ChangeDetector::new(settings);
    let mut rng = ChaCha8Rng::seed_from_u64(1);
    for n in 0..settings.warmup as u64 {
        let x = value(&mut rng, if n < 100 { -3.0 } else { 3.0 });
        assert_eq!(detector.observe(n, x), None, "still warming up at {n}");
    }
    let mut detector = ChangeDetector::new(settings);
    let mut n = 0;
    let mut alarms = Vec::new();
    while alarms.len() < 2 {
        let level = if n < 1000 {
            -3.0
        } else if n < 2000 {
            0.0
        } else {
            3.0
        };
        if let Some(alarm) = detector.observe(n, value(&mut rng, level)) {
            alarms.push(alarm);
        }
        n += 1;
        assert!(n < 3000, "{alarms:?}");
    }
    // Each rise of 6 spreads takes a few values; the second comes after a fresh warmup.
    assert!(alarms[0].raised_at - 1000 < 10, "{alarms:?}");
    assert!(alarms[0].changed_at.abs_diff(1000) <= 2, "{alarms:?}");
    assert!(alarms[1].raised_at >= 2000.max(alarms[0].raised_at + settings.warmup as u64));
    assert_eq!(detector.statistic(), 0.0);
}

#[test]
fn non_finite_values_are_ignored() {
    let mut detector = ChangeDetector::new(DetectorSettings::default());
    for n in 0..1000 {
        assert_eq!(detector.observe(n, f64::NAN), None);
        assert_eq!(detector.observe(n, f64::INFINITY), None);
    }
    assert_eq!(detector.statistic(), 0.0);
    assert_eq!(detector.seen, 0);
}

#[test]
fn a_run_of_failures_is_found_in_five_values_and_dated_to_the_first() {
    let mut detector = ChangeDetector::new(DetectorSettings::default());
    // A constant stream leaves the statistic at 0.
    for n in 0..1000 {
        assert_eq!(detector.observe(n, -3.0), None, "at {n}");
    }
    assert_eq!(detector.statistic(), 0.0);
    // Each failure counts 4 spreads less the drift: 3.5, 7, 10.5, 14, 17.5 > 16.
    for n in 1000..1004 {
        assert_eq!(detector.observe_failure(n), None, "at {n}");
    }
    let alarm = detector
        .observe_failure(1004)
        .expect("five failures are an alarm");
    assert_eq!(alarm.changed_at, 1000);
}

#[test]
fn scattered_failures_raise_no_alarm_and_stay_out_of_the_baseline() {
    let mut detector = ChangeDetector::new(DetectorSettings::default());
    let mut rng = ChaCha8Rng::seed_from_u64(4);
    for n in 1..100_000u64 {
        // One trial in 50 fails, far more often than on the real stream (0.14%).
        let alarm = if n % 50 == 0 {
            detector.observe_failure(n)
        } else {
            detector.observe(n, value(&mut rng, -3.0))
        };
        assert_eq!(alarm, None, "false alarm at {n}");
    }
    assert!(
        (detector.mean + 3.0).abs() < 0.1,
        "baseline {}",
        detector.mean
    );
    assert_eq!(detector.lagging.len(), detector.settings.lag);
}
