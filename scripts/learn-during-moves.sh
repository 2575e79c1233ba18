#!/usr/bin/env bash
# Prints docs/ADAPTATION.md's learn_during_moves table: lin5 with and without the frames
# taken during moves (camera_fps 30, move_frames_learned at its default, 1), on the same seeds, at
# robot_speed 10 and 1 on the kinematic simulator (20,000 trials) and at robot_speed 10 on
# the dynamic one (2,000 trials: its moves cost physics steps in proportion to their time).
# Trials to a 4-step mean are counted on the running mean of the last 500 trials.
# Usage: scripts/learn-during-moves.sh [EYEHAND_BINARY] [SEEDS]   (default: target/release/eyehand, "1 2 3")
set -euo pipefail
cd "$(dirname "$0")/.."
eyehand=${1:-target/release/eyehand}
seeds=${2:-1 2 3}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

echo "| simulator | robot_speed (°/s) | learn_during_moves | seed | trials to 1 / 0.1 / 0.05 mm (4-step mean) | 4-step mean at the end (mm) | stored patterns per trial | trials/s |"
echo "|---|---|---|---|---|---|---|---|"
for cell in "kinematic 10 20000" "kinematic 1 20000" "dynamic 10 2000"; do
    read -r sim speed trials <<<"$cell"
    for learn in 0 1; do
        fps=0
        [ "$learn" = 1 ] && fps=30
        for seed in $seeds; do
            data="$work/$sim-$speed-$learn-$seed"
            "$eyehand" run --sim "$sim" --trials "$trials" --seed "$seed" --data "$data" \
                --set robot_speed="$speed" --set learn_during_moves="$learn" \
                --set camera_fps="$fps" --quiet --no-plot >/dev/null 2>&1
            python3 - "$sim" "$speed" "$learn" "$seed" "$data/lin5/0" <<'PY'
import json, sys
sim, speed, learn, seed, run = sys.argv[1:]
summary = json.load(open(f"{run}/summary.json"))
rows = [line.split() for line in open(f"{run}/4step")]
window, kept, first = 500, [], {}
for trial, distance, *_ in rows:
    kept.append(float(distance))
    if len(kept) > window:
        kept.pop(0)
    mean = sum(kept) / len(kept)
    for goal in (1.0, 0.1, 0.05):
        if goal not in first and len(kept) == window and mean <= goal:
            first[goal] = int(trial)
reach = " / ".join(f"{first[g]:,}" if g in first else "-" for g in (1.0, 0.1, 0.05))
end = summary["mean_distance_mm"][3]
per_trial = summary["patterns"] / summary["trials"]
print(f"| {sim} | {speed} | {learn} | {seed} | {reach} | {end:.4f} | {per_trial:.1f} | {summary['trials_per_second']:,.0f} |")
PY
        done
    done
done
