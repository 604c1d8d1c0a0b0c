#!/usr/bin/env bash
# L/T/X junctions on real frames of other leagues, scored against the junctions drawn by eye on
# the frames with hand-drawn truth (tests/data/hand_truth/junctions.json, which says how).
# Per venue: the built-in thresholds, and a calibration on each half of the venue's frames
# (venue_common.sh: halves; detector parameters and thresholds, as `fieldlines calibrate` chooses
# them) for the frames with truth of the other half, each with
# the stripes and junctions on and the centre circle off, then on. A detection matches a true
# junction within 6 px (the synthetic fields' rule) or, in the columns after the bar, within
# 12 px (the hand-drawn centre lines are a few px off on wide near lines, and the fisheye bends
# them); one within 12 px of a junction marked "?" counts neither way; any other is false.
# Prints Markdown.
#   usage: bash scripts/junctions_real.sh [OUT_DIR]   (default build/junctions-real)
#   env:   FIELDLINES_BIN (default build/release/app/cli/fieldlines), SHARED (default ../shared)
set -euo pipefail
cd "$(dirname "$0")/.."
bin="${FIELDLINES_BIN:-build/release/app/cli/fieldlines}"
out="${1:-build/junctions-real}"
data="${SHARED:-../shared}/data"
rm -rf "$out"
mkdir -p "$out"
source scripts/venue_common.sh
# THRESHOLDS OUT CIRCLE: the file with the stripes and junctions on, the circle on or off.
junctions_on() {
  python3 -c "import json,sys; t=json.load(open(sys.argv[1])); t.setdefault('detector',{}).update(stripes=True, intersections=True, centre_circle=sys.argv[3]=='on'); json.dump(t, open(sys.argv[2],'w'))" "$1" "$2" "$3"
}
echo "| venue | thresholds | circle | true junctions | detected | matched | type correct | false | precision | recall | within 12 px: P / R / type |"
echo "|---|---|---|---:|---:|---:|---:|---:|---:|---:|---|"
venue_rows() {
  local k
  calibrate_halves "$id" "$out/$id-cal" || true
  for which in built-in calibrated; do
    if [[ $which == calibrated && ! -f "$out/$id-cal-0.json" || $which == calibrated && ! -f "$out/$id-cal-1.json" ]]; then
      echo "| $title | $which | | refused: $(cat "$out/$id"-cal-*.err | tr '\n' ' ') | | | | | | | |"; continue
    fi
    for circle in off on; do
      # The frames with truth of each half detected with the file calibrated on the other half.
      for k in 0 1; do
        source_file=assets/default_thresholds.json
        [[ $which == calibrated ]] && source_file="$out/$id-cal-$k.json"
        junctions_on "$source_file" "$out/$id-$which-$circle-$k.json" "$circle"
        mapfile -t images < <(scored_images "$id" "$k")
        echo '{"images": []}' > "$out/$id-$which-$circle-$k.out.json"
        [[ ${#images[@]} -eq 0 ]] ||
          "$bin" detect --quiet --thresholds "$out/$id-$which-$circle-$k.json" --json "$out/$id-$which-$circle-$k.out.json" "${images[@]}"
      done
      python3 - "$out/$id-$which-$circle-0.out.json" "$out/$id-$which-$circle-1.out.json" "$title" "$which" "$circle" <<'PY'
import json, math, os, sys
truth = {f["image"].split("/")[-1]: f["junctions"] for f in json.load(open("tests/data/hand_truth/junctions.json"))["frames"]}
images = json.load(open(sys.argv[1]))["images"] + json.load(open(sys.argv[2]))["images"]
def score(images, reach):
    n_true = detected = matched = typed = false = 0
    for im in images:
        js = truth[os.path.basename(im["path"])]
        sure = [j for j in js if j["type"] != "?"]
        unsure = [j for j in js if j["type"] == "?"]
        n_true += len(sure)
        taken = set()
        for d in im["intersections"]:
            detected += 1
            near = [(math.hypot(d["x"] - j["x"], d["y"] - j["y"]), k) for k, j in enumerate(sure) if k not in taken]
            best = min(near, default=(1e9, -1))
            if best[0] <= reach:
                taken.add(best[1]); matched += 1; typed += d["type"] == sure[best[1]]["type"]
            elif not any(math.hypot(d["x"] - j["x"], d["y"] - j["y"]) <= 12 for j in unsure):
                false += 1
    p = f"{matched / (matched + false):.3f}" if matched + false else "-"
    r = f"{matched / n_true:.3f}" if n_true else "-"
    return n_true, detected, matched, typed, false, p, r
n_true, detected, matched, typed, false, p, r = score(images, 6)
_, _, m12, t12, _, p12, r12 = score(images, 12)
print(f"| {sys.argv[3]} | {sys.argv[4]} | {sys.argv[5]} | {n_true} | {detected} | {matched} | {typed} | {false} | {p} | {r} | {p12} / {r12} / {t12} of {m12} |")
PY
    done
  done
}
each_venue venue_rows 11
