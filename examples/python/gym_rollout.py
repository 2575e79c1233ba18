"""Rollouts of ``eyehand/Reach-v0``: a random policy, then the built-in lin5 as the policy,
learning from every episode as the trial loop lets it.

    python examples/python/gym_rollout.py [EPISODES]
"""

import sys

import gymnasium as gym
import numpy as np

import eyehand


def rollout(env, policy, episodes, learner=None):
    """Mean final distance (mm), reach rate and mean steps over ``episodes`` episodes."""
    finals, reached, steps = [], 0, []
    for episode in range(episodes):
        obs, info = env.reset(seed=episode if episode == 0 else None)
        for step in range(1, 1000):
            obs, reward, terminated, truncated, info = env.step(policy(obs))
            if terminated or truncated:
                break
        finals.append(info["distance_mm"])
        reached += terminated
        steps.append(step)
        if learner is not None:
            env.unwrapped.learn(learner)
    return np.mean(finals), reached / episodes, np.mean(steps)


def main():
    episodes = int(sys.argv[1]) if len(sys.argv) > 1 else 2000
    print("| policy | episodes | mean final distance (mm) | reached ε | mean steps |")
    print("|---|---|---|---|---|")
    env = gym.make("eyehand/Reach-v0")
    env.action_space.seed(1)
    result = rollout(env, lambda obs: env.action_space.sample(), episodes)
    print("| random | {} | {:.1f} | {:.1%} | {:.2f} |".format(episodes, *result))
    env = gym.make("eyehand/Reach-v0", max_move_deg=180.0)
    lin5 = eyehand.Learner("lin5")
    env.unwrapped.prelearn(lin5)
    policy = lambda obs: env.unwrapped.action_for(lin5.propose(obs))  # noqa: E731
    result = rollout(env, policy, episodes, learner=lin5)
    print("| lin5, learning as it goes | {} | {:.1f} | {:.1%} | {:.2f} |".format(episodes, *result))


if __name__ == "__main__":
    main()
