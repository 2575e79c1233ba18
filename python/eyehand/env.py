"""The Gymnasium environment ``eyehand/Reach-v0``: one episode is one trial of the testbed.

Observation Box(5) = (cx, cy, cz, θ2, θ3), as the learners see it (pixels, the area
measure, degrees). Action Box(3) = (Δθ1, Δθ2, Δθ3) in degrees, each within ±``max_move_deg``
(default 5°, a move that keeps the object in view from most starts; a number or one per
joint); actions are clipped to it. Reward: minus the distance
(mm) from the camera to the target after the move. ``terminated`` once the camera is within
ε after at least ``min_feedback_steps`` steps; ``truncated`` after ``feedback_steps`` steps or
when the object leaves the image (the observation then repeats the last one seen). ``info``:
``distance_mm``, ``joints_deg`` (θ1, θ2, θ3), ``seen`` and ``end`` (None, "reached",
"steps_used" or "lost").

``reset(seed=…)`` restarts the draws of targets and starts from the seed; ``reset(options=
{"sim": …, "camera": …, "events": […]})`` builds a fresh testbed with that simulator, camera
and events (``rotate:EPISODE:DEG`` / ``elongate:EPISODE:LINK:CM``, applied before that
episode, counted from this reset).
"""

import gymnasium as gym
import numpy as np
from gymnasium import spaces

from ._eyehand import Testbed, parse_event


class ReachEnv(gym.Env):
    """Reach a target under the camera: the trial loop of ``eyehand run`` as an ``Env``."""

    metadata = {"render_modes": []}

    def __init__(
        self,
        config=None,
        sim="kinematic",
        camera="projection",
        urdf=None,
        events=(),
        max_move_deg=5.0,
        seed=1,
        **entries,
    ):
        self._build = dict(config=config, sim=sim, camera=camera, urdf=urdf, entries=entries)
        self._seed = seed
        self._events = []
        self._episode = 0
        self.testbed = None
        self._rebuild(sim, camera, events)
        limits = self.testbed.joint_limits_deg
        reading = self.testbed.reading_bounds
        move = np.broadcast_to(np.asarray(max_move_deg, dtype=np.float64), (3,)).copy()
        if not np.all(np.isfinite(move) & (move > 0)):
            raise ValueError(f"max_move_deg must be positive and finite, not {max_move_deg}")
        self.action_space = spaces.Box(-move, move, dtype=np.float64)
        low = np.concatenate([reading[:, 0], limits[1:, 0]])
        high = np.concatenate([reading[:, 1], limits[1:, 1]])
        self.observation_space = spaces.Box(low, high, dtype=np.float64)

    def _rebuild(self, sim, camera, events):
        build = self._build
        config = None if build["config"] is None else str(build["config"])
        urdf = None if build["urdf"] is None else str(build["urdf"])
        self.testbed = Testbed(config, sim, camera, self._seed, urdf, **build["entries"])
        self._events = [parse_event(text) for text in events]
        self._episode = 0

    def reset(self, *, seed=None, options=None):
        super().reset(seed=seed)
        if options:
            unknown = set(options) - {"sim", "camera", "events"}
            if unknown:
                raise ValueError(f"unknown reset options: {sorted(unknown)}")
            self._rebuild(
                options.get("sim", self._build["sim"]),
                options.get("camera", self._build["camera"]),
                options.get("events", ()),
            )
        self._episode += 1
        for kind, episode, link, amount in self._events:
            if episode == self._episode:
                if kind == "rotate":
                    self.testbed.rotate_camera(amount)
                else:
                    self.testbed.stretch_link(link, amount)
        obs = self.testbed.reset(seed=seed)
        return obs, self._info(seen=True)

    def step(self, action):
        move = np.clip(np.asarray(action, dtype=np.float64), self.action_space.low, self.action_space.high)
        _reading, joints, distance, seen = self.testbed.step(move)
        end = self.testbed.end
        info = {"distance_mm": distance, "joints_deg": joints, "seen": seen, "end": end}
        terminated = end == "reached"
        truncated = end in ("steps_used", "lost")
        return self.testbed.observation, -distance, terminated, truncated, info

    def _info(self, seen):
        path = self.testbed.path
        return {
            "distance_mm": self.testbed.distance_mm,
            "joints_deg": path[-1, 3:].copy(),
            "seen": seen,
            "end": None,
        }

    def learn(self, learner):
        """Hands the episode's poses to ``learner`` (an ``eyehand.Learner`` or any object
        with ``learn(path)``), as the trial loop does after a trial."""
        self.testbed.learn(learner)

    def prelearn(self, learner):
        """The 8 pre-learning moves a run makes before its first trial, learned by
        ``learner``; call it before the first ``reset``."""
        self.testbed.prelearn(learner)
