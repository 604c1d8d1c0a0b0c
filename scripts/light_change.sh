#!/usr/bin/env bash
# Light that changes after calibration: each venue is calibrated on its frames as shot (each half
# for the other's hand-truth frames, venue_common.sh), then those frames are scored as shot and at a third of
# the exposure (every frame multiplied by 0.35 with ImageMagick into OUT/dim/data), with the
# detector's gradient threshold fixed (dark_field 0) and following the frame's field
# (dark_field = the calibration's reference field brightness, light.hpp). Prints Markdown.
#   usage: bash scripts/light_change.sh [OUT_DIR]   (default build/light-change)
#   env:   FIELDLINES_BIN (default build/release/app/cli/fieldlines), SHARED (default ../shared)
set -euo pipefail
cd "$(dirname "$0")/.."
bin="${FIELDLINES_BIN:-build/release/app/cli/fieldlines}"
out="${1:-build/light-change}"
shared_data="${SHARED:-../shared}/data"
data="$shared_data"
rm -rf "$out"
mkdir -p "$out"
source scripts/venue_common.sh
dim="$out/dim/data"
for folder in msl-samples humanoid-samples elsed-ssl/images; do
  mkdir -p "$dim/$folder"
  for f in "$shared_data/$folder"/*; do
    [[ -f $f ]] && convert "$f" -evaluate multiply 0.35 "$dim/$folder/$(basename "$f")"
  done
done
# THRESHOLDS OUT MODE: the file with dark_field 0 (fixed) or the reference field's R + G + B.
with_dark_field() {
  python3 - "$1" "$3" "$2" <<'PY'
import json, sys
t = json.load(open(sys.argv[1]))
t["detector"]["dark_field"] = sum(t["light"]["reference_field"]) if sys.argv[2] == "follow" else 0.0
json.dump(t, open(sys.argv[3], "w"))
PY
}
echo "| venue | gradient threshold | frames as shot: marking P / R | at 0.35 of the exposure |"
echo "|---|---|---:|---:|"
for v in "${venues[@]}"; do
  IFS='|' read -r id pattern title <<<"$v"
  if ! compgen -G "$shared_data/$pattern" >/dev/null; then echo "| $title | not measured: no $shared_data | | |"; continue; fi
  data="$shared_data"
  halves "$id" "$pattern"
  calibrate_halves "$id" "$out/$id"
  for mode in fixed follow; do
    per_half with_dark_field "$out/$id" "$out/$id-$mode" "$mode"
    label="fixed"; [[ $mode == follow ]] && label="follows the field (dark_field $(python3 -c "import json; print(round(json.load(open('$out/$id-$mode-0.json'))['detector']['dark_field']))") on the first half)"
    data="$shared_data"; as_shot=$(score "$id" "$out/$id-$mode" | tr '|' '/')
    data="$dim"; dimmed=$(score "$id" "$out/$id-$mode" | tr '|' '/')
    echo "| $title | $label | $as_shot | $dimmed |"
  done
done
