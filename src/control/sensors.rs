//! Noisy sensors: what the camera and the joint encoders report, apart from what is.
//!
//! A real blob detector's centroid jitters by a fraction of a pixel and its area by a
//! fraction of itself; a real encoder reads the joint to within its resolution. The noise
//! is Gaussian, drawn from its own stream of the run's seed (so the targets and starts a
//! seed draws stay the same whatever the noise), and only when its σ is above zero (so a
//! noiseless run draws nothing and stays byte-identical to one without this module).
//! Whether the object is seen is decided on the true image: noise changes what is reported,
//! not what is there.

use crate::camera::CameraModel;
use crate::learn::Observation;
use nalgebra::Vector3;
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rand_distr::StandardNormal;

/// The least a blob's area is scaled by its noise: a draw below it (σ past about 0.3 makes
/// them common) is clamped here, keeping cz finite and within the blob's own scale (√10 the
/// reading's distance factor at most).
const MIN_AREA_FACTOR: f64 = 0.1;

/// The stream of the run's seed the sensor noise is drawn from.
const NOISE_STREAM: u64 = 0x006e_6f69_7365;

/// How noisy the sensors are; all zero (exact sensors) by default.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct SensorNoise {
    /// σ of the blob centroid, each image axis (`camera_noise_px`, pixels); 0 by default.
    pub centroid_px: f64,
    /// σ of the blob area relative to itself (`camera_area_noise`); 0 by default.
    pub area_relative: f64,
    /// σ of each joint encoder's reading (`joint_noise_deg`, degrees); 0 by default.
    pub joint_deg: f64,
}

/// The sensor noise of a run, with its own generator.
#[derive(Debug, Clone)]
pub(crate) struct NoisySensors {
    noise: SensorNoise,
    rng: ChaCha8Rng,
}

impl NoisySensors {
    /// Sensors with `noise`, drawing from their own stream of `seed`.
    pub(crate) fn new(noise: SensorNoise, seed: u64) -> NoisySensors {
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        rng.set_stream(NOISE_STREAM);
        NoisySensors { noise, rng }
    }

    /// What the sensors report when the truth is `exact`, seen by a camera of `model`.
    pub(crate) fn report(&mut self, exact: Observation, model: &CameraModel) -> Observation {
        let SensorNoise {
            centroid_px,
            area_relative,
            joint_deg,
        } = self.noise;
        let mut seen = exact;
        if joint_deg > 0.0 {
            seen.theta_deg += self.gaussian3() * joint_deg;
        }
        if centroid_px > 0.0 {
            let jitter = self.gaussian3() * centroid_px;
            seen.c.x += jitter.x;
            seen.c.y += jitter.y;
        }
        if area_relative > 0.0 {
            let factor = 1.0 + area_relative * self.gaussian();
            let area = model.area_from_cz(seen.c.z) * factor.max(MIN_AREA_FACTOR);
            seen.c.z = model.cz_from_area(area);
        }
        seen
    }

    fn gaussian(&mut self) -> f64 {
        self.rng.sample(StandardNormal)
    }

    fn gaussian3(&mut self) -> Vector3<f64> {
        Vector3::new(self.gaussian(), self.gaussian(), self.gaussian())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn statistics(values: &[f64]) -> (f64, f64) {
        let n = values.len() as f64;
        let mean = values.iter().sum::<f64>() / n;
        let var = values.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / (n - 1.0);
        (mean, var.sqrt())
    }

    #[test]
    fn noisy_readings_have_the_configured_spread_and_no_bias() {
        let model = CameraModel::default();
        let noise = SensorNoise {
            centroid_px: 0.5,
            area_relative: 0.02,
            joint_deg: 0.1,
        };
        let mut sensors = NoisySensors::new(noise, 7);
        let exact = Observation {
            theta_deg: Vector3::new(10.0, 30.0, 90.0),
            c: Vector3::new(12.0, -40.0, 0.0),
        };
        let reports: Vec<Observation> =
            (0..10_000).map(|_| sensors.report(exact, &model)).collect();
        let axis = |f: &dyn Fn(&Observation) -> f64| {
            statistics(&reports.iter().map(f).collect::<Vec<_>>())
        };
        let checks: [(&str, (f64, f64), f64, f64); 4] = [
            ("cx", axis(&|o| o.c.x), 12.0, 0.5),
            ("cy", axis(&|o| o.c.y), -40.0, 0.5),
            ("θ2", axis(&|o| o.theta_deg.y), 30.0, 0.1),
            (
                "area",
                axis(&|o| model.area_from_cz(o.c.z) / model.reference_area()),
                1.0,
                0.02,
            ),
        ];
        for (name, (mean, sigma), want_mean, want_sigma) in checks {
            assert!((sigma / want_sigma - 1.0).abs() < 0.03, "{name}: σ {sigma}");
            assert!(
                (mean - want_mean).abs() < 0.03 * want_sigma,
                "{name}: mean {mean}"
            );
        }
    }

    /// The largest area noise the config allows: no reading leaves the blob's own scale
    /// (before the clamp, σ 0.45 wrote inf into a run's `abs_err`).
    #[test]
    fn the_noisiest_area_keeps_cz_finite_and_within_the_clamp() {
        let model = CameraModel::default();
        let noise = SensorNoise {
            area_relative: 0.5,
            ..SensorNoise::default()
        };
        let mut sensors = NoisySensors::new(noise, 3);
        let exact = Observation {
            theta_deg: Vector3::zeros(),
            c: Vector3::new(0.0, 0.0, 20.0),
        };
        let top = model.cz_from_area(model.area_from_cz(20.0) * MIN_AREA_FACTOR);
        let mut clamped = 0;
        for _ in 0..10_000 {
            let cz = sensors.report(exact, &model).c.z;
            assert!(cz.is_finite() && cz <= top * (1.0 + 1e-12), "{cz}");
            clamped += usize::from(cz >= top * (1.0 - 1e-12));
        }
        assert!(
            clamped > 100,
            "draws under a tenth of the area are common: {clamped}"
        );
    }

    #[test]
    fn exact_sensors_report_the_truth_and_draw_nothing() {
        let mut sensors = NoisySensors::new(SensorNoise::default(), 7);
        let before = sensors.rng.clone();
        let exact = Observation {
            theta_deg: Vector3::new(1.0, 2.0, 3.0),
            c: Vector3::new(4.0, 5.0, 6.0),
        };
        assert_eq!(sensors.report(exact, &CameraModel::default()), exact);
        assert_eq!(sensors.rng, before);
    }
}
