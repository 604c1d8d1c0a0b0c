#!/usr/bin/env bash
# The field features (junctions, centre circle, field boundary, stripe centre lines) scored on
# synthetic frames whose truth comes from their field and camera (fieldlines eval --gt
# --features), as Markdown tables on stdout. Per scene, 40 frames in all five lights per
# seed; thresholds built in, or calibrated label-free on seed 1. Seeds 4242 and 777 are held
# out from tuning the stages; 9001 and 9002 were scored once, on a finished build. Every stage on,
# then without the centre circle (the junctions from the detector's own drawing alone). A row
# counts paint from 0.5 px wide as visible instead of 1 px (--min-width); the last rows give the
# detector each frame's camera (the circle also fitted on the turf, junctions checked square on
# it); a second table scores the features on the ground with that camera.
#   usage: bash scripts/features_table.sh [OUT_DIR]      (default build/features-table)
#   env:   FIELDLINES_BIN (default build/release/app/cli/fieldlines), N (frames per set, 40)
set -euo pipefail
cd "$(dirname "$0")/.."
bin="${FIELDLINES_BIN:-build/release/app/cli/fieldlines}"
out="${1:-build/features-table}"
n="${N:-40}"
rm -rf "$out"
mkdir -p "$out"
for scene in ssl kid; do
  for seed in 1 4242 777 9001 9002; do
    "$bin" synth --scene "$scene" --condition all --n "$n" --seed "$seed" -o "$out/${scene}_$seed" --quiet >/dev/null
  done
  "$bin" calibrate "$out/${scene}_1" -o "$out/${scene}_cal.json" --quiet >/dev/null
done

# The same thresholds with the stripes and junctions on and the centre circle off (no second
# drawing): what eval scores for "junctions only".
without_circle() {
  python3 - "$1" "$2" <<'PY'
import json, sys
t = json.load(open(sys.argv[1]))
t.setdefault("detector", {}).update({"stripes": True, "intersections": True, "centre_circle": False})
json.dump(t, open(sys.argv[2], "w"), indent=2)
PY
}
without_circle assets/default_thresholds.json "$out/builtin_lines.json"
for scene in ssl kid; do without_circle "$out/${scene}_cal.json" "$out/${scene}_cal_lines.json"; done

# One row: LABEL, then columns COLUMNS of the pooled line of eval's table TABLE (1 edges, 2
# features, 3 features on the ground); the eval arguments choose the stages (--features, or a
# thresholds file's).
table_row() {
  local table="$1" columns="$2" label="$3"
  shift 3
  "$bin" eval "$@" --markdown | grep '^| all | all |' | sed -n "${table}p" |
    awk -F'|' -v label="$label" -v columns="$columns" '{
      n = split(columns, c, " "); line = "| " label
      for (k = 1; k <= n; ++k) line = line " | " $c[k]
      print line " |" }' | sed 's/  */ /g'
}
row() { table_row 2 "4 5 6 7 8 9 11 12 13" "$@"; }

echo "| frames | stages | thresholds | scene | true junctions | detected | precision | recall | type correct | circles found | wrong ellipses | boundary within 4 px | markings on line |"
echo "|---|---|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
# Every stage (--features over the thresholds), then the thresholds' own stages: no circle.
for stages in "every stage|--features|" "no centre circle||_lines"; do
  IFS='|' read -r what features suffix <<<"$stages"
  for pair in "4242 777 held out" "9001 9002 fresh"; do
    read -r a b kind <<<"$pair"
    row "seeds $a + $b ($kind) | $what | built-in | both" --gt "$out/ssl_$a" "$out/ssl_$b" "$out/kid_$a" "$out/kid_$b" \
      ${suffix:+--thresholds "$out/builtin$suffix.json"} $features
    for scene in kid ssl; do
      name="$([[ $scene == kid ]] && echo Kid || echo SSL)"
      row "seeds $a + $b ($kind) | $what | calibrated on seed 1 | $name" --gt "$out/${scene}_$a" "$out/${scene}_$b" \
        --thresholds "$out/${scene}_cal$suffix.json" $features
    done
  done
done
row "seeds 4242 + 777, paint from 0.5 px visible | every stage | built-in | both" \
  --gt "$out/ssl_4242" "$out/ssl_777" "$out/kid_4242" "$out/kid_777" --min-width 0.5 --features
# The camera known (eval --truth-camera): the centre circle also fitted on the turf, with each
# frame's camera exactly, or off as a robot's pose estimate is (pitch and roll by up to 1 or 2
# degrees, height by up to 5 or 10 %, drawn per frame). EMIT SEEDS WHAT EVAL-ARGS... per case.
each_camera_case() {
  local emit="$1" pair error a b kind what amount
  for pair in "4242 777 held out" "9001 9002 fresh"; do
    read -r a b kind <<<"$pair"
    for error in "exactly|" "within 1 deg and 5 %|1,0.05" "within 2 deg and 10 %|2,0.1"; do
      IFS='|' read -r what amount <<<"$error"
      "$emit" "seeds $a + $b ($kind)" "$what" --gt "$out/ssl_$a" "$out/ssl_$b" "$out/kid_$a" "$out/kid_$b" \
        --features --truth-camera ${amount:+--camera-error "$amount"}
    done
  done
}
camera_row() {
  local seeds="$1" what="$2"
  shift 2
  row "$seeds | every stage, camera known $what | built-in | both" "$@"
}
each_camera_case camera_row

# The features on the ground with the camera known (eval --truth-camera's third table): each
# matched junction's error over its true distance, and the centre circle's centre error on the
# turf where it lies within 4 m.
ground_row() {
  local seeds="$1" what="$2"
  shift 2
  table_row 3 "4 5 6 7 8 9 10 11" "$seeds | $what" "$@"
}
echo
echo "| frames | camera given | junctions matched | their median distance m | ground error median % | 90th percentile % | within 5 % | circles within 4 m found on the ground | centre error median cm | within 10 cm |"
echo "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|"
each_camera_case ground_row
