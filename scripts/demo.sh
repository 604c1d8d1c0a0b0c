#!/usr/bin/env bash
# Opens the built-in demo: the studio on a synthetic project generated on first use in the
# user's data folder ($XDG_DATA_HOME/fieldlines/demo). Without a display (or without the studio)
# it runs `fieldlines detect` on the demo images, writes drawn overlays and says where they went.
set -euo pipefail
cd "$(dirname "$0")/.."
bin=build/release/app
studio="$bin/studio/fieldlines-studio"
if [[ -n "${DISPLAY:-}${WAYLAND_DISPLAY:-}" && -x "$studio" ]]; then
  exec "$studio" "$@"
fi
project="$("$bin/cli/fieldlines" synth --demo --quiet)"
demo_dir="$(dirname "$project")"
out="$demo_dir/detections"
mkdir -p "$out"
"$bin/cli/fieldlines" detect --quiet --draw "$out/overlays" --json "$out/detections.json" "$demo_dir/images"
echo "demo: no display for the studio; detected lines in the demo project $project"
echo "demo: overlays in $out/overlays, every segment in $out/detections.json"
