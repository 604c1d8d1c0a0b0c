#!/usr/bin/env bash
# Refreshes the studio screenshots of docs/studio.md (docs/screenshots/studio-*.png): runs the
# real-window tests that take them (every tab on the demo, the Camera tab on rendered frames),
# pointed at docs/screenshots instead of the build folder.
set -euo pipefail
cd "$(dirname "$0")/.."
FIELDLINES_SCREENSHOT_DIR="$PWD/docs/screenshots" \
  ctest --preset release -R 'studio.StudioWindow.PanelScreenshots|studio.StudioCameraWindow' --output-on-failure
