"""The Gymnasium environment ``eyehand/Reach-v0``: one episode is one trial of the testbed.

Observation Box(5, float32) = (cx, cy, cz, θ2, θ3), as the learners see it (pixels, the area
measure, degrees); cz is bounded at ``CZ_HIGH`` (the object 20 standoffs, 4 m, away: farther
than any arm here reaches) and clipped there. Action Box(3, float32) in [−1, 1]: the move
(Δθ1, Δθ2, Δθ3) as a share of ``max_move_deg`` (default 8° per joint: the smallest whole
degree at which the model-based ``ik`` policy reaches all of 300 seeded targets within the
ten steps; at 5°, 97%; a number or one per joint);
actions are clipped to [−1, 1] and ``action_for(move_deg)`` gives the action of a move in
degrees (scaled down as a whole to the bound). Reward: minus the distance (mm) from the camera to the target after the move; when
the move loses the object, minus ``feedback_steps`` × ``WORST_DISTANCE_MM`` instead (worse
than any whole episode that keeps the object in view, so losing it never pays).
``terminated`` once the camera is within ε after at least ``min_feedback_steps`` steps;
``truncated`` after ``feedback_steps`` steps or when the object leaves the image (the
observation then repeats the last one seen). ``info``: ``distance_mm``, ``joints_deg`` (θ1,
θ2, θ3), ``seen`` and ``end`` (None, "reached", "steps_used" or "lost").

``render_mode="rgb_array"`` makes ``render()`` draw the episode as ``eyehand show`` draws a
trial (the arm's views beside the camera image); ``"human"`` shows it in a Matplotlib window
where a display exists. ``image_resolution=N`` adds the ray-cast camera's N×N grey image:
the observation is then a Dict of ``reading`` (the Box above) and ``image``.

``reset(seed=…)`` restarts the draws of targets and starts from the seed; ``reset(options=
{"sim": …, "camera": …, "events": […]})`` builds a fresh testbed with that simulator, camera
and events (``rotate:EPISODE:DEG`` / ``elongate:EPISODE:LINK:CM``, applied before that
episode, counted from this reset).
"""

import importlib.util
import os
import sys

import gymnasium as gym
import numpy as np
from gymnasium import spaces

from ._eyehand import Testbed, parse_event

#: The move bound's default (degrees per joint and step).
MAX_MOVE_DEG = 8.0
#: The observation's bound on cz: the object 20 standoffs away (cz = 100·(depth/standoff − 1)).
CZ_HIGH = 1900.0
#: The farthest the camera can be from the target while it sees the object (mm): the
#: object at ``CZ_HIGH``'s 4 m, the target a standoff above it.
WORST_DISTANCE_MM = 4200.0


def _display_exists():
    """Whether a window can be shown: Matplotlib is installed and, on Linux, a display
    is set."""
    if importlib.util.find_spec("matplotlib") is None:
        return False
    return not sys.platform.startswith("linux") or any(
        os.environ.get(name) for name in ("DISPLAY", "WAYLAND_DISPLAY")
    )


#: The render modes: an RGB array, and a window where a display exists (and Matplotlib).
RENDER_MODES = ("rgb_array", "human") if _display_exists() else ("rgb_array",)
#: Frames per second of ``human`` rendering.
RENDER_FPS = 4
#: The smallest and largest camera image observation (pixels a side).
MIN_IMAGE = 2
MAX_IMAGE = 4096


def show_in_window(window, frame, fps):
    """Shows ``frame`` in ``window`` (a Matplotlib image; a new window when None) and
    returns the window."""
    import matplotlib.pyplot as plt

    if window is None:
        plt.ion()
        figure, axes = plt.subplots(figsize=(frame.shape[1] / 100, frame.shape[0] / 100))
        axes.set_axis_off()
        window = axes.imshow(frame)
    else:
        window.set_data(frame)
    plt.pause(1.0 / fps)
    return window


class ReachEnv(gym.Env):
    """Reach a target under the camera: the trial loop of ``eyehand run`` as an ``Env``."""

    metadata = {"render_modes": list(RENDER_MODES), "render_fps": RENDER_FPS}

    def __init__(
        self,
        config=None,
        sim="kinematic",
        camera="projection",
        urdf=None,
        events=(),
        max_move_deg=MAX_MOVE_DEG,
        seed=1,
        render_mode=None,
        image_resolution=None,
        **entries,
    ):
        if render_mode is not None and render_mode not in RENDER_MODES:
            raise ValueError(
                f"render_mode must be one of {RENDER_MODES} or None, not {render_mode!r} "
                "('human' needs Matplotlib and a display)"
            )
        self.render_mode = render_mode
        self._window = None
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
        self.max_move_deg = move
        self.action_space = spaces.Box(-1.0, 1.0, shape=(3,), dtype=np.float32)
        low = np.concatenate([reading[:, 0], limits[1:, 0]])
        high = np.concatenate([reading[:, 1], limits[1:, 1]])
        high[2] = min(high[2], CZ_HIGH)
        self._box = spaces.Box(low.astype(np.float32), high.astype(np.float32), dtype=np.float32)
        self.observation_space = self._box
        self.image_resolution = None
        if image_resolution is not None:
            n = int(image_resolution)
            if not MIN_IMAGE <= n <= MAX_IMAGE:
                raise ValueError(
                    f"image_resolution must be from {MIN_IMAGE} to {MAX_IMAGE}, not {image_resolution}"
                )
            self.image_resolution = n
            image = spaces.Box(0, 255, shape=(n, n, 1), dtype=np.uint8)
            self.observation_space = spaces.Dict({"reading": self._box, "image": image})

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
        if self.render_mode == "human":
            self.render()
        return self._observation(obs), self._info(seen=True)

    def action_for(self, move_deg):
        """The action (in [−1, 1], float32) of the move ``move_deg`` (Δθ1, Δθ2, Δθ3 in
        degrees), scaled down as a whole where it passes the move bound (its direction
        kept): to use a learner's answer as the policy."""
        share = np.asarray(move_deg, dtype=np.float64) / self.max_move_deg
        largest = np.max(np.abs(share))
        if largest > 1.0:
            share = share / largest
        return share.astype(np.float32)

    def step(self, action):
        share = np.clip(np.asarray(action, dtype=np.float64), -1.0, 1.0)
        _reading, joints, distance, seen = self.testbed.step(share * self.max_move_deg)
        end = self.testbed.end
        info = {"distance_mm": distance, "joints_deg": joints, "seen": seen, "end": end}
        terminated = end == "reached"
        truncated = end in ("steps_used", "lost")
        reward = -self.testbed.feedback_steps * WORST_DISTANCE_MM if end == "lost" else -distance
        if self.render_mode == "human":
            self.render()
        return self._observation(self.testbed.observation), float(reward), terminated, truncated, info

    def _observation(self, obs):
        """``obs`` as the observation space holds it: float32, cz clipped at ``CZ_HIGH``;
        with the camera's image when ``image_resolution`` is set."""
        space = self._box
        reading = np.clip(np.asarray(obs, dtype=np.float64), space.low, space.high).astype(np.float32)
        if self.image_resolution is None:
            return reading
        image = self.testbed.camera_image(self.image_resolution)
        return {"reading": reading, "image": image[:, :, np.newaxis]}

    def render(self):
        """The episode as ``eyehand show`` draws a trial: the arm's side and top views of
        every pose so far beside the camera's image at the last one. ``rgb_array``: an
        (H, W, 3) uint8 array; ``human``: shown in a Matplotlib window (None returned)."""
        if self.render_mode is None:
            gym.logger.warn("render() without a render_mode: pass render_mode to gym.make")
            return None
        frame = self.testbed.render()
        if frame is None:
            raise gym.error.ResetNeeded("render() before the first reset()")
        if self.render_mode == "rgb_array":
            return frame
        self._window = show_in_window(self._window, frame, RENDER_FPS)
        return None

    def close(self):
        if self._window is not None:
            import matplotlib.pyplot as plt

            plt.close(self._window.figure)
            self._window = None

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
