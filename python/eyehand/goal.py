"""The goal-conditioned environment ``eyehand/ReachGoal-v0``: the episodes of
``eyehand/Reach-v0`` in the form Hindsight Experience Replay needs (Stable-Baselines3's
``HerReplayBuffer``, gymnasium-robotics' Fetch tasks).

Observation: a Dict of ``observation`` Box(6, float32) = (θ1, θ2, θ3 in degrees as the
encoders report them, the camera's position x, y, z in mm), ``achieved_goal`` Box(3,
float32), the camera's position (world, mm), and ``desired_goal`` Box(3, float32), the goal
point: where the camera is to be, a standoff above the object (world, mm). Positions are
bounded at ±``CAMERA_BOUND_MM``. The camera's reading is not in the observation: it depends
on the desired goal, which HER replaces by goals reached later.

Reward: ``compute_reward(achieved_goal, desired_goal, info)`` on one goal pair or on (B, 3)
batches (``info`` unused): ``reward_type="sparse"`` gives −1 beyond
``distance_threshold_mm`` (default 50 mm, FetchReach's 5 cm; settable on the env) and 0
within it, ``"dense"`` minus the distance (mm). Episodes end as ``Reach-v0``'s do:
``terminated`` within ε after ``min_feedback_steps``, ``truncated`` after ``feedback_steps``
or when the object leaves the image; ``info`` is ``Reach-v0``'s.
"""

import gymnasium as gym
import numpy as np
from gymnasium import spaces

from .env import ReachEnv

#: The bound of the camera and goal positions (mm, each axis): past any arm's reach here.
CAMERA_BOUND_MM = 2000.0
#: The sparse reward's default success distance (mm): FetchReach's 5 cm.
DISTANCE_THRESHOLD_MM = 50.0
#: The reward types.
REWARD_TYPES = ("sparse", "dense")


class ReachGoalEnv(gym.Env):
    """Reach a goal point given in world coordinates: ``eyehand/Reach-v0`` for HER."""

    metadata = ReachEnv.metadata

    def __init__(
        self,
        distance_threshold_mm=DISTANCE_THRESHOLD_MM,
        reward_type="sparse",
        render_mode=None,
        **kwargs,
    ):
        if reward_type not in REWARD_TYPES:
            raise ValueError(f"reward_type must be one of {REWARD_TYPES}, not {reward_type!r}")
        self._reach = ReachEnv(render_mode=render_mode, **kwargs)
        self.render_mode = self._reach.render_mode
        self.reward_type = reward_type
        self.distance_threshold_mm = distance_threshold_mm
        limits = self._reach.testbed.joint_limits_deg
        bound = np.full(3, CAMERA_BOUND_MM)
        goal = spaces.Box(-bound.astype(np.float32), bound.astype(np.float32), dtype=np.float32)
        low = np.concatenate([limits[:, 0], -bound]).astype(np.float32)
        high = np.concatenate([limits[:, 1], bound]).astype(np.float32)
        self.observation_space = spaces.Dict(
            {
                "observation": spaces.Box(low, high, dtype=np.float32),
                "achieved_goal": goal,
                "desired_goal": goal,
            }
        )
        self.action_space = self._reach.action_space

    @property
    def distance_threshold_mm(self):
        """The sparse reward's success distance (mm)."""
        return self._threshold

    @distance_threshold_mm.setter
    def distance_threshold_mm(self, value):
        value = float(value)
        if not (np.isfinite(value) and value > 0):
            raise ValueError(f"distance_threshold_mm must be positive and finite, not {value}")
        self._threshold = value

    @property
    def testbed(self):
        """The testbed the episodes run on."""
        return self._reach.testbed

    @property
    def max_move_deg(self):
        """The move bound (degrees per joint)."""
        return self._reach.max_move_deg

    def action_for(self, move_deg):
        """The action of the move ``move_deg`` (degrees), as ``ReachEnv.action_for``."""
        return self._reach.action_for(move_deg)

    def reset(self, *, seed=None, options=None):
        super().reset(seed=seed)
        _, info = self._reach.reset(seed=seed, options=options)
        return self._observation(info), info

    def step(self, action):
        _, _, terminated, truncated, info = self._reach.step(action)
        obs = self._observation(info)
        reward = self.compute_reward(obs["achieved_goal"], obs["desired_goal"], info)
        return obs, float(reward), terminated, truncated, info

    def render(self):
        return self._reach.render()

    def close(self):
        self._reach.close()

    def compute_reward(self, achieved_goal, desired_goal, info):
        """The reward of the camera at ``achieved_goal`` for ``desired_goal`` (mm): (3,)
        each, or (B, 3) each for (B,) rewards; ``info`` is not used."""
        achieved = np.asarray(achieved_goal, dtype=np.float64)
        desired = np.asarray(desired_goal, dtype=np.float64)
        distance = np.linalg.norm(achieved - desired, axis=-1)
        if self.reward_type == "dense":
            return -distance
        return -(distance > self._threshold).astype(np.float64)

    def dict_observation(self, joints_deg, camera_mm, goal_mm):
        """The observation of joints θ1..θ3 (degrees), the camera's position and the goal
        point (mm): (3,) each, or (N, 3) each for N observations."""
        space = self.observation_space
        goal_box = space["achieved_goal"]
        state = np.concatenate([joints_deg, camera_mm], axis=-1)
        box = space["observation"]
        return {
            "observation": np.clip(state, box.low, box.high).astype(np.float32),
            "achieved_goal": np.clip(camera_mm, goal_box.low, goal_box.high).astype(np.float32),
            "desired_goal": np.clip(goal_mm, goal_box.low, goal_box.high).astype(np.float32),
        }

    def _observation(self, info):
        testbed = self._reach.testbed
        return self.dict_observation(info["joints_deg"], testbed.camera_mm, testbed.goal_mm)
