"""The vector environments: N arms stepped in Rust, byte for byte N single environments."""

import gymnasium as gym
import numpy as np
import pytest
from gymnasium.vector import AutoresetMode

import eyehand  # noqa: F401  (registers the environments)
from eyehand.vector import ReachGoalVectorEnv, ReachVectorEnv

#: Steps enough for several episodes an arm (10 steps at most each), so autoreset is met.
STEPS = 35


def single_envs(name, n, seed, **kwargs):
    """N single environments, arm i of seed ``seed + i`` as the vector env makes it."""
    return [gym.make(name, seed=seed + i, **kwargs).unwrapped for i in range(n)]


def rollout_single(envs, actions, reset_seed):
    """Steps single envs with next-step autoreset, as SyncVectorEnv does."""
    obs = [env.reset(seed=reset_seed + i)[0] for i, env in enumerate(envs)]
    records = [(obs, [0.0] * len(envs), [False] * len(envs), [False] * len(envs), None)]
    ended = [False] * len(envs)
    for action in actions:
        step = []
        for i, env in enumerate(envs):
            if ended[i]:
                ob, info = env.reset()
                step.append((ob, 0.0, False, False, info))
            else:
                step.append(env.step(action[i]))
        ended = [s[2] or s[3] for s in step]
        records.append(tuple(zip(*step)))
    return records


def random_actions(n, steps, seed):
    rng = np.random.default_rng(seed)
    return rng.uniform(-1.0, 1.0, size=(steps, n, 3)).astype(np.float32)


@pytest.mark.parametrize("threads", [1, 2])
def test_the_vector_env_is_n_single_envs_byte_for_byte_autoreset_included(threads):
    n, seed = 5, 40
    vec = gym.make_vec("eyehand/Reach-v0", num_envs=n, vectorization_mode="vector_entry_point",
                       seed=seed, threads=threads)
    assert isinstance(vec, ReachVectorEnv)
    assert vec.metadata["autoreset_mode"] == AutoresetMode.NEXT_STEP
    actions = random_actions(n, STEPS, seed=7)
    expected = rollout_single(single_envs("eyehand/Reach-v0", n, seed), actions, reset_seed=100)
    obs, info = vec.reset(seed=100)
    assert obs.dtype == np.float32 and obs.shape == (n, 5)
    assert np.array_equal(obs, np.stack(expected[0][0]))
    resets = 0
    for t, action in enumerate(actions, start=1):
        obs, reward, terminated, truncated, info = vec.step(action)
        want_obs, want_reward, want_term, want_trunc, want_info = expected[t]
        assert obs.tobytes() == np.stack(want_obs).tobytes(), f"step {t}"
        assert reward.tobytes() == np.array(want_reward, dtype=np.float64).tobytes(), f"step {t}"
        assert list(terminated) == list(want_term) and list(truncated) == list(want_trunc)
        assert list(info["end"]) == [i["end"] for i in want_info]
        assert np.array_equal(info["distance_mm"], [i["distance_mm"] for i in want_info])
        assert np.array_equal(info["joints_deg"], np.stack([i["joints_deg"] for i in want_info]))
        assert list(info["seen"]) == [i["seen"] for i in want_info]
        resets += sum(r == 0.0 for r in want_reward)
    assert resets >= 2 * n, "every arm was autoreset more than once"
    assert vec.observation_space.contains(obs)


def test_the_vector_env_matches_sync_vector_env():
    n = 3
    vec = gym.make_vec("eyehand/Reach-v0", num_envs=n, vectorization_mode="vector_entry_point")
    sync = gym.vector.SyncVectorEnv(
        [lambda i=i: gym.make("eyehand/Reach-v0", seed=1 + i) for i in range(n)]
    )
    a, _ = vec.reset(seed=5)
    b, _ = sync.reset(seed=5)
    assert np.array_equal(a, b)
    for action in random_actions(n, 25, seed=3):
        a = vec.step(action)
        b = sync.step(action)
        for x, y in zip(a[:4], b[:4]):
            assert np.array_equal(x, y)
        assert np.array_equal(a[4]["distance_mm"], b[4]["distance_mm"])


def test_a_reset_mask_resets_only_the_arms_it_picks():
    vec = ReachVectorEnv(num_envs=3)
    first, _ = vec.reset(seed=2)
    moved, *_ = vec.step(np.full((3, 3), 0.3, dtype=np.float32))
    mask = np.array([False, True, False])
    obs, info = vec.reset(seed=2, options={"reset_mask": mask})
    assert np.array_equal(obs[1], first[1]), "arm 1 starts again from seed 3"
    assert np.array_equal(obs[[0, 2]], moved[[0, 2]]), "the others go on"
    assert list(info["_end"]) == list(mask)


def test_bad_actions_and_arguments_are_refused_before_stepping():
    vec = ReachVectorEnv(num_envs=2)
    vec.reset(seed=1)
    with pytest.raises(ValueError, match="shape"):
        vec.step(np.zeros((3, 3), dtype=np.float32))
    with pytest.raises(ValueError, match="finite"):
        vec.step(np.array([[0.0, np.nan, 0.0], [0.0, 0.0, 0.0]], dtype=np.float32))
    with pytest.raises(ValueError, match="num_envs"):
        ReachVectorEnv(num_envs=0)
    with pytest.raises(ValueError, match="unknown reset options"):
        vec.reset(options={"camera": "raycast"})


def test_the_goal_vector_env_is_n_single_goal_envs():
    n, seed = 4, 11
    vec = gym.make_vec("eyehand/ReachGoal-v0", num_envs=n,
                       vectorization_mode="vector_entry_point", seed=seed, threads=2)
    assert isinstance(vec, ReachGoalVectorEnv)
    actions = random_actions(n, STEPS, seed=9)
    expected = rollout_single(single_envs("eyehand/ReachGoal-v0", n, seed), actions, reset_seed=0)
    obs, _ = vec.reset(seed=0)
    for t, action in enumerate(actions, start=1):
        obs, reward, terminated, truncated, _ = vec.step(action)
        want_obs, want_reward, want_term, want_trunc, _ = expected[t]
        for key in ("observation", "achieved_goal", "desired_goal"):
            assert obs[key].tobytes() == np.stack([o[key] for o in want_obs]).tobytes()
        assert np.array_equal(reward, want_reward), f"step {t}"
        assert list(terminated) == list(want_term) and list(truncated) == list(want_trunc)
    assert vec.observation_space.contains(obs)
