#!/usr/bin/env bash
# Refreshes the studio screenshots of docs/studio.md (docs/screenshots/studio-*.png): runs the real-window
# test that takes them, pointed at docs/screenshots instead of the build folder.
set -euo pipefail
cd "$(dirname "$0")/.."
FIELDLINES_SCREENSHOT_DIR="$PWD/docs/screenshots" \
  ctest --preset release -R 'studio.StudioWindow.PanelScreenshots' --output-on-failure
