#!/usr/bin/env bash
# Reproduces the label-free calibration tables of docs/calibration.md with the built CLI.
#  1. The authors' five annotation files: each calibrated with its label columns cut off, then
#     scored against the human labels on all rows (`fieldlines eval`): recall of the labelled
#     segments. The CSV holds no frames, so recall of the true lines is measured with the same
#     thresholds (and the built-in detector the files were detected with) on the hand-drawn truth
#     of that league's frames (`fieldlines eval --hand`: the 12 SSL frames for the SSL files, the
#     nine Humanoid frames for D4), where a line with no segment counts too.
#  2. Synthetic sets: calibrated on the images of seed 1 (all lighting conditions), scored
#     against the exact ground truth of seed 2 (also with the built-in detector kept), next to
#     supervised training on the same seed-1 images (autolabelled) and the default thresholds.
#   usage: bash scripts/calibration_table.sh [OUT_DIR]   (default build/calibration-table)
#   env:   FIELDLINES_BIN (default build/release/app/cli/fieldlines), SHARED (default ../shared)
set -euo pipefail
cd "$(dirname "$0")/.."
bin="${FIELDLINES_BIN:-build/release/app/cli/fieldlines}"
out="${1:-build/calibration-table}"
data="${SHARED:-../shared}/data"
annotations="$data/elsed-ssl/annotations"
rm -rf "$out"
mkdir -p "$out"
field() { python3 -c "import json,sys; d=json.load(open(sys.argv[1]))['total']; print('%.3f/%.3f' % (d[sys.argv[2]]['precision'], d[sys.argv[2]]['recall']) if d[sys.argv[2]]['tp'] + d[sys.argv[2]]['fn'] else 'n/a')" "$@"; }

echo "| file | marking P/R (of the labelled segments) | marking P/R of the true lines (hand-drawn frames) | boundary P/R | marking max angle / min proj / min length |"
echo "|---|---|---|---|---|"
for f in D1_ssl_natural_light D2_ssl_mixed_light D3_ssl_artificial_light D4_humanoid_kid ssl_navigation; do
  # Labels stripped: the first 12 columns only.
  cut -d, -f1-12 "$annotations/$f.csv" > "$out/$f-unlabelled.csv"
  "$bin" calibrate "$out/$f-unlabelled.csv" -o "$out/$f.json" --quiet
  "$bin" eval "$annotations/$f.csv" --thresholds "$out/$f.json" --json "$out/$f-eval.json" >/dev/null
  m=$(python3 -c "import json,sys; c=json.load(open(sys.argv[1]))['classes']['marking']; print('%.2f / %.1f / %.0f' % (c['max_angle_deg'], c['min_projection'], c['min_length']))" "$out/$f.json")
  hand=tests/data/hand_truth/ssl; [[ $f == D4_* ]] && hand=tests/data/hand_truth/humanoid
  "$bin" eval --hand "$hand" --data "$data" --thresholds "$out/$f.json" --json "$out/$f-hand.json" >/dev/null
  true_lines=$(python3 -c "import json,sys; m=json.load(open(sys.argv[1]))['total']['marking']; print('%.3f/%.3f (%s)' % (m['precision'], m['recall'], sys.argv[2]))" "$out/$f-hand.json" "$(basename "$hand")")
  echo "| $f | $(field "$out/$f-eval.json" marking) | $true_lines | $(field "$out/$f-eval.json" boundary) | $m |"
done
echo
echo "Synthetic sets (train/calibrate on seed 1, test on seed 2; detection scored against ground truth):"
for scene in ssl kid; do
  "$bin" synth --scene "$scene" --condition all --n 40 --seed 1 -o "$out/$scene-train" --quiet >/dev/null
  "$bin" synth --scene "$scene" --condition all --n 20 --seed 2 -o "$out/$scene-test" --quiet >/dev/null
  # A refusal is a result too: say so and go on.
  "$bin" calibrate "$out/$scene-train" -o "$out/$scene-label-free.json" --quiet 2> "$out/$scene-calibrate.err" ||
    echo "$scene: label-free refused: $(cat "$out/$scene-calibrate.err")"
  # The same with the built-in detector parameters kept (before calibration chose them).
  "$bin" calibrate "$out/$scene-train" -o "$out/$scene-label-free-built-in-detector.json" --keep-detector --quiet \
    2> "$out/$scene-calibrate-kept.err" ||
    echo "$scene: label-free with the built-in detector refused: $(cat "$out/$scene-calibrate-kept.err")"
  "$bin" autolabel "$out/$scene-train" --csv "$out/$scene-train.csv" --quiet
  "$bin" train "$out/$scene-train.csv" --train-fraction 1 -o "$out/$scene-supervised.json" --quiet >/dev/null
  for t in label-free label-free-built-in-detector supervised; do
    [[ -f "$out/$scene-$t.json" ]] || continue
    echo "#### $scene, $t"
    "$bin" eval --gt "$out/$scene-test" --thresholds "$out/$scene-$t.json" --markdown | tail -1
  done
  echo "#### $scene, default thresholds"
  "$bin" eval --gt "$out/$scene-test" --thresholds assets/default_thresholds.json --markdown | tail -1
done
