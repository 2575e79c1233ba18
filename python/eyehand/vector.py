"""The vector form of ``eyehand/Reach-v0``: N arms stepped in Rust in one call.

``gym.make_vec("eyehand/Reach-v0", num_envs=N, vectorization_mode="vector_entry_point",
threads=None, **kwargs)`` returns a ``ReachVectorEnv``: arm i behaves byte for byte as
``gym.make("eyehand/Reach-v0", seed=seed + i, **kwargs)`` (observations, rewards,
``terminated``, ``truncated`` and info), and ``reset(seed=s)`` resets arm i with seed
``s + i`` as ``SyncVectorEnv`` does. Autoreset is Gymnasium 1.x's next-step mode: the step
after an arm's episode ended resets that arm (its action ignored, reward 0, neither flag
set). ``threads`` (default: one per core for 256 arms or more, else one) splits the arms
among threads; the result does not depend on it.

``ReachGoalVectorEnv`` is the same for ``eyehand/ReachGoal-v0`` (Dict observations and
``compute_reward`` on batches).
"""

import os

import numpy as np
from gymnasium import spaces
from gymnasium.vector import AutoresetMode, VectorEnv
from gymnasium.vector.utils import batch_space

from ._eyehand import VecTestbed
from .env import MAX_MOVE_DEG, WORST_DISTANCE_MM, ReachEnv
from .goal import ReachGoalEnv

#: The fewest arms for which the default ``threads`` uses every core.
ARMS_FOR_THREADS = 256
#: Why an episode ended, by the engine's end code.
END_NAMES = np.array([None, "reached", "steps_used", "lost"], dtype=object)


class ReachVectorEnv(VectorEnv):
    """N arms of ``eyehand/Reach-v0`` stepped in Rust in one call."""

    metadata = {"render_modes": [], "autoreset_mode": AutoresetMode.NEXT_STEP}

    def __init__(
        self,
        num_envs=1,
        config=None,
        sim="kinematic",
        camera="projection",
        urdf=None,
        max_move_deg=MAX_MOVE_DEG,
        seed=1,
        threads=None,
        max_episode_steps=None,
        **entries,
    ):
        single = self._single_env(
            config=config, sim=sim, camera=camera, urdf=urdf,
            max_move_deg=max_move_deg, seed=seed, **entries,
        )
        feedback_steps = single.unwrapped.testbed.feedback_steps
        if max_episode_steps is not None and max_episode_steps < feedback_steps:
            raise ValueError(
                f"max_episode_steps={max_episode_steps} is shorter than the episodes "
                f"(feedback_steps={feedback_steps}): set feedback_steps={max_episode_steps} too"
            )
        self.num_envs = int(num_envs)
        if self.num_envs < 1:
            raise ValueError(f"num_envs must be at least 1, not {num_envs}")
        if threads is None:
            threads = (os.cpu_count() or 1) if self.num_envs >= ARMS_FOR_THREADS else 1
        if int(threads) < 1:
            raise ValueError(f"threads must be at least 1, not {threads}")
        self.single_observation_space = single.observation_space
        self.single_action_space = single.action_space
        self.observation_space = batch_space(self.single_observation_space, self.num_envs)
        self.action_space = batch_space(self.single_action_space, self.num_envs)
        self.max_move_deg = single.max_move_deg
        box = single.unwrapped._reach.observation_space if isinstance(single, ReachGoalEnv) \
            else single.observation_space
        self._arms = VecTestbed(
            self.num_envs,
            [float(m) for m in single.unwrapped.max_move_deg],
            [float(v) for v in box.low],
            [float(v) for v in box.high],
            -feedback_steps * WORST_DISTANCE_MM,
            config=None if config is None else str(config),
            sim=sim,
            camera=camera,
            seed=seed,
            urdf=None if urdf is None else str(urdf),
            threads=int(threads),
            **entries,
        )
        self._single = single

    def _single_env(self, **kwargs):
        """The single environment whose spaces and rules every arm shares."""
        return ReachEnv(**kwargs)

    def reset(self, *, seed=None, options=None):
        """Resets every arm (or those ``options["reset_mask"]`` picks): arm i from seed
        ``seed + i`` (an int), ``seed[i]`` (a list) or where its draws are (None)."""
        if seed is None:
            seeds = [None] * self.num_envs
        elif isinstance(seed, (int, np.integer)):
            super().reset(seed=int(seed))
            seeds = [int(seed) + i for i in range(self.num_envs)]
        else:
            seeds = [None if s is None else int(s) for s in seed]
            if len(seeds) != self.num_envs:
                raise ValueError(f"{len(seeds)} seeds for {self.num_envs} environments")
        mask = np.ones(self.num_envs, dtype=np.bool_)
        options = dict(options or {})
        if "reset_mask" in options:
            mask = np.asarray(options.pop("reset_mask"))
            if mask.shape != (self.num_envs,) or mask.dtype != np.bool_:
                raise ValueError(f"reset_mask must be a bool array of shape ({self.num_envs},)")
        if options:
            raise ValueError(f"unknown reset options: {sorted(options)}")
        batch = self._arms.reset(seeds, [bool(m) for m in mask])
        return self._observations(batch), self._infos(batch, mask)

    def step(self, actions):
        """Steps every arm with its action (an (N, 3) array)."""
        actions = np.ascontiguousarray(actions, dtype=np.float32)
        batch = self._arms.step(actions)
        obs, reward, terminated, truncated = batch[:4]
        everyone = np.ones(self.num_envs, dtype=np.bool_)
        return self._observations(batch), reward, terminated, truncated, self._infos(batch, everyone)

    def _observations(self, batch):
        """The batch's observations."""
        return batch[0]

    def _infos(self, batch, mask):
        """The info of each arm, as ``SyncVectorEnv`` gathers the single envs' infos."""
        _, _, _, _, end, distance, joints, seen = batch[:8]
        infos = {}
        for key, value in (
            ("distance_mm", distance),
            ("joints_deg", joints),
            ("seen", seen),
            ("end", END_NAMES[end]),
        ):
            infos[key], infos[f"_{key}"] = value, mask.copy()
        return infos

    def close_extras(self, **kwargs):
        """Stops the worker threads."""
        self._arms = None

    def action_for(self, move_deg):
        """The actions (N, 3) of the moves ``move_deg`` (N, 3, degrees), each scaled down
        as a whole where it passes the move bound, as ``ReachEnv.action_for`` does."""
        share = np.asarray(move_deg, dtype=np.float64) / self.max_move_deg
        largest = np.max(np.abs(share), axis=-1, keepdims=True)
        return (share / np.maximum(largest, 1.0)).astype(np.float32)


class ReachGoalVectorEnv(ReachVectorEnv):
    """N arms of ``eyehand/ReachGoal-v0`` stepped in Rust in one call."""

    def __init__(self, num_envs=1, distance_threshold_mm=None, reward_type="sparse", **kwargs):
        self._goal_kwargs = {"reward_type": reward_type}
        if distance_threshold_mm is not None:
            self._goal_kwargs["distance_threshold_mm"] = distance_threshold_mm
        super().__init__(num_envs, **kwargs)
        # Every arm's first step resets it: its reward is 0.
        self._ended = np.ones(self.num_envs, dtype=np.bool_)

    def _single_env(self, **kwargs):
        return ReachGoalEnv(**self._goal_kwargs, **kwargs)

    @property
    def distance_threshold_mm(self):
        """The sparse reward's success distance (mm)."""
        return self._single.distance_threshold_mm

    @distance_threshold_mm.setter
    def distance_threshold_mm(self, value):
        self._single.distance_threshold_mm = value

    def compute_reward(self, achieved_goal, desired_goal, info):
        """The reward of reaching ``achieved_goal`` for ``desired_goal`` ((B, 3) each)."""
        return self._single.compute_reward(achieved_goal, desired_goal, info)

    def reset(self, *, seed=None, options=None):
        mask = (options or {}).get("reset_mask")
        obs, infos = super().reset(seed=seed, options=options)
        self._ended[slice(None) if mask is None else mask] = False
        return obs, infos

    def step(self, actions):
        obs, _, terminated, truncated, infos = super().step(actions)
        reward = self.compute_reward(obs["achieved_goal"], obs["desired_goal"], infos)
        reward[self._ended] = 0.0
        self._ended = terminated | truncated
        return obs, reward, terminated, truncated, infos

    def _observations(self, batch):
        joints, camera, goal = batch[6], batch[8], batch[9]
        return self._single.dict_observation(joints, camera, goal)
