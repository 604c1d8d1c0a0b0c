#!/usr/bin/env bash
# Label-free calibration on real fields of other leagues, scored on frames it was not fitted on.
# Per venue: calibrate on the venue's frames that have no hand-drawn truth, then score the
# frames that have one (tests/data/hand_truth/<venue>, docs/calibration.md) with
#   the built-in thresholds, the calibration without and with per-frame light adaptation,
#   the built-in thresholds and the calibration with light adaptation, each with the stripes
#   stage on (stripes.hpp: markings must be turf, paint, turf),
#   (these with the built-in detector parameters: --keep-detector), and the calibration that
#   chooses the detector parameters too (the command's default; detector_calibration.hpp),
# and the recall ceiling (every segment called a marking: the share of line edges on any
# segment) of the built-in and of the calibrated detector parameters, and the calibrated file with
# the coarse pass (coarse_scale 2 and 3 from half the height down) added. Prints Markdown. Before/after overlays of the scored
# frames go to OUT_DIR/overlays/<venue>/{built-in,calibrated}/ (not into docs/: they are the
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
stripes() {  # THRESHOLDS -> the same file with the stripes stage on, beside it
  local on="${1%.json}-stripes.json"
  [[ $1 == assets/* ]] && on="$out/$(basename "${1%.json}")-stripes.json"
  python3 -c "import json,sys; t=json.load(open(sys.argv[1])); t['detector']['stripes']=True; json.dump(t, open(sys.argv[2], 'w'))" "$1" "$on"
  echo "$on"
}
echo "| venue | frames fitted / scored | thresholds | marking P | marking R | calibration says |"
echo "|---|---|---|---:|---:|---|"
venue_rows() {
  fitted=$(ls "$out/$id" | wc -l)
  n_scored=$(wc -w <<<"$scored")
  echo "| $title | $fitted / $n_scored | built-in | $(score "$id" assets/default_thresholds.json) | |"
  echo "| | | built-in + stripes | $(score "$id" "$(stripes assets/default_thresholds.json)") | |"
  for mode in no-light light detector; do
    flag=(--keep-detector); [[ $mode == no-light ]] && flag+=(--no-light-adaptation)
    [[ $mode == detector ]] && flag=()
    label="calibrated"; [[ $mode == light ]] && label="calibrated + light adaptation"
    [[ $mode == detector ]] && label="**calibrated detector + thresholds** (light adaptation, stripes)"
    if "$bin" calibrate "$out/$id" -o "$out/$id-$mode.json" --json "$out/$id-$mode.fit.json" --quiet "${flag[@]}" \
        2> "$out/$id-$mode.err"; then
      says=$(python3 -c "
import json; f=json.load(open('$out/$id-$mode.fit.json'))['fit']
m=f['marking']; parts=[('by contrast' if m['used_contrast'] else 'by colour')]
if m['warning']: parts.append(m['warning'])
if not f['boundary']['fitted']: parts.append('boundary off')
print('; '.join(parts))")
      echo "| | | $label | $(score "$id" "$out/$id-$mode.json") | $says |"
      if [[ $mode == light ]]; then
        echo "| | | $label + stripes | $(score "$id" "$(stripes "$out/$id-$mode.json")") | |"
      fi
    else
      echo "| | | $label | | | refused: $(sed 's/^fieldlines calibrate: error: //' "$out/$id-$mode.err" | tr '\n' ' ') |"
    fi
  done
  scored_paths=(); for image in $scored; do scored_paths+=("$data/$image"); done
  "$bin" detect --quiet --draw "$out/overlays/$id/built-in" "${scored_paths[@]}"
  [[ -f "$out/$id-light.json" ]] &&
    "$bin" detect --quiet --thresholds "$out/$id-light.json" --draw "$out/overlays/$id/calibrated" "${scored_paths[@]}"
  echo "| | | (recall ceiling of the built-in detector) | | $(score "$id" "$out/everything.json" | cut -d'|' -f2 | tr -d ' ') | |"
  if [[ -f "$out/$id-detector.json" ]]; then
    everything "$out/$id-detector.json" "$out/$id-everything.json"
    echo "| | | (recall ceiling of the calibrated detector) | | $(score "$id" "$out/$id-everything.json" | cut -d'|' -f2 | tr -d ' ') | |"
    # The coarse pass (detector.cpp) added to the calibrated file, rows from half the height down.
    for k in 2 3; do
      python3 -c "import json,sys; t=json.load(open(sys.argv[1])); t['detector'].update(coarse_scale=$k, coarse_from=0.5); json.dump(t, open(sys.argv[2], 'w'))" \
        "$out/$id-detector.json" "$out/$id-coarse$k.json"
      everything "$out/$id-coarse$k.json" "$out/$id-coarse$k-everything.json"
      echo "| | | calibrated detector + thresholds, coarse pass $k (ceiling $(score "$id" "$out/$id-coarse$k-everything.json" | cut -d'|' -f2 | tr -d ' ')) | $(score "$id" "$out/$id-coarse$k.json") | |"
    done
  fi
}
each_venue venue_rows 6

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
