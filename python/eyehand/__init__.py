"""eyehand from Python: the OSCAR-6 testbed, its built-in learners and runs, and the
Gymnasium environments ``eyehand/Reach-v0`` and ``eyehand/ReachGoal-v0`` (each with a vector
form stepped in Rust, ``eyehand.vector``) — all on the Rust engine the ``eyehand`` command
line uses.

- ``Testbed``: a trial driven one feedback step at a time (``reset``, ``step``, ``learn``,
  ``prelearn``, ``stretch_link``, ``rotate_camera``, ``fk``).
- ``Learner``: a built-in learner (any method ``eyehand run --method`` takes) with
  ``propose(query)`` and ``learn(path)``.
- ``patterns``: a path's learning patterns as the built-in learners form them;
  ``Patterns`` the same by name, and ``Query`` a query by name (``INPUTS``, ``INPUT_UNITS``,
  ``TARGETS`` name their columns; ``input_bounds`` gives a config's boundaries in that order).
- ``run``: a whole run of a built-in or a Python learner, writing the run folder
  ``eyehand run`` writes.

A query (and the environment's observation) is (cx, cy, cz, θ2, θ3); a path is an (n, 6)
array of poses (cx, cy, cz, θ1, θ2, θ3); moves are (Δθ1, Δθ2, Δθ3) in degrees. A learner
that sets ``eyehand_api = 2`` gets named inputs instead: ``propose(query)`` an
``eyehand.Query`` and ``learn(patterns)`` an ``eyehand.Patterns``, whose five inputs come in
the order of ``INPUTS`` — (θ2, θ3, cx, cy, cz), the order of the config's boundaries 0–4.
"""

import json
import pathlib
import warnings

import numpy as np

from ._eyehand import (
    ENTRY_NAMES,
    INPUT_UNITS,
    INPUTS,
    TARGETS,
    Learner,
    Patterns,
    Query,
    Testbed,
    patterns,
)
from ._eyehand import run as _run

__all__ = [
    "ENTRY_NAMES",
    "INPUTS",
    "INPUT_UNITS",
    "TARGETS",
    "Learner",
    "NotLearnedWarning",
    "Patterns",
    "Query",
    "Testbed",
    "input_bounds",
    "patterns",
    "run",
    "RECORDED_STEPS",
    "MAX_EPISODE_STEPS",
]

#: The registered environments' episode length: the default ``feedback_steps`` (pass
#: ``max_episode_steps`` to ``gym.make`` with another ``feedback_steps``).
MAX_EPISODE_STEPS = 10

#: Distances after feedback steps 1..RECORDED_STEPS are written to ``1step`` … ``5step``.
RECORDED_STEPS = 5


class NotLearnedWarning(RuntimeWarning):
    """A run that learned nothing (``summary["learned"]`` false; where ``eyehand run``
    exits 1): every trial failed, no trial gave the learner a pattern, or the arm stayed at
    its start pose through the window — a learner that answers zero moves, say."""


def run(
    learner=None,
    *,
    method=None,
    trials=None,
    config=None,
    data="data",
    seed=None,
    sim=None,
    camera=None,
    urdf=None,
    events=(),
    plot=False,
    **entries,
):
    """Runs every trial of a run and returns what it wrote.

    ``learner`` is any object with ``propose(query) -> (3,)`` and ``learn(path)`` (its
    ``name`` attribute, or its class name, names its folder); without it the built-in
    ``method`` (default: the config's) runs. With ``eyehand_api = 2`` on the learner,
    ``propose`` gets an ``eyehand.Query`` and ``learn`` an ``eyehand.Patterns`` (formed
    with the run's ``minimal_joint_move``) instead of arrays. A ``setup(config)`` it
    defines is called once before pre-learning with the run's resolved config, a dict of
    every entry by name (ints, floats, tuples of floats, lists for repeated entries,
    strings). A ``size()`` it defines (a count of its nodes, fields or units) is its
    ``nodes`` figure: in summary.json, the report and the ``nodes`` file.

    ``config`` is a config file (default: none, every entry at its default); keyword
    ``entries`` override its entries as ``--set`` does; ``events`` are
    ``rotate:TRIAL:DEG`` / ``elongate:TRIAL:LINK:CM`` strings.

    Returns a dict: ``folder`` (a ``pathlib.Path``), ``summary`` (summary.json as a dict),
    ``report`` (the summary as ``eyehand run`` prints it), ``learned`` (false for a run that
    learned nothing, which also warns with ``NotLearnedWarning`` and the reason
    ``summary["not_learned"]`` gives), ``trials`` and ``distances_mm``: for each feedback
    step 1..5, NumPy arrays of the trials that took that step and the distance to the
    target (mm) after it.

    The GIL is released while Rust runs (a Python learner takes it back for its calls).
    A Python learner's exception — or a non-finite move, as ``ValueError`` — stops the run
    and is raised here; the run folder keeps the data files written so far.
    """
    folder, summary, report = _run(
        learner,
        method=method,
        trials=trials,
        config=None if config is None else str(config),
        data=str(data),
        seed=seed,
        sim=sim,
        camera=camera,
        urdf=None if urdf is None else str(urdf),
        events=list(events),
        plot=plot,
        **entries,
    )
    folder = pathlib.Path(folder)
    summary = json.loads(summary)
    if not summary["learned"]:
        reason = summary["not_learned"]["reason"]
        message = f"nothing was learned: {reason} ({folder})"
        warnings.warn(message, NotLearnedWarning, stacklevel=2)
    steps = [_read_step_file(folder / f"{k}step") for k in range(1, RECORDED_STEPS + 1)]
    return {
        "folder": folder,
        "summary": summary,
        "report": report,
        "learned": summary["learned"],
        "trials": [trials for trials, _ in steps],
        "distances_mm": [distances for _, distances in steps],
    }


def input_bounds(config):
    """The boundaries of the five inputs in a config dict (as a learner's ``setup`` gets
    it): ``(low, high)``, two (5,) arrays in the order of ``INPUTS`` (θ2 °, θ3 °, cx px,
    cy px, cz) — ``boundary_0`` … ``boundary_4``."""
    low = np.array([float(config[f"boundary_{i}_low"]) for i in range(len(INPUTS))])
    high = np.array([float(config[f"boundary_{i}_high"]) for i in range(len(INPUTS))])
    return low, high


def _read_step_file(path):
    """The trial and distance columns of a ``Nstep`` file (the minutes column dropped)."""
    if path.stat().st_size == 0:
        return np.zeros(0, dtype=np.int64), np.zeros(0)
    table = np.loadtxt(path, ndmin=2)
    return table[:, 0].astype(np.int64), table[:, 1]


def _register_environment():
    from gymnasium.envs.registration import register, registry

    for name, env, vector in (
        ("eyehand/Reach-v0", "ReachEnv", "ReachVectorEnv"),
        ("eyehand/ReachGoal-v0", "ReachGoalEnv", "ReachGoalVectorEnv"),
    ):
        if name not in registry:
            register(
                id=name,
                entry_point=f"eyehand.env:{env}" if env == "ReachEnv" else f"eyehand.goal:{env}",
                vector_entry_point=f"eyehand.vector:{vector}",
                max_episode_steps=MAX_EPISODE_STEPS,
            )


_register_environment()
