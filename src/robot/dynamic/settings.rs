//! The dynamic simulator's settings: the engine that steps the arm, time step, solver,
//! servo gains and when a move counts as settled.

use crate::robot::MoveSettings;

/// What steps the dynamic arm.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub enum Engine {
    /// eyehand's own: the joint-space equations integrated by a fourth-order Runge–Kutta
    /// step per tick under its servo law (Rapier places the bodies and steps contacts).
    #[default]
    Rk4,
    /// Rapier's multibody integrator, each joint driven by a Rapier joint motor, its
    /// limits Rapier's joint limits, its contacts as Rapier resolves them.
    Rapier,
}

impl Engine {
    /// Both engines, the default first.
    pub const ALL: [Engine; 2] = [Engine::Rk4, Engine::Rapier];
}

/// How the dynamic simulator steps and servoes the arm. [`Default`] gives the values of the
/// shipped configs: a stiff, critically damped 100 Hz servo on a 200 Hz control loop.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DynamicSettings {
    /// The trapezoidal profile of a move (top speed and acceleration of the lead joint)
    /// and the floor; default 90°/s, 180°/s² and −0.22 m.
    pub moves: MoveSettings,
    /// What steps the arm; default [`Engine::Rk4`].
    pub engine: Engine,
    /// Physics and control time step (s); default 0.005 (200 Hz).
    pub dt: f64,
    /// Rapier's constraint solver iterations (each a sub-step of its step): on the `rapier`
    /// engine every tick, on `rk4` the ticks Rapier steps (a link near something); at
    /// least 4 while a link is near something; default 1.
    pub solver_iterations: usize,
    /// Rapier steps per tick on the `rapier` engine, each of `dt` / this; default 1.
    pub rapier_substeps: usize,
    /// Position gain of every joint servo (1/s², acceleration-based: the arm's mass matrix
    /// is factored in); default 400,000 (a 100 Hz servo).
    pub motor_stiffness: f64,
    /// Velocity gain of every joint servo (1/s, acceleration-based); default 1265 (critical
    /// damping for the default stiffness).
    pub motor_damping: f64,
    /// A move has settled once every joint is this close to its set-point (rad); default
    /// 0.0005° in radians.
    pub settle_position_tol: f64,
    /// … and every joint turns slower than this (rad/s); default 0.05°/s in radians.
    pub settle_speed_tol: f64,
    /// Simulated time (s) the arm gets to settle after the profile ends before the move is
    /// reported as not settled; default 2.
    pub settle_timeout: f64,
}

impl Default for DynamicSettings {
    fn default() -> Self {
        DynamicSettings {
            moves: MoveSettings::default(),
            engine: Engine::Rk4,
            dt: 0.005,
            solver_iterations: 1,
            rapier_substeps: 1,
            motor_stiffness: 400_000.0,
            motor_damping: 1265.0,
            settle_position_tol: 0.0005f64.to_radians(),
            settle_speed_tol: 0.05f64.to_radians(),
            settle_timeout: 2.0,
        }
    }
}

impl DynamicSettings {
    /// These settings with every value that is not finite and positive replaced by its
    /// default (zero solver iterations or sub-steps become one).
    pub fn sanitized(&self) -> DynamicSettings {
        let default = DynamicSettings::default();
        let pick = |value: f64, fallback: f64| {
            if value.is_finite() && value > 0.0 {
                value
            } else {
                fallback
            }
        };
        DynamicSettings {
            moves: MoveSettings {
                speed: pick(self.moves.speed, default.moves.speed),
                accel: pick(self.moves.accel, default.moves.accel),
                floor_z: if self.moves.floor_z.is_nan() {
                    default.moves.floor_z
                } else {
                    self.moves.floor_z
                },
            },
            engine: self.engine,
            dt: pick(self.dt, default.dt),
            solver_iterations: self.solver_iterations.max(1),
            rapier_substeps: self.rapier_substeps.max(1),
            motor_stiffness: pick(self.motor_stiffness, default.motor_stiffness),
            motor_damping: pick(self.motor_damping, default.motor_damping),
            settle_position_tol: pick(self.settle_position_tol, default.settle_position_tol),
            settle_speed_tol: pick(self.settle_speed_tol, default.settle_speed_tol),
            settle_timeout: pick(self.settle_timeout, default.settle_timeout),
        }
    }

    /// Steps the arm gets to settle after a move's profile.
    pub(super) fn settle_steps(&self) -> usize {
        (self.settle_timeout / self.dt).ceil() as usize
    }
}
