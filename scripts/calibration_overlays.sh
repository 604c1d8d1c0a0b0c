#!/usr/bin/env bash
# Before/after overlays of label-free calibration for docs/calibration.md, on data we generate (never the
# authors'): 20 synthetic Kid frames of seed 7 over every lighting condition, calibrated without a
# label, one frame drawn with the default thresholds and with the calibrated ones.
#   usage: bash scripts/calibration_overlays.sh [FRAME_INDEX]   (default 11)
#   env:   FIELDLINES_BIN (default build/release/app/cli/fieldlines)
set -euo pipefail
cd "$(dirname "$0")/.."
bin="${FIELDLINES_BIN:-build/release/app/cli/fieldlines}"
index="$(printf '%04d' "${1:-11}")"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
"$bin" synth --scene kid --condition all --n 20 --seed 7 -o "$work/frames" --quiet >/dev/null
"$bin" calibrate "$work/frames" -o "$work/robot.json" --quiet
frame="$work/frames/kid_7_$index.png"
"$bin" detect "$frame" --draw "$work/before" --quiet
"$bin" detect "$frame" --thresholds "$work/robot.json" --draw "$work/after" --quiet
cp "$work/before/kid_7_$index.png" docs/screenshots/calibrate-kid-before.png
cp "$work/after/kid_7_$index.png" docs/screenshots/calibrate-kid-after.png
# The figures docs/calibration.md quotes beside them: the whole set against its exact ground
# truth, detected with each file's detector (the calibrated one chooses its own).
for t in assets/default_thresholds.json "$work/robot.json"; do
  "$bin" eval --gt "$work/frames" --thresholds "$t" --json "$work/score.json" >/dev/null
  python3 -c "import json,sys; m=json.load(open(sys.argv[1]))['total']['marking']; print(sys.argv[2], 'marking P %.3f R %.3f' % (m['precision'], m['recall']))" "$work/score.json" "$(basename "$t")"
done
