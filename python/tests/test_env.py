"""The Gymnasium environment eyehand/Reach-v0."""

import warnings

import gymnasium as gym
import numpy as np
import pytest
from gymnasium.utils.env_checker import check_env

import eyehand
from eyehand.env import WORST_DISTANCE_MM


def test_check_env_passes_without_a_warning():
    env = gym.make("eyehand/Reach-v0")
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        check_env(env.unwrapped)


def test_actions_are_shares_of_the_move_bound_clipped_to_one():
    env = gym.make("eyehand/Reach-v0", max_move_deg=[1.0, 2.0, 3.0]).unwrapped
    assert env.action_space.dtype == np.float32
    assert np.array_equal(env.action_space.low, [-1.0] * 3)
    assert np.array_equal(env.action_space.high, [1.0] * 3)
    env.reset(seed=3)
    before = env.testbed.path[-1, 3:]
    _, _, _, _, info = env.step(np.array([50.0, -50.0, 0.5], dtype=np.float32))
    assert np.allclose(info["joints_deg"] - before, [1.0, -2.0, 1.5])
    assert np.allclose(env.action_for([0.5, -1.0, 3.0]), [0.5, -0.5, 1.0])
    assert np.allclose(env.action_for([0.5, -4.0, 3.0]), [0.25, -1.0, 0.5]), "direction kept"
    with pytest.raises(ValueError, match="max_move_deg"):
        gym.make("eyehand/Reach-v0", max_move_deg=0.0)


def test_the_spaces_are_the_learners_view_with_finite_bounds():
    env = gym.make("eyehand/Reach-v0").unwrapped
    assert env.observation_space.shape == (5,) and env.action_space.shape == (3,)
    assert env.observation_space.dtype == np.float32
    assert np.all(np.isfinite(env.observation_space.low))
    assert np.all(np.isfinite(env.observation_space.high))
    obs, info = env.reset(seed=4)
    assert env.observation_space.contains(obs)
    assert info["seen"] and info["distance_mm"] > 0


def test_the_default_move_bound_lets_ik_reach_every_target_in_the_step_budget():
    env = gym.make("eyehand/Reach-v0").unwrapped
    ik = eyehand.Learner("ik")
    for episode in range(40):
        obs, _ = env.reset(seed=100 + episode)
        terminated = truncated = False
        while not (terminated or truncated):
            obs, _, terminated, truncated, info = env.step(env.action_for(ik.propose(obs)))
        assert terminated, f"episode {episode}: {info}"


def test_reset_with_a_seed_is_reproducible():
    env = gym.make("eyehand/Reach-v0").unwrapped
    first = [env.reset(seed=9)[0], env.reset()[0]]
    again, _ = env.reset(seed=9)
    other, _ = env.reset(seed=10)
    assert np.array_equal(first[0], again) and not np.array_equal(first[0], first[1])
    assert not np.array_equal(again, other)


def test_reward_terminated_and_truncated_follow_the_trial():
    env = gym.make("eyehand/Reach-v0", max_move_deg=180.0).unwrapped
    ik = eyehand.Learner("ik")
    obs, _ = env.reset(seed=2)
    for step in range(1, 6):
        obs, reward, terminated, truncated, info = env.step(env.action_for(ik.propose(obs)))
        assert reward == -info["distance_mm"] and info["seen"]
        assert terminated == (step == 5), "ε is reached, but only after min_feedback_steps"
        assert not truncated
    obs, _ = env.reset()
    for step in range(1, 11):
        obs, reward, terminated, truncated, info = env.step(np.zeros(3))
        assert not terminated and truncated == (step == 10)


def test_losing_the_object_truncates_with_a_return_below_any_kept_episode():
    env = gym.make("eyehand/Reach-v0", max_move_deg=90.0).unwrapped
    obs, _ = env.reset(seed=5)
    after, reward, terminated, truncated, info = env.step(np.array([1.0, 0.0, 0.0]))
    assert truncated and not terminated and not info["seen"] and info["end"] == "lost"
    assert np.array_equal(after, obs), "the observation repeats the last one seen"
    # The worst a whole episode that keeps the object in view can collect.
    assert reward <= -env.testbed.feedback_steps * WORST_DISTANCE_MM
    obs, _ = env.reset(seed=5)
    kept = 0.0
    for _ in range(env.testbed.feedback_steps):
        obs, step_reward, terminated, truncated, info = env.step(np.zeros(3, dtype=np.float32))
        kept += step_reward
    assert info["end"] == "steps_used" and kept > reward


def test_options_select_camera_and_events():
    env = gym.make("eyehand/Reach-v0", max_move_deg=180.0).unwrapped
    ik = eyehand.Learner("ik")
    obs, _ = env.reset(seed=1, options={"camera": "raycast", "events": ["rotate:2:30"]})
    _, _, _, _, info = env.step(env.action_for(ik.propose(obs)))
    assert info["distance_mm"] < 5.0, "the nominal robot: ik reaches the target"
    obs, _ = env.reset()
    _, _, _, _, info = env.step(env.action_for(ik.propose(obs)))
    assert info["distance_mm"] > 5.0, "after the camera turn ik misses"
    with pytest.raises(ValueError, match="bad event"):
        env.reset(options={"events": ["spin:1:2"]})
