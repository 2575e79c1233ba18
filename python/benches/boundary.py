"""The cost of the Python boundary: feedback steps per second of ``Testbed.step`` and of the
Gymnasium environment driven from Python, and trials per second of ``eyehand.run`` with a
trivial Python learner, on the kinematic simulator (configs/ik.conf). The Rust side of the
same loops: ``cargo bench --bench trial_steps``. Prints the table of docs/PYTHON.md.

    python python/benches/boundary.py [TRIALS]     # default 20,000 trials a row, seed 1
"""

import pathlib
import sys
import tempfile
import time

import gymnasium as gym
import numpy as np

import eyehand

REPO = pathlib.Path(__file__).resolve().parents[2]
CONFIG = REPO / "configs" / "ik.conf"
SEED = 1


class StandStill:
    """Proposes no move and learns nothing: the boundary's own cost."""

    name = "standstill"
    zero = np.zeros(3)

    def propose(self, query):
        return self.zero

    def learn(self, path):
        pass


def testbed_steps(trials, policy):
    """Feedback steps and seconds of ``trials`` trials of ``Testbed.step`` under ``policy``."""
    testbed = eyehand.Testbed(config=CONFIG, seed=SEED)
    steps = 0
    started = time.perf_counter()
    for _ in range(trials):
        obs = testbed.reset()
        while not testbed.done:
            testbed.step(policy(obs))
            obs = testbed.observation
            steps += 1
    return steps, time.perf_counter() - started


def env_steps(trials):
    """Steps and seconds of ``trials`` episodes of eyehand/Reach-v0 with a zero action."""
    env = gym.make("eyehand/Reach-v0", config=CONFIG)
    action = np.zeros(3)
    steps = 0
    started = time.perf_counter()
    env.reset(seed=SEED)
    for _ in range(trials):
        while True:
            _, _, terminated, truncated, _ = env.step(action)
            steps += 1
            if terminated or truncated:
                break
        env.reset()
    return steps, time.perf_counter() - started


def main():
    trials = int(sys.argv[1]) if len(sys.argv) > 1 else 20_000
    ik = eyehand.Learner("ik")
    zero = np.zeros(3)
    print("| Python (kinematic, configs/ik.conf) | steps/s | trials/s |")
    print("|---|---|---|")
    for label, policy in [("Testbed.step, ik (eyehand.Learner)", ik.propose),
                          ("Testbed.step, no move", lambda obs: zero)]:
        steps, seconds = testbed_steps(trials, policy)
        print(f"| {label} | {steps / seconds:.0f} | {trials / seconds:.0f} |")
    steps, seconds = env_steps(trials)
    print(f"| gym.make('eyehand/Reach-v0').step, no move | {steps / seconds:.0f} | {trials / seconds:.0f} |")
    with tempfile.TemporaryDirectory() as data:
        result = eyehand.run(StandStill(), trials=trials, seed=SEED, config=CONFIG, data=data)
    print(f"| eyehand.run, Python learner, no move (files written) | - "
          f"| {result['summary']['trials_per_second']:.0f} |")
    print(f"\n{trials} trials a row, seed {SEED}")


if __name__ == "__main__":
    main()
