//! A one-sided CUSUM test for a rise in the level of a stream of pattern errors.
//!
//! The stream is the log of each learning pattern's error (so that a rise by a factor is a
//! step of fixed size, and single outliers weigh little). A baseline follows the stream's
//! level slowly (an exponential average over `baseline_patterns`); the statistic
//! S ← max(0, S + x − baseline − drift) grows while errors stay above the baseline by more
//! than `drift` and drains otherwise. An alarm comes when S exceeds `threshold`; the change
//! is dated to the last pattern at which S was zero (the CUSUM estimate of the change
//! point). While S is positive the baseline is frozen, so a change cannot teach the baseline
//! to accept it. After an alarm the detector starts afresh and re-learns the baseline.
//!
//! The stream of a learning tree drifts down as it learns; a one-sided test for rises does
//! not mind that.

/// Settings of the change detector.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DetectorSettings {
    /// Patterns the baseline averages over (its time constant); 2,000 by default.
    pub baseline_patterns: usize,
    /// Patterns watched before the first alarm can come; 500 by default.
    pub warmup_patterns: usize,
    /// Allowed rise of the log error above the baseline before it counts; 1.0 (a factor
    /// e ≈ 2.7) by default.
    pub drift: f64,
    /// Alarm level of the CUSUM statistic (log units); 60 by default.
    pub threshold: f64,
    /// Errors below this (degrees) count as this, so exact answers do not dominate the
    /// log; 1e-6 by default.
    pub error_floor: f64,
}

impl Default for DetectorSettings {
    fn default() -> Self {
        DetectorSettings {
            baseline_patterns: 2000,
            warmup_patterns: 500,
            drift: 1.0,
            threshold: 60.0,
            error_floor: 1e-6,
        }
    }
}

impl DetectorSettings {
    /// The settings a config gives (`change_baseline`, `change_warmup`, `change_drift`,
    /// `change_threshold`).
    pub fn from_config(config: &crate::experiment::Config) -> DetectorSettings {
        DetectorSettings {
            baseline_patterns: config.change_baseline,
            warmup_patterns: config.change_warmup,
            drift: config.change_drift,
            threshold: config.change_threshold,
            ..DetectorSettings::default()
        }
    }
}

/// A detected change.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Alarm {
    /// Sequence number of the pattern that raised the alarm.
    pub raised_at: u64,
    /// Sequence number of the first pattern after the estimated change.
    pub changed_at: u64,
}

/// CUSUM change detector over a stream of pattern errors.
#[derive(Debug, Clone, PartialEq)]
pub struct ChangeDetector {
    settings: DetectorSettings,
    baseline: f64,
    seen: usize,
    statistic: f64,
    last_zero: u64,
}

impl ChangeDetector {
    /// A detector that has seen nothing yet.
    pub fn new(settings: DetectorSettings) -> ChangeDetector {
        ChangeDetector {
            settings,
            baseline: 0.0,
            seen: 0,
            statistic: 0.0,
            last_zero: 0,
        }
    }

    /// The current CUSUM statistic.
    pub fn statistic(&self) -> f64 {
        self.statistic
    }

    /// Takes the error (degrees) of pattern number `sequence`; returns an alarm when the
    /// stream has risen. Non-finite errors are ignored.
    pub fn observe(&mut self, sequence: u64, error: f64) -> Option<Alarm> {
        if !error.is_finite() {
            return None;
        }
        let x = error.max(self.settings.error_floor).ln();
        self.seen += 1;
        if self.seen == 1 {
            self.baseline = x;
        }
        let warm = self.seen > self.settings.warmup_patterns;
        if warm {
            self.statistic = (self.statistic + x - self.baseline - self.settings.drift).max(0.0);
        }
        if self.statistic == 0.0 {
            self.last_zero = sequence;
            let rate = 1.0 / (self.seen.min(self.settings.baseline_patterns)) as f64;
            self.baseline += rate * (x - self.baseline);
        }
        if self.statistic > self.settings.threshold {
            let alarm = Alarm {
                raised_at: sequence,
                changed_at: self.last_zero + 1,
            };
            *self = ChangeDetector::new(self.settings);
            return Some(alarm);
        }
        None
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;
    use rand::{Rng, SeedableRng};
    use rand_chacha::ChaCha8Rng;

    /// Errors like a learning tree's: log-normal around `level`, with rare outliers.
    fn error(rng: &mut ChaCha8Rng, level: f64) -> f64 {
        let noise: f64 = (0..4).map(|_| rng.random_range(-1.0..1.0)).sum::<f64>() * 0.6;
        let outlier = if rng.random_range(0.0..1.0) < 0.002 {
            200.0
        } else {
            1.0
        };
        level * noise.exp() * outlier
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(24))]

        #[test]
        fn a_step_rise_is_found_soon_and_dated_near_the_change(seed in 0u64..1000, rise in 20.0f64..1000.0, at in 3000u64..20_000) {
            let mut rng = ChaCha8Rng::seed_from_u64(seed);
            let mut detector = ChangeDetector::new(DetectorSettings::default());
            for n in 1..at {
                prop_assert_eq!(detector.observe(n, error(&mut rng, 0.01)), None, "false alarm at {}", n);
            }
            let mut alarm = None;
            for n in at..at + 2000 {
                if let Some(a) = detector.observe(n, error(&mut rng, 0.01 * rise)) {
                    alarm = Some(a);
                    break;
                }
            }
            let alarm = alarm.expect("the rise is detected");
            prop_assert!(alarm.raised_at - at < 40, "delay {} patterns", alarm.raised_at - at);
            prop_assert!(alarm.changed_at.abs_diff(at) <= 5, "dated {} for {}", alarm.changed_at, at);
        }

        #[test]
        fn a_long_stationary_or_improving_stream_raises_no_alarm(seed in 0u64..1000) {
            let mut rng = ChaCha8Rng::seed_from_u64(seed);
            let mut detector = ChangeDetector::new(DetectorSettings::default());
            for n in 1..200_000u64 {
                let level = 0.01 * (1.0 + 100.0 * (-(n as f64) / 20_000.0).exp());
                prop_assert_eq!(detector.observe(n, error(&mut rng, level)), None, "false alarm at {}", n);
            }
        }
    }

    #[test]
    fn non_finite_errors_are_ignored() {
        let mut detector = ChangeDetector::new(DetectorSettings::default());
        for n in 0..1000 {
            assert_eq!(detector.observe(n, f64::NAN), None);
            assert_eq!(detector.observe(n, f64::INFINITY), None);
        }
        assert_eq!(detector.statistic(), 0.0);
    }
}
