//! What a testbed's episode looks like: a look kept at every pose of the trial going on,
//! drawn by `render` as `eyehand show` draws a trial (the arm's side and top views beside
//! the camera image), and the camera's grey image at a chosen resolution.

use eyehand::camera::NotSeen;
use eyehand::control::{TrialLoop, TrialOutcome};
use eyehand::experiment::show::{camera_greys, draw_frame, FrameView, Look, RgbFrame, TrialTrace};
use nalgebra::Vector3;

/// The looks of the episode going on.
#[derive(Debug)]
pub struct EpisodeView {
    looks: Vec<Look>,
    /// Rays per image side of a rendered frame's camera image.
    resolution: usize,
    /// Episodes begun, counted in the frame's title.
    episodes: usize,
}

impl EpisodeView {
    /// No looks yet; frames drawn with `resolution` rays per image side.
    pub fn new(resolution: usize) -> EpisodeView {
        EpisodeView {
            looks: Vec::new(),
            resolution,
            episodes: 0,
        }
    }

    /// Forgets the last episode's looks and keeps the start's.
    pub fn begin(&mut self, trials: &TrialLoop, reading: Vector3<f64>) {
        self.looks.clear();
        self.episodes += 1;
        self.keep(trials, Ok(reading));
    }

    /// Keeps the look after a step.
    pub fn keep(&mut self, trials: &TrialLoop, reading: Result<Vector3<f64>, NotSeen>) {
        if let Some(object) = trials.object() {
            let sim = trials.sim();
            self.looks.push(Look {
                joints: sim.joints(),
                camera_pose: sim.camera_pose(),
                object,
                reading,
                sim_time: 0.0,
            });
        }
    }

    /// The frame of the episode so far; `None` before the first reset.
    pub fn frame(&self, trials: &TrialLoop) -> Option<Result<RgbFrame, String>> {
        let last = self.looks.last()?;
        let steps = self.looks.len() - 1;
        let trace = TrialTrace {
            trial: self.episodes,
            looks: self.looks.clone(),
            ticks: Vec::new(),
            outcome: TrialOutcome::default(),
            model: trials.sim().model().clone(),
            events: Vec::new(),
        };
        let title = format!("episode {}, after step {steps}", self.episodes);
        let distance = trials.distance_mm().unwrap_or(0.0);
        let seen = match last.reading {
            Ok(c) => format!("reading cx {:.1} px, cy {:.1} px, cz {:.2}", c.x, c.y, c.z),
            Err(_) => "the object is not seen".to_string(),
        };
        let caption = [
            format!("step {steps}: {distance:.2} mm from the goal"),
            seen,
        ];
        let world = trials.sim().world();
        let view = FrameView {
            camera: trials.camera().model(),
            resolution: self.resolution,
            scene: &world,
        };
        Some(draw_frame(&trace, &title, &view, &caption))
    }

    /// The grey image (`resolution` × `resolution`, row by row) the ray-cast camera sees
    /// now: the floor, obstacles and arm, and the object where it is seen; `None` before
    /// the first reset.
    pub fn camera_image(&self, trials: &TrialLoop, resolution: usize) -> Option<Vec<u8>> {
        let last = self.looks.last()?;
        let world = trials.sim().world();
        let size = resolution as u32;
        let camera = trials.camera().model();
        Some(camera_greys(last, camera, resolution, &world, (size, size)).1)
    }
}
