//! eyehand: a simulated camera-in-hand robot arm (OSCAR-6) that learns its own eye-hand
//! mapping — camera reading and joint angles in, joint moves out — with no knowledge of its
//! geometry, and keeps learning after its camera is turned or a link is stretched.
//!
//! The modules follow the architecture (see `ARCHITECTURE.md`):
//! [`robot`] (URDF model and simulators), [`camera`], [`control`] (trial loop and learning
//! patterns), [`learn`] (the learners), [`experiment`] (config, events, run output) and the
//! command line in [`cli`]. A learner written outside the crate needs only [`prelude`].
#![warn(missing_debug_implementations, unreachable_pub)]

pub mod camera;
pub mod cancel;
pub mod cli;
pub mod control;
pub mod experiment;
pub mod files;
pub mod learn;
pub mod prelude;
pub mod robot;
pub mod units;
