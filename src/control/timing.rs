//! The camera's clock: when frames are taken, how old they are when they arrive, and
//! whether the arm settles between them or keeps moving.
//!
//! Time is counted in the simulator's ticks (its physics step `dt`), from the moment the
//! trial's first frame is taken at the start pose. Frame k is taken at tick
//! round(k / (fps·dt)) and delivered `latency` later; the arm rests at its start until the
//! first frame arrives, and a trial's seconds count from then. A simulator without a clock
//! (the kinematic one) takes a frame the moment each move ends, as the study did.

/// How the arm moves between frames.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub enum ServoMode {
    /// One move per frame, settled before the next frame is taken (the study's).
    #[default]
    Step,
    /// A new move at every frame, relative to the pose the frame was taken at; the servos'
    /// set-point changes at once, without settling (the dynamic simulator only).
    Continuous,
}

/// When the camera delivers frames; [`Default`] is the study's: a frame the moment a move
/// has settled, no latency, step servoing.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct CameraTiming {
    /// Frames per second of a free-running camera (`camera_fps`); 0 (the default): a frame
    /// is taken the moment a move has settled.
    pub fps: f64,
    /// A frame shows the world as it was this long (s) before it is delivered
    /// (`camera_latency_ms` / 1000); default 0.
    pub latency: f64,
    /// Step (the default) or continuous servoing (`servo_mode`).
    pub servo: ServoMode,
}

impl CameraTiming {
    /// True for the study's timing, which needs no clock.
    pub fn is_untimed(&self) -> bool {
        *self == CameraTiming::default()
    }
}

/// The camera's clock on a simulator with ticks.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct FrameClock {
    /// Ticks between frames (0: a frame whenever asked).
    ticks_per_frame: f64,
    /// Ticks from a frame's taking to its delivery.
    pub(super) latency_ticks: u64,
    /// The tick (s).
    dt: f64,
    /// Continuous servoing.
    pub(super) continuous: bool,
}

impl FrameClock {
    /// The clock of `timing` on a simulator whose tick is `dt` (s); `None` for the
    /// study's timing or a simulator without a clock. Latency is rounded to whole ticks.
    pub(super) fn new(timing: &CameraTiming, dt: Option<f64>) -> Option<FrameClock> {
        let dt = dt.filter(|dt| *dt > 0.0 && !timing.is_untimed())?;
        let rate = timing.fps.max(0.0);
        Some(FrameClock {
            ticks_per_frame: if rate > 0.0 { 1.0 / (rate * dt) } else { 0.0 },
            latency_ticks: (timing.latency.max(0.0) / dt).round() as u64,
            dt,
            continuous: timing.servo == ServoMode::Continuous && rate > 0.0,
        })
    }

    /// The tick at which frame `k` of a free-running camera is taken.
    pub(super) fn capture_tick(&self, k: u64) -> u64 {
        (k as f64 * self.ticks_per_frame).round() as u64
    }

    /// The tick of the first frame taken at or after tick `now`.
    pub(super) fn next_capture(&self, now: u64) -> u64 {
        if self.ticks_per_frame == 0.0 {
            return now;
        }
        let mut k = (now as f64 / self.ticks_per_frame).floor() as u64;
        while self.capture_tick(k) < now {
            k += 1;
        }
        self.capture_tick(k)
    }

    /// Seconds of `ticks`.
    pub(super) fn seconds(&self, ticks: u64) -> f64 {
        ticks as f64 * self.dt
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn clock(fps: f64, latency: f64) -> FrameClock {
        let timing = CameraTiming {
            fps,
            latency,
            servo: ServoMode::Continuous,
        };
        FrameClock::new(&timing, Some(0.005)).unwrap()
    }

    #[test]
    fn frames_fall_on_the_nearest_tick_and_latency_on_whole_ticks() {
        let c = clock(30.0, 0.05);
        let ticks: Vec<u64> = (0..4).map(|k| c.capture_tick(k)).collect();
        assert_eq!(ticks, [0, 7, 13, 20]);
        assert_eq!(c.latency_ticks, 10);
        assert_eq!(c.next_capture(8), 13);
        assert_eq!(c.next_capture(13), 13);
        assert!(c.continuous);
    }

    #[test]
    fn the_studys_timing_or_no_clock_needs_none() {
        assert_eq!(FrameClock::new(&CameraTiming::default(), Some(0.005)), None);
        assert_eq!(
            FrameClock::new(
                &CameraTiming {
                    fps: 30.0,
                    ..Default::default()
                },
                None
            ),
            None
        );
        let on_demand = FrameClock::new(
            &CameraTiming {
                latency: 0.02,
                ..Default::default()
            },
            Some(0.005),
        )
        .unwrap();
        assert_eq!(on_demand.next_capture(17), 17);
        assert!(!on_demand.continuous);
    }
}
