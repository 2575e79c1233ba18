#!/usr/bin/env bash
# Prints docs/ARMS.md's "From the URDF alone" tables: for the OSCAR-6, the Panda, the
# UR-style arm and that arm with a ±360° shoulder lift and a continuous elbow, what
# `eyehand reach` chose, then one lin5 run of each with nothing set but the URDF
# (20,000 kinematic trials, then 2,000 dynamic ones; seed 1).
# Usage: scripts/arms-from-urdf.sh [EYEHAND_BINARY]   (default: target/release/eyehand)
set -euo pipefail
cd "$(dirname "$0")/.."
eyehand=${1:-target/release/eyehand}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

sed -e 's|lower="-3.1416" upper="0.5"|lower="-6.2832" upper="6.2832"|' \
    -e 's|<joint name="elbow_joint" type="revolute">|<joint name="elbow_joint" type="continuous">|' \
    -e 's|<limit lower="-2.8" upper="3.0" effort="150"|<limit effort="150"|' \
    tests/data/ur_style.urdf >"$work/ur_full_turn.urdf"

arms=(oscar6 panda ur_style ur_full_turn)
urdf_args() {
    case $1 in
        oscar6) ;;
        panda) echo "--urdf tests/data/panda/panda.urdf" ;;
        ur_style) echo "--urdf tests/data/ur_style.urdf" ;;
        ur_full_turn) echo "--urdf $work/ur_full_turn.urdf" ;;
    esac
}

echo "| arm | learned joints | reach space r, z (cm) | boundary_0, boundary_1 (°) | target poses in contact | moves stopped by a contact (of 500) |"
echo "|---|---|---|---|---|---|"
for arm in "${arms[@]}"; do
    # shellcheck disable=SC2046
    "$eyehand" reach $(urdf_args "$arm") 2>/dev/null >"$work/reach"
    python3 - "$arm" "$work/reach" <<'EOF'
import re, sys
arm, text = sys.argv[1], open(sys.argv[2]).read()
line = lambda key: next(l for l in text.splitlines() if l.startswith(key))
joints = line("learned joints").split(None, 2)[2]
space = re.search(r"r ([\d.]+)\.\.([\d.]+) cm, z ([\d.]+)\.\.([\d.]+) cm", line("reach space"))
how = "fitted" if "(fitted)" in line("reach space") else "given"
bounds = re.search(r"to spare: ([-\d]+ [-\d]+, [-\d]+ [-\d]+)", line("learned θ2"))
bounds = bounds.group(1) + " (fitted)" if how == "fitted" else "the config's (the study's)"
touching = re.match(r"target contact\s+(\d+) of the (\d+)", line("target contact"))
stopped = re.match(r"contact\s+(\d+) of (\d+)", line("contact "))
print(f"| {arm} | {joints} | {space.group(1)}..{space.group(2)}, {space.group(3)}..{space.group(4)} ({how}) "
      f"| {bounds} | {touching.group(1)} of {touching.group(2)} | {stopped.group(1)} of {stopped.group(2)} |")
EOF
done

echo
echo "| arm | simulator | trials | lin5 mean distance after steps 1..5 (mm) | contact stops per 1,000 moves | failed trials | trials/s |"
echo "|---|---|---|---|---|---|---|"
for sim in kinematic dynamic; do
    trials=20000
    [ "$sim" = dynamic ] && trials=2000
    for arm in "${arms[@]}"; do
        data="$work/data-$arm-$sim"
        # shellcheck disable=SC2046
        "$eyehand" run $(urdf_args "$arm") --sim "$sim" --trials "$trials" --seed 1 \
            --data "$data" --quiet --no-plot >/dev/null 2>&1
        python3 - "$arm" "$sim" "$data/lin5/0/summary.json" <<'EOF'
import json, sys
arm, sim, path = sys.argv[1:]
s = json.load(open(path))
means = ", ".join(f"{m:.3g}" for m in s["mean_distance_mm"])
stops = 1000.0 * s["stopped_by_contact"] / max(s["moves"], 1)
print(f"| {arm} | {sim} | {s['trials']:,} | {means} | {stops:.2g} | {s['failures']} | {s['trials_per_second']:,.0f} |")
EOF
    done
done
