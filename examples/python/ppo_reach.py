"""Trains stable-baselines3's PPO on ``eyehand/Reach-v0`` and prints its learning curve:
after every ``EVERY`` steps, the median final distance and the share of lost episodes over
``EPISODES`` evaluation episodes of the deterministic policy (seeded, the same each time).

    pip install stable-baselines3          # brings torch: large, so not part of the tests
    python examples/python/ppo_reach.py [STEPS] [EVERY]     # default 200000, 20000

The evaluation environment is a second one with seeds of its own; training steps are the
environment's steps (feedback moves), not episodes.
"""

import sys

import gymnasium as gym
import numpy as np
from stable_baselines3 import PPO

import eyehand  # noqa: F401  (registers the environment)

#: Evaluation episodes at each point of the curve, and their first seed.
EPISODES = 200
EVAL_SEED = 10_000


def evaluate(model, env):
    """Median final distance (mm) and the share of lost episodes of the deterministic
    policy over ``EPISODES`` seeded episodes."""
    finals, lost = [], 0
    for episode in range(EPISODES):
        obs, info = env.reset(seed=EVAL_SEED + episode)
        done = False
        while not done:
            action, _ = model.predict(obs, deterministic=True)
            obs, _, terminated, truncated, info = env.step(action)
            done = terminated or truncated
        finals.append(info["distance_mm"])
        lost += info["end"] == "lost"
    return float(np.median(finals)), lost / EPISODES


def main():
    steps = int(sys.argv[1]) if len(sys.argv) > 1 else 200_000
    every = int(sys.argv[2]) if len(sys.argv) > 2 else 20_000
    train = gym.make("eyehand/Reach-v0", seed=1)
    evaluation = gym.make("eyehand/Reach-v0", seed=2)
    model = PPO("MlpPolicy", train, seed=1, verbose=0)
    print("| steps | median final distance (mm) | lost |")
    print("|---|---|---|")
    median, lost = evaluate(model, evaluation)
    print(f"| 0 | {median:.1f} | {lost:.1%} |", flush=True)
    for done in range(every, steps + 1, every):
        model.learn(total_timesteps=every, reset_num_timesteps=False)
        median, lost = evaluate(model, evaluation)
        print(f"| {done:,} | {median:.1f} | {lost:.1%} |", flush=True)


if __name__ == "__main__":
    main()
