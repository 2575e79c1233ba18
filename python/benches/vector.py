"""Env-steps per second of eyehand/Reach-v0: the single env, SyncVectorEnv of single envs and
the vector env stepped in Rust at N arms, under a random policy (actions drawn beforehand,
seed 1), kinematic simulator and projection camera at their defaults. An env-step is one
arm's step (autoresets included, as the vector env counts them).

    python python/benches/vector.py [SECONDS]      # each row runs about SECONDS (default 3)
"""

import sys
import time

import gymnasium as gym
import numpy as np

import eyehand  # noqa: F401  (registers the environments)

#: Distinct action batches cycled through (drawn once, so drawing costs nothing).
BATCHES = 64


def actions(shape, seed=1):
    rng = np.random.default_rng(seed)
    return rng.uniform(-1.0, 1.0, size=(BATCHES, *shape)).astype(np.float32)


def rate(step, arms, seconds):
    """Env-steps per second of ``step(k)`` (one call steps ``arms`` arms)."""
    calls, start = 0, time.perf_counter()
    while (elapsed := time.perf_counter() - start) < seconds:
        for _ in range(max(1, 4096 // arms)):
            step(calls)
            calls += 1
    return calls * arms / elapsed


def single(seconds):
    env = gym.make("eyehand/Reach-v0")
    env.reset(seed=1)
    batch = actions((3,))

    def step(k):
        _, _, terminated, truncated, _ = env.step(batch[k % BATCHES])
        if terminated or truncated:
            env.reset()

    return rate(step, 1, seconds)


def sync(n, seconds):
    env = gym.make_vec("eyehand/Reach-v0", num_envs=n, vectorization_mode="sync")
    env.reset(seed=1)
    batch = actions((n, 3))
    return rate(lambda k: env.step(batch[k % BATCHES]), n, seconds)


def vector(n, seconds, threads=None):
    env = gym.make_vec("eyehand/Reach-v0", num_envs=n, vectorization_mode="vector_entry_point",
                       threads=threads)
    env.reset(seed=1)
    batch = actions((n, 3))
    return rate(lambda k: env.step(batch[k % BATCHES]), n, seconds)


def main():
    seconds = float(sys.argv[1]) if len(sys.argv) > 1 else 3.0
    rows = [("gym.make, one env", 1, single(seconds))]
    rows.append(("SyncVectorEnv", 16, sync(16, seconds)))
    for n in (1, 16, 256, 4096):
        rows.append(("vector env, 1 thread", n, vector(n, seconds, threads=1)))
        if n >= 16:
            rows.append(("vector env, default threads", n, vector(n, seconds)))
    print("| env | arms | env-steps/s |")
    print("|---|---|---|")
    for name, n, value in rows:
        print(f"| {name} | {n} | {value:,.0f} |")


if __name__ == "__main__":
    main()
