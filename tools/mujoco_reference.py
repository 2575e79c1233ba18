#!/usr/bin/env python3
"""Reference dynamics of the OSCAR-6 from MuJoCo, for eyehand's dynamic simulator tests.

Loads urdf/oscar6.urdf into MuJoCo (its own URDF reader, contacts off, joint damping,
friction loss and armature zero, gravity 9.81 m/s² along -z) and writes into tests/data/:

  mujoco_accelerations.csv   joint accelerations from rest at 50 fixed poses
  mujoco_swing_N.csv         passive swings from 3 start poses (servos off, no joint
                             limits), RK4 at 0.1 ms for 1 s, a row every 10 ms
  mujoco_stretched.csv       the arm with link 2 10 cm longer, its mass properties scaled
                             as a uniform rod (see docs/DYNAMIC.md): holding torques
                             (gravity) and accelerations from rest at the same 50 poses
  mujoco_moves.csv           servoed moves: each move's number, start and goal (rad)
  mujoco_move_N.csv          move N driven by eyehand's servo law (src/robot/dynamic/
                             servo_law.rs) at its default settings: every 5 ms tick the
                             set-point of the trapezoidal profile (90°/s, 180°/s² for the
                             joint with the farthest to go) with its speed and acceleration,
                             the servo's accelerations s = [a* + k(x* - x - dt v) + c(v* - v)]
                             / (1 + k dt²/2 + c dt) made torques by MuJoCo's own mass
                             matrix, MuJoCo's gravity torques at the set-point fed forward,
                             each within the URDF effort, held over the tick (qfrc_applied)
                             while MuJoCo integrates RK4 at 0.1 ms; a row every tick

Needs `pip install mujoco numpy`; run from the repository root:
    python3 tools/mujoco_reference.py
The tests read the files; they never run this script.
"""

import pathlib
import re

import mujoco
import numpy as np

ROOT = pathlib.Path(__file__).resolve().parent.parent
OUT = ROOT / "tests" / "data"
SEED = 13
POSES = 50
SWING_STARTS = [
    [0.0, 0.0, 0.0, 0.0, 0.0, 0.0],
    [0.0, 0.6, 1.2, 0.0, 1.0, 0.0],
    [0.5, 0.3, 0.9, 0.0, 0.6, 0.0],
]
SWING_SECONDS = 1.0
SWING_DT = 1e-4
SWING_EVERY = 100  # steps between rows: 10 ms
STRETCH_LINK = "link_2"
STRETCH_JOINT = "joint_3"  # the joint at the link's far end
STRETCH_M = 0.10
TICK = 0.005  # eyehand's default dt
TICK_SUBSTEPS = 50  # MuJoCo steps of 0.1 ms per tick
STIFFNESS = 400_000.0  # motor_stiffness (1/s²)
DAMPING = 1265.0  # motor_damping (1/s)
SPEED = np.radians(90.0)  # robot_speed
ACCEL = np.radians(180.0)  # robot_accel
SETTLE_SECONDS = 0.5  # simulated after each move's profile
# Small, large, and onto joint 3's upper limit (2.967 rad), in degrees but the limit.
MOVES = [
    (np.radians([0, 30, 60, 0, 40, 0]), np.radians([2, 31, 58, 0, 41, 0])),
    (np.radians([-60, 10, 30, 0, 20, 0]), np.radians([70, 60, 110, 30, 80, -40])),
    (np.radians([20, 40, 100, 0, 30, 0]), np.array([*np.radians([25, 45]), 2.967, *np.radians([10, 60, 20])])),
]
MJCF_OPTIONS = (
    '<mujoco><compiler discardvisual="true" fusestatic="false" '
    'balanceinertia="false"/></mujoco>'
)


def with_mujoco_options(urdf: str) -> str:
    """The URDF with MuJoCo's compiler options inside <robot>."""
    return re.sub(r"(<robot[^>]*>)", r"\1" + MJCF_OPTIONS, urdf, count=1)


def stretched(urdf: str) -> str:
    """The URDF with STRETCH_LINK longer by STRETCH_M along its far joint's origin, its
    mass, centre of mass and inertia scaled as a uniform rod: mass by s = L'/L, every
    coordinate along the link by s, the second moments of mass by s·A·S·A."""
    joint = re.search(
        r'<joint name="%s".*?<origin xyz="([^"]+)"' % STRETCH_JOINT, urdf, re.S
    )
    far = np.array([float(v) for v in joint.group(1).split()])
    length = np.linalg.norm(far)
    d = far / length
    s = (length + STRETCH_M) / length
    urdf = urdf[: joint.start(1)] + fmt(far * s) + urdf[joint.end(1) :]

    link = re.search(r'<link name="%s">.*?</link>' % STRETCH_LINK, urdf, re.S)
    body = link.group(0)
    com = np.array(
        [float(v) for v in re.search(r'<inertial>\s*<origin xyz="([^"]+)"', body).group(1).split()]
    )
    mass = float(re.search(r'<mass value="([^"]+)"', body).group(1))
    names = ["ixx", "ixy", "ixz", "iyy", "iyz", "izz"]
    values = {n: float(re.search(r'%s="([^"]+)"' % n, body).group(1)) for n in names}
    tensor = np.array(
        [
            [values["ixx"], values["ixy"], values["ixz"]],
            [values["ixy"], values["iyy"], values["iyz"]],
            [values["ixz"], values["iyz"], values["izz"]],
        ]
    )
    stretch = np.eye(3) + (s - 1.0) * np.outer(d, d)
    moments = 0.5 * np.trace(tensor) * np.eye(3) - tensor
    moments = s * stretch @ moments @ stretch
    tensor = np.trace(moments) * np.eye(3) - moments
    new = re.sub(
        r'(<inertial>\s*<origin xyz=")[^"]+"', lambda m: m.group(1) + fmt(stretch @ com) + '"', body
    )
    new = re.sub(r'(<mass value=")[^"]+"', lambda m: m.group(1) + repr(float(mass * s)) + '"', new)
    index = {"ixx": (0, 0), "ixy": (0, 1), "ixz": (0, 2), "iyy": (1, 1), "iyz": (1, 2), "izz": (2, 2)}
    for n, (i, j) in index.items():
        new = re.sub(r'(%s=")[^"]+"' % n, lambda m, v=tensor[i, j]: m.group(1) + repr(float(v)) + '"', new)
    return urdf[: link.start()] + new + urdf[link.end() :]


def fmt(v) -> str:
    return " ".join(repr(float(x)) for x in v)


def load(urdf: str) -> mujoco.MjModel:
    model = mujoco.MjModel.from_xml_string(with_mujoco_options(urdf))
    model.dof_damping[:] = 0.0
    model.dof_frictionloss[:] = 0.0
    model.dof_armature[:] = 0.0
    model.jnt_limited[:] = 0
    model.opt.gravity[:] = [0.0, 0.0, -9.81]
    model.opt.disableflags |= mujoco.mjtDisableBit.mjDSBL_CONTACT
    assert model.nq == 6, "six revolute joints"
    return model


def poses(model: mujoco.MjModel) -> np.ndarray:
    """POSES poses drawn uniformly inside the joint limits (seeded)."""
    rng = np.random.default_rng(SEED)
    low, high = model.jnt_range[:, 0], model.jnt_range[:, 1]
    return rng.uniform(low, high, size=(POSES, 6))


def at_rest(model: mujoco.MjModel, q: np.ndarray):
    """Accelerations from rest and the holding (gravity) torques at q."""
    data = mujoco.MjData(model)
    data.qpos[:] = q
    data.qvel[:] = 0.0
    mujoco.mj_forward(model, data)
    return data.qacc.copy(), data.qfrc_bias.copy()


def swing(model: mujoco.MjModel, start) -> list:
    model.opt.integrator = mujoco.mjtIntegrator.mjINT_RK4
    model.opt.timestep = SWING_DT
    data = mujoco.MjData(model)
    data.qpos[:] = start
    mujoco.mj_forward(model, data)
    rows = [[0.0, *data.qpos, *data.qvel]]
    for k in range(1, int(round(SWING_SECONDS / SWING_DT)) + 1):
        mujoco.mj_step(model, data)
        if k % SWING_EVERY == 0:
            rows.append([k * SWING_DT, *data.qpos, *data.qvel])
    return rows


def efforts(urdf: str) -> np.ndarray:
    """Each revolute joint's URDF effort (N m), in the file's order."""
    joints = re.findall(r'<joint name="[^"]+" type="revolute">.*?</joint>', urdf, re.S)
    return np.array([float(re.search(r'effort="([^"]+)"', j).group(1)) for j in joints])


def fraction(distance: float, t: float) -> float:
    """The share of a trapezoidal move of `distance` (rad) done at time t."""
    full_ramp = SPEED / ACCEL
    if ACCEL * full_ramp**2 >= distance:
        ramp, cruise = np.sqrt(distance / ACCEL), 0.0
    else:
        ramp, cruise = full_ramp, (distance - ACCEL * full_ramp**2) / SPEED
    duration = 2 * ramp + cruise
    if distance == 0.0 or t >= duration:
        return 1.0
    t = max(t, 0.0)
    top = ACCEL * ramp
    if t < ramp:
        covered = 0.5 * ACCEL * t * t
    elif t < ramp + cruise:
        covered = 0.5 * top * ramp + top * (t - ramp)
    else:
        covered = distance - 0.5 * ACCEL * (duration - t) ** 2
    return min(max(covered / distance, 0.0), 1.0)


def servoed_move(model: mujoco.MjModel, effort: np.ndarray, start, goal) -> list:
    model.opt.integrator = mujoco.mjtIntegrator.mjINT_RK4
    model.opt.timestep = TICK / TICK_SUBSTEPS
    data, probe = mujoco.MjData(model), mujoco.MjData(model)
    data.qpos[:] = start
    mujoco.mj_forward(model, data)
    distance = np.max(np.abs(goal - start))
    at = lambda k: start + (goal - start) * fraction(distance, k * TICK)
    duration = next(k for k in range(10**6) if fraction(distance, k * TICK) == 1.0) * TICK
    rows = [[0.0, *data.qpos, *data.qvel]]
    mass = np.zeros((model.nv, model.nv))
    for k in range(int(round((duration + SETTLE_SECONDS) / TICK))):
        x, v = data.qpos.copy(), data.qvel.copy()
        target = at(k + 1)
        speed = (at(k + 2) - at(k)) / (2 * TICK)
        accel = (at(k + 2) - 2 * at(k + 1) + at(k)) / TICK**2
        s = (accel + STIFFNESS * (target - x - TICK * v) + DAMPING * (speed - v)) / (
            1 + 0.5 * STIFFNESS * TICK**2 + DAMPING * TICK
        )
        mujoco.mj_forward(model, data)
        mujoco.mj_fullM(model, data, mass)
        probe.qpos[:] = target
        probe.qvel[:] = 0.0
        mujoco.mj_forward(model, probe)
        held = np.clip(probe.qfrc_bias, -effort, effort)
        left = effort - np.abs(held)
        data.qfrc_applied[:] = held + np.clip(mass @ s, -left, left)
        for _ in range(TICK_SUBSTEPS):
            mujoco.mj_step(model, data)
        rows.append([(k + 1) * TICK, *data.qpos, *data.qvel])
    return rows


def write(name: str, header: str, rows) -> None:
    path = OUT / name
    with open(path, "w") as out:
        out.write("# " + header + "\n")
        for row in rows:
            out.write(",".join("%.17g" % v for v in row) + "\n")
    print("wrote", path.relative_to(ROOT))


def main() -> None:
    OUT.mkdir(parents=True, exist_ok=True)
    urdf = (ROOT / "urdf" / "oscar6.urdf").read_text()
    model = load(urdf)
    qs = poses(model)
    q_cols = ",".join("q%d" % i for i in range(1, 7))
    write(
        "mujoco_accelerations.csv",
        "MuJoCo %s, oscar6.urdf, accelerations from rest (rad/s^2); %s,a1..a6"
        % (mujoco.__version__, q_cols),
        [[*q, *at_rest(model, q)[0]] for q in qs],
    )
    for n, start in enumerate(SWING_STARTS, 1):
        write(
            "mujoco_swing_%d.csv" % n,
            "MuJoCo %s, oscar6.urdf, passive swing, RK4 %g s, no limits; t,%s,v1..v6"
            % (mujoco.__version__, SWING_DT, q_cols),
            swing(load(urdf), start),
        )
    long_model = load(stretched(urdf))
    rows = []
    for q in qs:
        acc, torque = at_rest(long_model, q)
        rows.append([*q, *torque, *acc])
    write(
        "mujoco_stretched.csv",
        "MuJoCo %s, oscar6.urdf with %s %g m longer (uniform rod); %s,tau1..tau6 (N m),a1..a6"
        % (mujoco.__version__, STRETCH_LINK, STRETCH_M, q_cols),
        rows,
    )
    write(
        "mujoco_moves.csv",
        "servoed moves of oscar6.urdf: n,start q1..q6,goal q1..q6 (rad)",
        [[n, *start, *goal] for n, (start, goal) in enumerate(MOVES, 1)],
    )
    for n, (start, goal) in enumerate(MOVES, 1):
        write(
            "mujoco_move_%d.csv" % n,
            "MuJoCo %s, oscar6.urdf, servoed move %d (eyehand's servo law, 5 ms ticks), "
            "RK4 %g s, no limits; t,%s,v1..v6"
            % (mujoco.__version__, n, TICK / TICK_SUBSTEPS, q_cols),
            servoed_move(load(urdf), efforts(urdf), start, goal),
        )


if __name__ == "__main__":
    main()
