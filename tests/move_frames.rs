//! `learn_during_moves`: the frames a camera takes while the arm moves join the trial's
//! learning path on the kinematic simulator, each a pose at which the object is seen, and
//! a run learns from more patterns than moves.

use eyehand::camera::{CameraModel, ProjectionCamera};
use eyehand::control::{MoveFrames, TrialLoop, TrialSettings};
use eyehand::experiment::{run, Config, RunOptions};
use eyehand::learn::{IkLearner, LearnError, Learner, Observation, Query};
use eyehand::robot::{ArmModel, KinematicSim, MoveSettings};
use nalgebra::Vector3;

/// The ik learner, keeping every path it is given to learn from.
#[derive(Debug)]
struct Keeping {
    ik: IkLearner,
    paths: Vec<Vec<Observation>>,
}

impl Learner for Keeping {
    fn name(&self) -> &str {
        "keeping"
    }
    fn propose(&mut self, query: &Query) -> Vector3<f64> {
        self.ik.propose(query)
    }
    fn learn(&mut self, path: &[Observation]) -> Result<(), LearnError> {
        self.paths.push(path.to_vec());
        Ok(())
    }
}

fn trial_loop(frames: Option<MoveFrames>) -> TrialLoop {
    let sim = KinematicSim::new(ArmModel::oscar6(), MoveSettings::from_degrees(10.0, 20.0));
    let settings = TrialSettings {
        feedback_steps: 5,
        min_feedback_steps: 5,
        epsilon: 1e-4,
        noise: Default::default(),
        timing: Default::default(),
        move_frames: frames,
    };
    TrialLoop::new(
        Box::new(sim),
        Box::new(ProjectionCamera::new(CameraModel::default())),
        settings,
        3,
    )
}

#[test]
fn frames_during_moves_join_the_path_between_the_step_poses() {
    let frames = MoveFrames {
        fps: 30.0,
        per_move: 4,
    };
    let mut with = trial_loop(Some(frames));
    let mut without = trial_loop(None);
    let keeping = || Keeping {
        ik: IkLearner::new(ArmModel::oscar6(), CameraModel::default()),
        paths: Vec::new(),
    };
    let (mut a, mut b) = (keeping(), keeping());
    for _ in 0..20 {
        let one = with.run_trial(&mut a).unwrap();
        let other = without.run_trial(&mut b).unwrap();
        // The frames are only learned: the trials themselves are the same.
        assert_eq!(one, other);
    }
    let camera = CameraModel::default();
    let mut extra = 0;
    for (long, short) in a.paths.iter().zip(&b.paths) {
        // The step poses are in the long path in their order, frames between them.
        let mut steps = short.iter().peekable();
        for pose in long {
            if steps.peek() == Some(&pose) {
                steps.next();
            } else {
                extra += 1;
            }
            // Every pose sees the object inside the image.
            assert!(pose.c.x.abs() <= camera.width / 2.0, "{pose:?}");
            assert!(pose.c.y.abs() <= camera.height / 2.0, "{pose:?}");
        }
        assert!(
            steps.peek().is_none(),
            "every step pose is in the long path"
        );
        assert!(long.len() <= short.len() + 4 * (short.len() - 1));
    }
    assert!(
        extra > 2 * a.paths.len(),
        "{extra} frames in {} trials",
        a.paths.len()
    );
}

#[test]
fn a_run_learning_during_moves_learns_more_patterns_than_moves() {
    let data = tempfile::tempdir().unwrap();
    let base = Config {
        trials: 300,
        ..Config::default_config()
    };
    let summary = |learn_during_moves| {
        let config = Config {
            learn_during_moves,
            camera_fps: if learn_during_moves == 1 { 30.0 } else { 0.0 },
            ..base.clone()
        };
        run(&RunOptions::new(config, data.path())).unwrap().summary
    };
    let (with, without) = (summary(1), summary(0));
    assert!(
        with.patterns as u64 > with.moves,
        "{} patterns, {} moves",
        with.patterns,
        with.moves
    );
    assert!(
        with.patterns as f64 > 1.3 * without.patterns as f64,
        "{} against {}",
        with.patterns,
        without.patterns
    );
}
