#!/usr/bin/env bash
# Label-free calibration on real fields of other leagues, scored on frames it was not fitted on.
# Per venue: its frames split in two halves (venue_common.sh: halves); each half calibrated
# without labels and scored on the hand-drawn truth of the other half's frames
# (tests/data/hand_truth/<venue>, docs/calibration.md), the two halves pooled. Rows: the built-in
# thresholds; the calibration as the command makes it (detector parameters and thresholds,
# detector_calibration.hpp), with its recall ceiling (every segment called a marking: the share
# of line edges on any segment); that file with the stripes' turf in the field colour alone
# rather than the frame's turf colours (turf_colours.hpp) and with the coarse pass (coarse_scale 2 and 3 from half the height down).
# Columns: marking P and R (segments, each of a line's two edges), the ceiling, the share of
# hand-drawn field-boundary columns within 4 px, the stripes' centre lines P / R against the
# drawn lines' centres (one per line: what the robot takes; fieldlines eval --hand). Prints
# Markdown. Overlays of the scored frames (`eval --draw`: each drawn line edge found, lost by the
# classification or missed; the drawn and the detected field boundary) go to
# OUT_DIR/overlays/<venue>/{built-in,calibrated}/<truth half>/ (not into docs/: they are the
# shared data's images).
#   usage: bash scripts/venue_calibration.sh [OUT_DIR]   (default build/venue-calibration)
#   env:   FIELDLINES_BIN (default build/release/app/cli/fieldlines), SHARED (default ../shared)
set -euo pipefail
cd "$(dirname "$0")/.."
bin="${FIELDLINES_BIN:-build/release/app/cli/fieldlines}"
out="${1:-build/venue-calibration}"
data="${SHARED:-../shared}/data"
rm -rf "$out"
mkdir -p "$out"
source scripts/venue_common.sh
everything assets/default_thresholds.json "$out/everything.json"
detector_with() {  # IN OUT KEY=VALUE...: a copy with detector parameters set
  python3 - "$@" <<'PY'
import json, sys
t = json.load(open(sys.argv[1]))
for kv in sys.argv[3:]:
    k, v = kv.split("=")
    t["detector"][k] = json.loads(v)
json.dump(t, open(sys.argv[2], "w"))
PY
}
# A row: LABEL THRESHOLDS [SAYS]: marking P | R, the recall ceiling of its detector, the boundary.
row() {
  local label=$1 th=$2 says=${3:-} ceiling=$out/ceiling
  if [[ -f "$th-0.json" ]]; then per_half everything "$th" "$ceiling"; else everything "$th" "$ceiling.json"; ceiling=$ceiling.json; fi
  echo "| | | $label | $(score "$id" "$th") | $(score "$id" "$ceiling" | cut -d'|' -f2 | tr -d ' ') | $(score "$id" "$th" boundary) | $(score "$id" "$th" centre) | $says |"
}
echo "| venue | frames per half / scored | thresholds | marking P | marking R | on any segment | boundary within 4 px | stripes' centre lines P / R | calibration says |"
echo "|---|---|---|---:|---:|---:|---:|---:|---|"
venue_rows() {
  local frames scored k
  frames=$(( $(ls "$out/$id-fit0" | wc -l) )) scored=$(( $(ls "$out/$id-truth0" "$out/$id-truth1" | grep -c json) ))
  echo "| $title | $frames + $(ls "$out/$id-fit1" | wc -l) / $scored | | | | | | | |"
  row "built-in" assets/default_thresholds.json
  if ! calibrate_halves "$id" "$out/$id"; then
    echo "| | | calibrated | | | | | | refused: $(sed 's/^fieldlines calibrate: error: //' "$out/$id"-*.err | tr '\n' ' ') |"
    return
  fi
  says=$(python3 -c "
import json; f=json.load(open('$out/$id-0.fit.json'))['fit']
m=f['marking']; parts=[('by contrast' if m['used_contrast'] else 'by colour')]
if m['warning']: parts.append(m['warning'])
if not f['boundary']['fitted']: parts.append('boundary off')
print('; '.join(parts))")
  row "**calibrated** (detector + thresholds)" "$out/$id" "$says (first half)"
  per_half detector_with "$out/$id" "$out/$id-median" stripe_turf_colours=false
  row "calibrated, stripes on the field colour alone" "$out/$id-median"
  for k in 2 3; do
    per_half detector_with "$out/$id" "$out/$id-coarse$k" coarse_scale=$k coarse_from=0.5
    row "calibrated, coarse pass $k" "$out/$id-coarse$k"
  done
  for k in 0 1; do
    compgen -G "$out/$id-truth$k/*.json" >/dev/null || continue
    "$bin" eval --hand "$out/$id-truth$k" --data "$data" --draw "$out/overlays/$id/built-in" >/dev/null
    "$bin" eval --hand "$out/$id-truth$k" --data "$data" --thresholds "$out/$id-$k.json" \
      --draw "$out/overlays/$id/calibrated" >/dev/null
  done
}
each_venue venue_rows 9

echo
echo "Synthetic Kid field, one light at a time: calibrated on 20 frames of one light (seed 1), scored"
echo "against the exact truth of 20 frames of each other light (seed 2); marking P / R."
echo
conditions=(artificial natural mixed dim shadows)
for c in "${conditions[@]}"; do
  for seed in 1 2; do
    "$bin" synth --scene kid --condition "$c" --n 20 --seed "$seed" --quiet -o "$out/kid-$c-$seed" >/dev/null
  done
done
echo "| calibrated on | light adaptation | detector | $(printf '%s | ' "${conditions[@]}")"
echo "|---|---|---|$(printf -- '---:|%.0s' "${conditions[@]}")"
for cal in "${conditions[@]}"; do
  for mode in no-light light detector; do
    flag=(--keep-detector); [[ $mode == no-light ]] && flag+=(--no-light-adaptation)
    [[ $mode == detector ]] && flag=()
    row="| $cal | $([[ $mode == no-light ]] && echo off || echo on) | $([[ $mode == detector ]] && echo calibrated || echo built-in) |"
    "$bin" calibrate "$out/kid-$cal-1" -o "$out/kid-$cal-$mode.json" --quiet "${flag[@]}"
    for c in "${conditions[@]}"; do
      if [[ $c == "$cal" ]]; then row+=" (fitted) |"; continue; fi
      "$bin" eval --gt "$out/kid-$c-2" --thresholds "$out/kid-$cal-$mode.json" --json "$out/score.json" >/dev/null
      row+=" $(python3 -c "import json; m=json.load(open('$out/score.json'))['total']['marking']; print('%.3f / %.3f' % (m['precision'], m['recall']))") |"
    done
    echo "$row"
  done
done

echo
echo "Recall ceiling on the same synthetic frames (seed 2; every segment called a marking): the"
echo "built-in detector's and the calibrated detector's (calibrated on the artificial light)."
echo
everything "$out/kid-artificial-detector.json" "$out/kid-everything.json"
echo "| detector | $(printf '%s | ' "${conditions[@]}")"
echo "|---|$(printf -- '---:|%.0s' "${conditions[@]}")"
for th in "$out/everything.json" "$out/kid-everything.json"; do
  row="| $([[ $th == "$out/everything.json" ]] && echo built-in || echo calibrated) |"
  for c in "${conditions[@]}"; do
    "$bin" eval --gt "$out/kid-$c-2" --thresholds "$th" --json "$out/score.json" >/dev/null
    row+=" $(python3 -c "import json; print('%.3f' % json.load(open('$out/score.json'))['total']['marking']['recall'])") |"
  done
  echo "$row"
done
