#!/usr/bin/env bash
# Reproduces the per-scene/condition table of docs/synth.md with the built CLI:
# for each scene, thresholds are trained on autolabelled synthetic images of seed 1 (all lighting
# conditions mixed), then detection + classification are scored against the exact ground truth
# of fresh images of seed 2, per condition.
#   usage: bash scripts/synth_table.sh [OUT_DIR]      (default build/synth-table)
#   env:   FIELDLINES_BIN (default build/release/app/cli/fieldlines), N_TRAIN (40), N_TEST (20)
set -euo pipefail
cd "$(dirname "$0")/.."
bin="${FIELDLINES_BIN:-build/release/app/cli/fieldlines}"
out="${1:-build/synth-table}"
n_train="${N_TRAIN:-40}"
n_test="${N_TEST:-20}"
rm -rf "$out"
mkdir -p "$out"
for scene in ssl kid; do
  "$bin" synth --scene "$scene" --condition all --n "$n_train" --seed 1 -o "$out/$scene-train" --quiet >/dev/null
  "$bin" autolabel "$out/$scene-train" --csv "$out/$scene-train.csv" --quiet
  # Marking thresholds for precision first (F-beta 0.5); the boundary keeps the authors' defaults.
  "$bin" train "$out/$scene-train.csv" --train-fraction 1 --class marking --objective fbeta:0.5 \
    -o "$out/$scene-thresholds.json" --quiet >/dev/null
  for condition in artificial natural mixed dim shadows; do
    "$bin" synth --scene "$scene" --condition "$condition" --n "$n_test" --seed 2 \
      -o "$out/$scene-test-$condition" --quiet >/dev/null
  done
  echo "### $scene (thresholds trained on $n_train autolabelled images, seed 1)"
  echo
  "$bin" eval --gt "$out/$scene-test-"* --thresholds "$out/$scene-thresholds.json" --markdown
  echo
  echo "with the default thresholds:"
  echo
  "$bin" eval --gt "$out/$scene-test-"* --markdown
  echo
done
