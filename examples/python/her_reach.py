"""Trains stable-baselines3's SAC (or sb3-contrib's TQC) with Hindsight Experience Replay on
``eyehand/ReachGoal-v0`` and prints its learning curve: after every ``EVERY`` environment
steps, the share of ``EPISODES`` seeded evaluation episodes of the deterministic policy
that end within 5 cm, 1 cm and 1 mm of the goal (the distance after the episode's last
step).

    pip install stable-baselines3 sb3-contrib       # brings torch: large, so not in the tests
    python examples/python/her_reach.py [STEPS] [EVERY] [SEED] [ALGO]
                                        # default 20000 5000 1 tqc; ALGO tqc, sac or lin5

``lin5`` runs the built-in learner on the testbed of the same seed instead, for comparison.

Training uses the sparse reward at 5 cm (FetchReach's), HER's ``future`` goals (4 a
transition) and the rl-baselines3-zoo's TQC setting for FetchReach (two layers of 64 units,
one critic, learning rate 1e-3, batch 256, buffer 1,000,000, γ 0.95, 1,000 random steps
first, observations normalised by ``VecNormalize``; the zoo's time feature is left out, as
an episode's step count is no part of this task). Training steps are the environment's
steps (feedback moves), not episodes; ``torch`` runs on one thread.
"""

import sys

import gymnasium as gym
import numpy as np
import torch
from stable_baselines3 import SAC, HerReplayBuffer
from stable_baselines3.common.vec_env import DummyVecEnv, VecNormalize

import eyehand  # noqa: F401  (registers the environments)

#: Evaluation episodes at each point of the curve, and their first seed.
EPISODES = 100
EVAL_SEED = 10_000
#: The success distances reported (mm).
DISTANCES_MM = (50.0, 10.0, 1.0)


def evaluate(model, normalise, env):
    """The share of the ``EPISODES`` seeded episodes of the deterministic policy that end
    within each of ``DISTANCES_MM``, and the median final distance."""
    finals = []
    for episode in range(EPISODES):
        obs, info = env.reset(seed=EVAL_SEED + episode)
        done = False
        while not done:
            action, _ = model.predict(normalise.normalize_obs(obs), deterministic=True)
            obs, _, terminated, truncated, info = env.step(action)
            done = terminated or truncated
        finals.append(info["distance_mm"])
    finals = np.array(finals)
    return [float(np.mean(finals <= d)) for d in DISTANCES_MM], float(np.median(finals))


def make_model(algo, env, seed):
    """SAC or TQC with HER, at the zoo's FetchReach settings."""
    settings = dict(
        replay_buffer_class=HerReplayBuffer,
        replay_buffer_kwargs=dict(n_sampled_goal=4, goal_selection_strategy="future"),
        buffer_size=1_000_000,
        batch_size=256,
        gamma=0.95,
        learning_rate=1e-3,
        learning_starts=1000,
        seed=seed,
        verbose=0,
    )
    if algo == "tqc":
        from sb3_contrib import TQC

        policy = dict(net_arch=[64, 64], n_critics=1)
        return TQC("MultiInputPolicy", env, policy_kwargs=policy, **settings)
    if algo == "sac":
        return SAC("MultiInputPolicy", env, policy_kwargs=dict(net_arch=[64, 64]), **settings)
    raise SystemExit(f"ALGO must be sac or tqc, not {algo}")


def rl_curve(algo, steps, every, seed):
    """(steps, shares, median) after every ``every`` training steps of SAC or TQC + HER."""
    torch.set_num_threads(1)
    single = DummyVecEnv([lambda: gym.make("eyehand/ReachGoal-v0", seed=seed)])
    train = VecNormalize(single, norm_obs=True, norm_reward=False)
    evaluation = gym.make("eyehand/ReachGoal-v0", seed=seed + 1000)
    model = make_model(algo, train, seed)
    for done in range(0, steps + 1, every):
        if done:
            model.learn(total_timesteps=every, reset_num_timesteps=False)
        yield (done, *evaluate(model, train, evaluation))


def lin5_curve(steps, every, seed):
    """The same for lin5 on the testbed of the same seed, learning after every episode as a
    run does (its 8 pre-learning moves counted as steps; its moves unbounded), evaluated on
    the same episodes without learning."""
    lin5 = eyehand.Learner("lin5")
    train = eyehand.Testbed(seed=seed)
    evaluation = eyehand.Testbed(seed=seed + 1000)
    train.prelearn(lin5)
    taken = 8
    for done in range(0, steps + 1, every):
        while taken < done:
            obs = train.reset()
            while not train.done:
                train.step(lin5.propose(obs))
                obs = train.observation
            taken += train.steps
            train.learn(lin5)
        finals = []
        for episode in range(EPISODES):
            obs = evaluation.reset(seed=EVAL_SEED + episode)
            while not evaluation.done:
                evaluation.step(lin5.propose(obs))
                obs = evaluation.observation
            finals.append(evaluation.distance_mm)
        finals = np.array(finals)
        yield done, [float(np.mean(finals <= d)) for d in DISTANCES_MM], float(np.median(finals))


def main():
    steps = int(sys.argv[1]) if len(sys.argv) > 1 else 20_000
    every = int(sys.argv[2]) if len(sys.argv) > 2 else 5_000
    seed = int(sys.argv[3]) if len(sys.argv) > 3 else 1
    algo = sys.argv[4] if len(sys.argv) > 4 else "tqc"
    if algo == "lin5":
        print(f"lin5, seed {seed}")
        curve = lin5_curve(steps, every, seed)
    else:
        print(f"{algo} + HER, seed {seed}")
        curve = rl_curve(algo, steps, every, seed)
    print("| steps | within 5 cm | within 1 cm | within 1 mm | median final distance (mm) |")
    print("|---|---|---|---|---|")
    for done, shares, median in curve:
        cells = " | ".join(f"{share:.0%}" for share in shares)
        print(f"| {done:,} | {cells} | {median:.1f} |", flush=True)


if __name__ == "__main__":
    main()
