# Sourced by venue_calibration.sh and detector_candidates.sh: the venues with hand-drawn truth,
# which of their frames are fitted and which scored, and how a thresholds file is scored.
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

# VENUE THRESHOLDS -> "P | R" of the markings on the venue's hand-drawn truth.
score() {
  "$bin" eval --hand "tests/data/hand_truth/$1" --data "$data" --thresholds "$2" --json "$out/score.json" >/dev/null
  python3 -c "import json; m=json.load(open('$out/score.json'))['total']['marking']; print('%.3f | %.3f' % (m['precision'], m['recall']))"
}

# VENUE PATTERN: links the venue's frames without hand-drawn truth into $out/VENUE (what is
# fitted) and sets $scored to the others (image paths under $data).
fitting_frames() {
  scored=$(python3 -c "import json,glob; print(' '.join(json.load(open(f))['image'] for f in glob.glob('tests/data/hand_truth/$1/*.json')))")
  mkdir -p "$out/$1"
  for image in $data/$2; do
    [[ " $scored " == *" ${image#$data/} "* ]] || ln -s "$(realpath "$image")" "$out/$1/"
  done
}

# CALLBACK CELLS: for each venue with hand-drawn truth, sets $id, $title and (fitting_frames) the
# fitted frames and $scored, then runs CALLBACK; a venue whose frames are not in $data gets a
# "not measured" row of CELLS cells instead.
each_venue() {
  local callback=$1 cells=$2 v pattern
  for v in "${venues[@]}"; do
    IFS='|' read -r id pattern title <<<"$v"
    [[ -d "tests/data/hand_truth/$id" ]] || continue
    if ! compgen -G "$data/$pattern" >/dev/null; then
      echo "| $title | not measured: no $data |$(printf ' |%.0s' $(seq 3 "$cells"))"
      continue
    fi
    fitting_frames "$id" "$pattern"
    "$callback"
  done
}
