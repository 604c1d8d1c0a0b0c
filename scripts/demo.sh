#!/usr/bin/env bash
# Open the built-in demo. Until the studio lands this runs `fieldlines detect` on sample images
# and writes drawn overlays, then says where they went.
set -euo pipefail
cd "$(dirname "$0")/.."
bin=build/release/app/cli/fieldlines
out="${FIELDLINES_DEMO_OUT:-${XDG_DATA_HOME:-$HOME/.local/share}/fieldlines/demo-detect}"
samples="${FIELDLINES_SHARED_DIR:-../shared}/data/elsed-ssl/images"
if [[ ! -d "$samples" ]]; then
  echo "demo: no sample images at $samples" >&2
  exit 1
fi
mkdir -p "$out"
"$bin" detect --draw "$out" --json "$out/detections.json" "$samples"
echo "demo: overlays and detections.json written to $out"
