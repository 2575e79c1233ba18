//! Feedback steps under the camera's clock (a free-running camera, latency, continuous
//! servoing) on a simulator with ticks.
//!
//! In step servoing a move is executed and settles; the arm then holds still until the
//! first frame taken after it, and that frame's delivery. In continuous servoing the move
//! the learner asks for at a frame is added to the pose that frame was taken at (as the
//! encoders reported it) and becomes the servos' new goal at once; the arm keeps moving
//! while the camera keeps taking frames, and the step ends when the next frame arrives.
//! Frames taken but not yet delivered wait in a queue (with latency above a frame's
//! period, more than one does).

use super::timing::FrameClock;
use super::trial::{Sight, TrialLoop};
use nalgebra::{Point3, Vector3};
use std::collections::VecDeque;

/// A frame on its way to the trial loop.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct Frame {
    /// What it shows, as the sensors reported it when it was taken.
    pub(super) sight: Sight,
    /// The tick at which it is delivered.
    pub(super) delivered_at: u64,
}

/// The trial's time and the frames taken but not yet delivered.
#[derive(Debug, Clone, Default)]
pub(super) struct FrameQueue {
    /// Ticks since the trial's first frame was taken.
    pub(super) now: u64,
    /// The number of the next frame the free-running camera takes.
    next_frame: u64,
    pending: VecDeque<Frame>,
}

impl TrialLoop {
    /// Starts the trial's clock: the first frame was taken at the start pose at tick 0
    /// and the arm waits there for its delivery; a free-running camera has meanwhile taken
    /// the frames due (of the arm at rest).
    pub(super) fn start_clock(&mut self, clock: &FrameClock, object: &Point3<f64>) {
        self.frames.pending.clear();
        self.frames.now = clock.latency_ticks;
        self.frames.next_frame = 1;
        if clock.continuous {
            self.take_due_frames(clock, object);
        }
    }

    /// One feedback step of `delta` (θ1..θ3, rad) under `clock`: the frame delivered at
    /// its end.
    pub(super) fn clocked_step(
        &mut self,
        clock: &FrameClock,
        delta: &Vector3<f64>,
        object: &Point3<f64>,
    ) -> Sight {
        if clock.continuous {
            let here = self.path[self.path.len() - 1]
                .theta_deg
                .map(f64::to_radians);
            self.sim.servo_toward(&(here + delta));
            return self.run_to_delivery(clock, object);
        }
        let report = self.sim.execute(delta);
        if let Some(frames) = self.settings().move_frames {
            self.learn_frames_of_move(&frames, report.duration, object);
        }
        self.frames.now += (report.duration / clock.seconds(1)).round() as u64;
        let taken = clock.next_capture(self.frames.now);
        self.hold_until(taken);
        let sight = self.look(object);
        self.hold_until(taken + clock.latency_ticks);
        sight
    }

    /// Seconds since the trial's first frame was delivered.
    pub(super) fn clock_seconds(&self, clock: &FrameClock) -> f64 {
        clock.seconds(self.frames.now.saturating_sub(clock.latency_ticks))
    }

    /// Servo ticks (holding the arm where its set-point is) until tick `tick`.
    fn hold_until(&mut self, tick: u64) {
        while self.frames.now < tick {
            self.sim.servo_tick();
            self.frames.now += 1;
        }
    }

    /// Servo ticks, the camera taking its frames as they fall due, until the oldest frame
    /// on its way is delivered: that frame.
    fn run_to_delivery(&mut self, clock: &FrameClock, object: &Point3<f64>) -> Sight {
        loop {
            if let Some(frame) = self.frames.pending.front() {
                if frame.delivered_at <= self.frames.now {
                    let sight = frame.sight;
                    self.frames.pending.pop_front();
                    return sight;
                }
            }
            self.sim.servo_tick();
            self.frames.now += 1;
            self.take_due_frames(clock, object);
        }
    }

    /// Takes every frame of the free-running camera due by now.
    fn take_due_frames(&mut self, clock: &FrameClock, object: &Point3<f64>) {
        loop {
            let taken = clock.capture_tick(self.frames.next_frame);
            if taken > self.frames.now {
                return;
            }
            let sight = self.look(object);
            self.frames.pending.push_back(Frame {
                sight,
                delivered_at: taken + clock.latency_ticks,
            });
            self.frames.next_frame += 1;
        }
    }
}
