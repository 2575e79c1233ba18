"""The goal-conditioned environment eyehand/ReachGoal-v0."""

import warnings

import gymnasium as gym
import numpy as np
import pytest
from gymnasium.utils.env_checker import check_env

import eyehand


def test_check_env_passes_without_a_warning():
    env = gym.make("eyehand/ReachGoal-v0")
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        check_env(env.unwrapped)


def test_both_envs_are_registered_with_their_episode_length():
    for name in ("eyehand/Reach-v0", "eyehand/ReachGoal-v0"):
        env = gym.make(name)
        assert env.spec.max_episode_steps == eyehand.MAX_EPISODE_STEPS
        assert env.unwrapped.testbed.feedback_steps == eyehand.MAX_EPISODE_STEPS


def test_the_goals_are_the_camera_and_the_goal_point():
    env = gym.make("eyehand/ReachGoal-v0", max_move_deg=180.0).unwrapped
    ik = eyehand.Learner("ik")
    obs, info = env.reset(seed=3)
    distance = np.linalg.norm(obs["achieved_goal"] - obs["desired_goal"])
    assert distance == pytest.approx(info["distance_mm"], abs=0.01)
    assert np.allclose(obs["observation"][:3], info["joints_deg"], atol=1e-4)
    assert np.array_equal(obs["observation"][3:], obs["achieved_goal"])
    goal = obs["desired_goal"].copy()
    query = env.testbed.observation
    obs, reward, terminated, truncated, info = env.step(env.action_for(ik.propose(query)))
    assert np.array_equal(obs["desired_goal"], goal), "the goal stays through the episode"
    assert info["distance_mm"] < 5.0 and reward == 0.0, "within 5 cm: the sparse reward is 0"


def test_compute_reward_on_batches_agrees_with_step():
    env = gym.make("eyehand/ReachGoal-v0").unwrapped
    rng = np.random.default_rng(5)
    achieved, desired, infos, rewards = [], [], [], []
    for episode in range(6):
        obs, _ = env.reset(seed=episode)
        done = False
        while not done:
            obs, reward, terminated, truncated, info = env.step(
                rng.uniform(-0.3, 0.3, size=3).astype(np.float32)
            )
            achieved.append(obs["achieved_goal"])
            desired.append(obs["desired_goal"])
            infos.append(info)
            rewards.append(reward)
            done = terminated or truncated
    achieved, desired = np.stack(achieved), np.stack(desired)
    for threshold in (50.0, 200.0, 400.0):
        env.distance_threshold_mm = threshold
        batch = env.compute_reward(achieved, desired, np.array(infos))
        assert batch.shape == (len(infos),)
        distance = np.linalg.norm(achieved.astype(np.float64) - desired, axis=1)
        assert np.array_equal(batch, -(distance > threshold).astype(np.float64))
    env.distance_threshold_mm = 50.0
    assert np.array_equal(env.compute_reward(achieved, desired, infos), rewards)
    assert min(rewards) == -1.0, "random moves stay beyond 5 cm somewhere"
    # A goal relabelled to the one achieved (HER's "final" and "future" goals) pays 0.
    assert np.array_equal(env.compute_reward(achieved, achieved, infos), np.zeros(len(infos)))
    dense = gym.make("eyehand/ReachGoal-v0", reward_type="dense").unwrapped
    assert np.allclose(dense.compute_reward(achieved, desired, infos), -distance)
    with pytest.raises(ValueError, match="reward_type"):
        gym.make("eyehand/ReachGoal-v0", reward_type="shaped")
    with pytest.raises(ValueError, match="distance_threshold_mm"):
        env.distance_threshold_mm = -1.0


def test_step_reward_is_the_dense_distance_when_asked():
    env = gym.make("eyehand/ReachGoal-v0", reward_type="dense").unwrapped
    obs, _ = env.reset(seed=8)
    obs, reward, *_ = env.step(np.array([0.2, -0.1, 0.1], dtype=np.float32))
    expected = -np.linalg.norm(obs["achieved_goal"].astype(np.float64) - obs["desired_goal"])
    assert reward == expected
