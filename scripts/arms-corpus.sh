#!/usr/bin/env bash
# Prints docs/ARMS.md's table of the public corpus: for every serial arm of PyPI's
# example-robot-data (the arms of tests/corpus.rs), what `eyehand reach` chose with nothing
# but `--urdf` (three arms also with a camera_mount that works), then one lin5 run of
# 20,000 kinematic trials (seed 1) — or the refusal.
# Usage: scripts/arms-corpus.sh [--sim dynamic] [EYEHAND_BINARY]   (default:
# target/release/eyehand). With `--sim dynamic`, docs/DYNAMIC.md's table instead: 2,000 lin5
# trials (seed 1) per arm on the dynamic simulator, its settle time-outs, contact stops and
# speed faults.
# The collection's share/example-robot-data folder is EYEHAND_ROBOT_DATA; without it the
# script installs the package into a virtual environment of its own.
set -euo pipefail
cd "$(dirname "$0")/.."
sim=kinematic
trials=20000
if [ "${1:-}" = "--sim" ]; then
    sim=$2
    trials=2000
    shift 2
fi
eyehand=${1:-target/release/eyehand}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
if [ -z "${EYEHAND_ROBOT_DATA:-}" ]; then
    python3 -m venv "$work/venv"
    "$work/venv/bin/pip" install --quiet --disable-pip-version-check --no-deps example-robot-data==6.0.0
    purelib=$("$work/venv/bin/python" -c 'import sysconfig; print(sysconfig.get_paths()["purelib"])')
    EYEHAND_ROBOT_DATA="$purelib/cmeel.prefix/share/example-robot-data"
fi
robots="$EYEHAND_ROBOT_DATA/robots"

arms=(
    panda_description/urdf/panda.urdf
    xarm_description/urdf/xarm7.urdf
    kinova_description/robots/kinova.urdf
    "kinova_description/robots/kinova.urdf camera_mount=0,0,0,180,0,0"
    ur_description/urdf/ur3_robot.urdf
    ur_description/urdf/ur5_robot.urdf
    ur_description/urdf/ur10_robot.urdf
    z1_description/urdf/z1.urdf
    so_arm_description/urdf/so100.urdf
    "z1_description/urdf/z1.urdf camera_mount=0,0,0,180,0,0"
    so_arm_description/urdf/so101.urdf
    "so_arm_description/urdf/so101.urdf camera_mount=0,0,-0.05,0,-90,0"
    talos_data/robots/talos_left_arm.urdf
)

if [ "$sim" = dynamic ]; then
    echo "| arm | lin5 mean distance after steps 1..5 (mm) | settle time-outs | contact stops per 1,000 moves | speed faults (worst) | trials/s |"
else
    echo "| arm | camera link | reach space r, z (cm) | lin5 mean distance after steps 1..5 (mm) | contact stops per 1,000 moves | trials/s |"
fi
echo "|---|---|---|---|---|---|"
for entry in "${arms[@]}"; do
    # An arm's URDF, then the config entries set for it (none: nothing but --urdf).
    read -r arm entries <<<"$entry"
    sets=()
    for set in $entries; do sets+=(--set "$set"); done
    data="$work/data"
    rm -rf "$data"
    "$eyehand" reach --urdf "$robots/$arm" "${sets[@]}" >"$work/reach" 2>"$work/reach-err" || true
    "$eyehand" run --urdf "$robots/$arm" "${sets[@]}" --set "sim=$sim" --trials "$trials" \
        --seed 1 --data "$data" --quiet --no-plot >/dev/null 2>"$work/run-err" || true
    python3 - "$arm" "$entries" "$work/reach" "$work/run-err" "$data/lin5/0/summary.json" "$sim" <<'EOF'
import json, os, re, sys
arm, entries, reach, err, summary, sim = sys.argv[1:]
name = os.path.basename(arm).removesuffix(".urdf")
if entries:
    name += " (" + entries.replace("=", " ") + ")"
text = open(reach).read()
line = lambda key: next((l for l in text.splitlines() if l.startswith(key)), "")
camera = re.search(r"`([^`]+)`", line("camera link"))
camera = camera.group(1) if camera else "-"
space = re.search(r"r ([\d.]+)\.\.([\d.]+) cm, z ([\d.]+)\.\.([\d.]+) cm", line("reach space"))
if os.path.exists(summary) and sim == "dynamic":
    s = json.load(open(summary))
    means = ", ".join(f"{m:.3g}" for m in s["mean_distance_mm"])
    stops = 1000.0 * s["stopped_by_contact"] / max(s["moves"], 1)
    worst = s["worst_speed_fault"]
    faults = f"{s['speed_faults']:,}" + (
        f" (joint {worst['joint']}: {worst['speed_deg_s']:.0f} of {worst['limit_deg_s']:.0f}°/s)" if worst else "")
    print(f"| {name} | {means} | {s['settle_timeouts']:,} | {stops:.2g} | {faults} | {s['trials_per_second']:,.1f} |")
elif os.path.exists(summary):
    s = json.load(open(summary))
    means = ", ".join(f"{m:.3g}" for m in s["mean_distance_mm"])
    stops = 1000.0 * s["stopped_by_contact"] / max(s["moves"], 1)
    print(f"| {name} | `{camera}` | {space.group(1)}..{space.group(2)}, {space.group(3)}..{space.group(4)} "
          f"| {means} | {stops:.2g} | {s['trials_per_second']:,.0f} |")
else:
    why = [l for l in open(err).read().splitlines() if not l.startswith("eyehand: warning")]
    why = why[-1].removeprefix("eyehand: ") if why else "?"
    why = re.sub(r" \(closer than.*?in area\)", "", why)
    if sim == "dynamic":
        print(f"| {name} | refused: {why} | - | - | - | - |")
    else:
        print(f"| {name} | `{camera}` | refused: {why} | - | - | - |")
EOF
done
