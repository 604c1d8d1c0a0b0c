#!/usr/bin/env bash
# Which detector parameters `fieldlines calibrate` should choose: per candidate (smoothing kernel,
# scan interval, minimum length, gradient threshold), each venue is calibrated with that detector
# kept (--keep-detector) on each half of its frames, then scored on the other half's frames with
# hand-drawn truth (venue_common.sh: halves), with the stripes stage off and on (each calibrated so: with it on, the markings are fitted
# on the stripes, as the command does), beside the candidate's recall ceiling (every segment
# called a marking). Prints Markdown: marking P / R.
#   usage: bash scripts/detector_candidates.sh [OUT_DIR] [KERNEL,SCAN,MIN_LENGTH,THRESHOLD ...]
#          (default build/detector-candidates; the method's, ELSED's and the chosen ones)
#   env:   FIELDLINES_BIN (default build/release/app/cli/fieldlines), SHARED (default ../shared)
set -euo pipefail
cd "$(dirname "$0")/.."
bin="${FIELDLINES_BIN:-build/release/app/cli/fieldlines}"
out="${1:-build/detector-candidates}"
shift || true
candidates=("$@")
[[ ${#candidates[@]} -gt 0 ]] || candidates=(7,10,40,30 5,2,15,30 5,2,25,30)
data="${SHARED:-../shared}/data"
rm -rf "$out"
mkdir -p "$out"
source scripts/venue_common.sh
with() {  # THRESHOLDS OUT KEY=VALUE... : a copy with the detector parameters set
  local in=$1 to=$2; shift 2
  python3 - "$in" "$to" "$@" <<'PY'
import json, sys
t = json.load(open(sys.argv[1]))
for kv in sys.argv[3:]:
    k, v = kv.split("=")
    t["detector"][k] = json.loads(v)
json.dump(t, open(sys.argv[2], "w"))
PY
}
echo "| kernel, scan, min length, threshold | venue | stripes off | stripes on | recall ceiling |"
echo "|---|---|---:|---:|---:|"
for v in "${venues[@]}"; do
  IFS='|' read -r id pattern title <<<"$v"
  compgen -G "$data/$pattern" >/dev/null || continue
  halves "$id" "$pattern"
done
for c in "${candidates[@]}"; do
  IFS=, read -r kernel scan length threshold <<<"$c"
  start="$out/start-$kernel-$scan-$length-$threshold.json"
  with assets/default_thresholds.json "$start" gaussian_kernel="$kernel" scan_interval="$scan" \
    min_line_length="$length" gradient_threshold="$threshold"
  everything "$start" "$out/everything.json"
  for v in "${venues[@]}"; do
    IFS='|' read -r id pattern title <<<"$v"
    [[ -d "$out/$id-fit0" ]] || continue
    cells=()
    for stripes in false true; do
      with "$start" "$out/start-stripes.json" stripes=$stripes
      fit="$out/$id-$kernel-$scan-$length-$threshold-$stripes"
      if calibrate_halves "$id" "$fit" --thresholds "$out/start-stripes.json" --keep-detector; then
        cells+=("$(score "$id" "$fit" | tr '|' '/')")
      else
        cells+=("refused")
      fi
    done
    ceiling=$(score "$id" "$out/everything.json" | cut -d'|' -f2 | tr -d ' ')
    echo "| $c | $title | ${cells[0]} | ${cells[1]} | $ceiling |"
  done
done
