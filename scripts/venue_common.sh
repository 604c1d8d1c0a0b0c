# Sourced by the scripts that score on real venues (venue_calibration.sh, detector_candidates.sh,
# junctions_real.sh, light_change.sh): the venues with hand-drawn truth, which of their frames are
# fitted and which scored (halves), and how a thresholds file is scored.
# Needs: $bin (the CLI), $data (the shared data folder), $out (a scratch folder).

# venue|frames (glob under data)|title
venues=("msl-delocht|msl-samples/20190606_r4_*|MSL, De Locht 2019"
        "msl-bangkok|msl-samples/20220715_r7_*|MSL, Bangkok 2022"
        "msl-bordeaux|msl-samples/20230709_r5_*|MSL, Bordeaux 2023"
        "humanoid|humanoid-samples/*|Humanoid (mixed fields)"
        "ssl|elsed-ssl/images/*.png|SSL (the authors' lab field)")

# THRESHOLDS OUT: its detector parameters (stripes off), every segment a marking, the boundary
# off, no gate: what the detector offers the classifier.
everything() {
  python3 - "$1" "$2" <<'PY'
import json, sys
t = json.load(open(sys.argv[1]))
t["classes"]["marking"].update(max_angle_deg=90, min_projection=0, min_length=0)
t["classes"]["boundary"].update(max_angle_deg=0, min_projection=1000, min_length=100000)
t["detector"]["stripes"] = False
t.pop("light", None); t.pop("field_boundary", None)
json.dump(t, open(sys.argv[2], "w"))
PY
}

# Every venue is split in two halves by the frames' order by name (even and odd positions). Each
# half is calibrated on its own frames and scored on the hand-drawn truth of the other half's, so
# every frame with truth is scored once, by thresholds fitted on frames that do not include it,
# and the two halves' counts are pooled. $out/VENUE-fitK holds links to half K's frames,
# $out/VENUE-truthK the truth files of the other half's frames (what half K's fit is scored on).
halves() {
  local id=$1 pattern=$2 k=0 image stem
  rm -rf "$out/$id-fit0" "$out/$id-fit1" "$out/$id-truth0" "$out/$id-truth1"
  mkdir -p "$out/$id-fit0" "$out/$id-fit1" "$out/$id-truth0" "$out/$id-truth1"
  for image in $data/$pattern; do
    ln -s "$(realpath "$image")" "$out/$id-fit$k/"
    stem=$(basename "${image%.*}")
    [[ -f "tests/data/hand_truth/$id/$stem.json" ]] && ln -s "$(realpath "tests/data/hand_truth/$id/$stem.json")" "$out/$id-truth$((1 - k))/"
    k=$((1 - k))
  done
}

# VENUE K: the image paths (under $data) that half K's fit is scored on.
scored_images() {
  local f
  for f in "$out/$1-truth$2"/*.json; do
    [[ -e $f ]] && echo "$data/$(python3 -c "import json,sys; print(json.load(open(sys.argv[1]))['image'])" "$f")"
  done
}

# VENUE PREFIX [calibrate options]: PREFIX-K.json calibrated on half K (K = 0, 1), its report
# PREFIX-K.fit.json and messages PREFIX-K.err; fails when either half is refused.
calibrate_halves() {
  local id=$1 prefix=$2 k status=0
  shift 2
  for k in 0 1; do
    "$bin" calibrate "$out/$id-fit$k" -o "$prefix-$k.json" --json "$prefix-$k.fit.json" --quiet "$@" \
      2>"$prefix-$k.err" || status=1
  done
  return $status
}

# FUNCTION IN_PREFIX OUT_PREFIX [ARGS]: FUNCTION IN_PREFIX-K.json OUT_PREFIX-K.json ARGS per half.
per_half() {
  local fn=$1 in=$2 to=$3 k
  shift 3
  for k in 0 1; do "$fn" "$in-$k.json" "$to-$k.json" "$@"; done
}

# VENUE THRESHOLDS [WHAT] -> the venue's figures pooled over both halves: THRESHOLDS is a file
# (the same for both) or a PREFIX of per-half files. WHAT: "marking" (default) -> "P | R" of the
# markings, "boundary" -> the share of hand-drawn field-boundary columns the detected boundary
# lies within 4 px of, "centre" -> "P / R" of the stripes' centre lines against the drawn lines'
# centres ("-" without stripes).
score() {
  local id=$1 th=$2 what=${3:-marking} k file
  for k in 0 1; do
    file=$th; [[ -f "$th-$k.json" ]] && file="$th-$k.json"
    rm -f "$out/score$k.json"
    compgen -G "$out/$id-truth$k/*.json" >/dev/null || continue
    "$bin" eval --hand "$out/$id-truth$k" --data "$data" --thresholds "$file" --json "$out/score$k.json" >/dev/null
  done
  python3 - "$what" "$out/score0.json" "$out/score1.json" <<'PY'
import json, os, sys
totals = [json.load(open(p))["total"] for p in sys.argv[2:] if os.path.exists(p)]
if sys.argv[1] == "boundary":
    n = sum(t["hand_field_boundary"]["columns"] for t in totals)
    print("%.3f" % (sum(t["hand_field_boundary"]["within_4px"] for t in totals) / n) if n else "-")
elif sys.argv[1] == "centre":
    c = [t["centre_lines"] for t in totals]
    detected, truth = sum(x["detected_px"] for x in c), sum(x["truth_px"] for x in c)
    print("%.3f / %.3f" % (sum(x["on_line_px"] for x in c) / detected, sum(x["covered_px"] for x in c) / truth)
          if detected and truth else "-")
else:
    m = [t["marking"] for t in totals]
    predicted, visible = sum(x["predicted"] for x in m), sum(x["visible_px"] for x in m)
    p = sum(x["correct"] for x in m) / predicted if predicted else 0.0
    r = sum(x["covered_px"] for x in m) / visible if visible else 0.0
    print("%.3f | %.3f" % (p, r))
PY
}

# CALLBACK CELLS: for each venue with hand-drawn truth, sets $id, $title and $pattern, splits it
# in halves, then runs CALLBACK; a venue whose frames are not in $data gets a "not measured" row
# of CELLS cells instead.
each_venue() {
  local callback=$1 cells=$2 v
  for v in "${venues[@]}"; do
    IFS='|' read -r id pattern title <<<"$v"
    [[ -d "tests/data/hand_truth/$id" ]] || continue
    if ! compgen -G "$data/$pattern" >/dev/null; then
      echo "| $title | not measured: no $data |$(printf ' |%.0s' $(seq 3 "$cells"))"
      continue
    fi
    halves "$id" "$pattern"
    "$callback"
  done
}
